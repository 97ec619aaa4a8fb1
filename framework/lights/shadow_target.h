// Not needed for the assignment: where a light sample's shadow ray aims. A LightSample carries
// one for spawn_shadow_ray; the estimators pass it along and never read it.
#pragma once

#include <limits>

#include <glm/vec3.hpp>

namespace pt {

/// The point a light sample was drawn at, as the shadow ray towards it needs it: the ray stops
/// short of the light by the point's error bound, so it never hits the light it aims at.
struct ShadowTarget {
  float distance = std::numeric_limits<float>::infinity();  ///< infinite for distant lights
  glm::vec3 p{0.0f};        ///< the point on the light (finite lights)
  glm::vec3 p_error{0.0f};  ///< its floating-point error bound
  glm::vec3 n{0.0f};        ///< the light's surface normal there (zero for point lights)
  bool delta = false;       ///< drawn from a delta light
};

}  // namespace pt
