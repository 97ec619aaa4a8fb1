#include "framework/scene/camera_placement.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

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

void place_course_camera(const Bounds3& bounds, int width, int height, Camera* camera) {
  // The course sets its camera up for its 800 × 600 window, then resizes the screen to -r W H
  // keeping the screen's distance, hence the size of a pixel: the vertical tangent scales by
  // H/600; ours then follows the image's aspect, as for every render.
  if (width > 0 && height > 0) {
    const float tan_h = std::tan(glm::radians(camera->hfov_degrees) / 2.0f);
    const float tan_v = tan_h * 600.0f / 800.0f * float(height) / 600.0f;
    const float half = tan_v * float(width) / float(height);
    if (std::isfinite(half) && half > 0.0f) camera->hfov_degrees = glm::degrees(2.0f * std::atan(half));
  }
  if (bounds.empty()) return;
  const glm::vec3 forward = -glm::normalize(glm::vec3(camera->camera_to_world[2]));
  const float distance = 1.5f * glm::length(bounds.extent());
  if (!(distance > 0.0f) || !std::isfinite(distance)) return;
  camera->camera_to_world[3] = glm::vec4(bounds.center() - distance * forward, 1.0f);
}

}  // namespace pt
