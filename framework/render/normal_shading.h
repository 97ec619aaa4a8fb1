// Not needed for the assignment.
// The normals view (--normals), the debug view Parts 1 and 2 are graded on: what a camera ray
// hits, coloured by its shading normal.
#pragma once

#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/math/ray.h"

namespace pt {

/// The shading normal mapped from [−1, 1] to [0, 1]; black where nothing is hit.
glm::vec3 normal_shading(const RayQuery& query, const Ray& ray);

}  // namespace pt
