// Not needed for the assignment.
// Reads the course's COLLADA 1.4 dialect (Blender export plus <extra><technique profile="CGL">).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "framework/scene/scene.h"

namespace pt {

/// Where the loader reports what it skipped or changed (unknown elements, a texture replaced by
/// grey, a default camera, a value clamped). A warning the same element makes again (a library
/// node instanced many times) is given once. Materials that no part renders yet are not its
/// business: see materials_falling_back() in scene/scene_summary.h. The default writes
/// "warning: ..." lines to stderr.
using WarningSink = std::function<void(const std::string&)>;

/// The most primitives (triangles and spheres) a scene may hold once every instance is expanded,
/// and the most node instances (lights and cameras included) the expansion may make: 2^24 each,
/// about 4 GB of scene and trees at the limit. Both are counted before anything is expanded, so a
/// file whose nodes instance each other into billions fails at once with the node chain named.
constexpr uint64_t kMaxInstancedPrimitives = uint64_t(1) << 24;
constexpr uint64_t kMaxInstancedNodes = uint64_t(1) << 24;

/// The instancing limits a load applies. A caller may lower them: the fuzz target does, so that
/// one input (a valid scene of millions of instances) stays quick under its sanitizers and the
/// limit's error path is reached often.
struct LoadLimits {
  uint64_t primitives = kMaxInstancedPrimitives;
  uint64_t nodes = kMaxInstancedNodes;
};

/// Loads a .dae file into a Scene in world space. Throws SceneError naming the file and the
/// element for anything it cannot make sense of: a missing or unreadable file, XML that does
/// not parse, an index out of range, a url="#id" that points nowhere, a number that is not one
/// (NaN, text), a count the element does not hold, instancing past the limits above, a scene with
/// nothing to render. Messages read "FILE: <element id=...> (line N): what is wrong". No number in
/// the file is trusted before what it describes is there: nothing is allocated by a count.
///
/// Physically impossible values (the policy the README states): a reflectance (diffuse colour,
/// mirror or glass reflectance, glass transmittance) outside [0, 1] is clamped there per channel,
/// a negative radiance, intensity or attenuation is clamped to 0, and a light left with nothing
/// to light (no radiance, a spot cone of no angle, an area light facing away from everything) is
/// left out; each with a warning naming the file, line and element and what was done.
///
/// A file with no camera gets one outside the scene's bounds, looking at their centre from the
/// side its surfaces face most, with a warning.
///
/// Every mesh vertex gets a shading normal (the file's, through the inverse transpose, or the
/// face normal where the file has none), so Scene::normals is the size of Scene::positions.
/// Corners that name the same position in the file get bit-identical floats.
Scene load_collada(const std::string& path, const WarningSink& warn = {},
                   const LoadLimits& limits = {});

/// The same, from a string in memory; `name` stands in for the file name in messages.
Scene load_collada_string(const std::string& xml, const std::string& name,
                          const WarningSink& warn = {}, const LoadLimits& limits = {});

}  // namespace pt
