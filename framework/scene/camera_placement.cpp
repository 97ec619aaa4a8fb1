#include "framework/scene/camera_placement.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace pt {

void centre_camera_on(const Bounds3& bounds, Camera* camera) {
  if (bounds.empty()) return;
  // In double: with huge (finite) coordinates the distance's square overflows float, which
  // would place the camera at infinity or NaN. The placement must come back to float.
  const glm::dvec3 position(camera->camera_to_world[3]);
  const glm::dvec3 forward = -glm::normalize(glm::dvec3(camera->camera_to_world[2]));
  const glm::dvec3 centre = 0.5 * (glm::dvec3(bounds.lo) + glm::dvec3(bounds.hi));
  const double distance = glm::length(centre - position);
  if (!(distance > 0.0)) return;
  const glm::vec3 placed(centre - distance * forward);
  if (!std::isfinite(placed.x) || !std::isfinite(placed.y) || !std::isfinite(placed.z))
    throw std::range_error("the camera cannot be centred on the scene: its position would not "
                           "fit in float (coordinates beyond 3e38)");
  camera->camera_to_world[3] = glm::vec4(placed, 1.0f);
}

}  // namespace pt
