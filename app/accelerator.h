// The structure that answers a render's rays, as the command line chose it (--bvh, --leaf-size,
// --bvh-width): Part 2's BVH, the wide BVH collapsed from it, or brute force; and its statistics.
#pragma once

#include <memory>
#include <string>

#include "framework/geometry/ray_query.h"
#include "framework/render/render_settings.h"
#include "framework/scene/scene.h"

namespace pt {

/// The structure that answers the rays: Part 2's BVH (SAH or midpoint splits), the wide tree
/// collapsed from it (--bvh-width 8, where the build has it), or brute force.
std::unique_ptr<RayQuery> make_ray_query(const RenderSettings& settings, const Scene& scene);

/// The BVH's build statistics, one line (two with the wide tree), for --info.
std::string describe_bvh(const RenderSettings& settings, const Scene& scene);

}  // namespace pt
