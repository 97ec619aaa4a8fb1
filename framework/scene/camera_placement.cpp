// Not needed for the assignment: the definitions of framework/scene/camera_placement.h.
#include "framework/scene/camera_placement.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

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
  // In double, as centre_camera_on: the diagonal of huge (finite) bounds overflows float.
  const glm::dvec3 lo(bounds.lo), hi(bounds.hi);
  const double distance = 1.5 * glm::length(hi - lo);
  if (!(distance > 0.0)) return;
  const glm::vec3 placed(0.5 * (lo + hi) - distance * glm::dvec3(forward));
  if (!std::isfinite(placed.x) || !std::isfinite(placed.y) || !std::isfinite(placed.z))
    throw std::range_error("the course's view of the scene would place the camera beyond float's "
                           "range (coordinates beyond 3e38)");
  camera->camera_to_world[3] = glm::vec4(placed, 1.0f);
}

}  // namespace pt
