#include "framework/scene/camera_placement.h"

#include <glm/geometric.hpp>

namespace pt {

void centre_camera_on(const Bounds3& bounds, Camera* camera) {
  if (bounds.empty()) return;
  glm::vec3 position(camera->camera_to_world[3]);
  glm::vec3 forward = -glm::normalize(glm::vec3(camera->camera_to_world[2]));
  glm::vec3 centre = bounds.center();
  float distance = glm::length(centre - position);
  if (!(distance > 0.0f)) return;
  camera->camera_to_world[3] = glm::vec4(centre - distance * forward, 1.0f);
}

}  // namespace pt
