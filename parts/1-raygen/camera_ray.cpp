// Part 1, step 1 (camera_ray): generate_camera_ray.
#include "parts/1-raygen/camera_ray.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "framework/student/todo.h"

namespace pt {

Ray generate_camera_ray(const Camera& camera, float image_aspect, glm::vec2 film, glm::vec2 lens) {
  // BEGIN SOLUTION
  // The sensor sits at z = -1, so its half-extents are the tangents of the half angles.
  const float half_w = std::tan(0.5f * glm::radians(camera.hfov_degrees));
  const float half_h = half_w / image_aspect;
  const glm::vec3 sensor((2.0f * film.x - 1.0f) * half_w, (2.0f * film.y - 1.0f) * half_h, -1.0f);

  glm::vec3 origin_cam(0.0f);
  glm::vec3 dir_cam = sensor;
  if (camera.lens_radius > 0.0f) {
    // Every ray through this film point converges where the pinhole ray meets the focal plane
    // z = -focal_distance; the lens point is uniform on the aperture disk (r = R·sqrt(u)).
    const float r = camera.lens_radius * std::sqrt(lens.x);
    const float phi = 2.0f * glm::pi<float>() * lens.y;
    origin_cam = glm::vec3(r * std::cos(phi), r * std::sin(phi), 0.0f);
    dir_cam = sensor * camera.focal_distance - origin_cam;
  }
  dir_cam = glm::normalize(dir_cam);

  Ray ray;
  ray.o = glm::vec3(camera.camera_to_world * glm::vec4(origin_cam, 1.0f));
  ray.d = glm::normalize(glm::vec3(camera.camera_to_world * glm::vec4(dir_cam, 0.0f)));
  ray.tmin = 0.0f;
  // The far clipping plane z = -zfar, reached at zfar / cos(angle to the view axis).
  ray.tmax = (camera.zfar > 0.0f && std::isfinite(camera.zfar))
                 ? camera.zfar / -dir_cam.z
                 : std::numeric_limits<float>::infinity();
  return ray;
  // END SOLUTION
  // STUDENT: return the world-space ray through the film point `film` ((0,0) the image's
  // bottom-left, (1,1) its top-right) for an image of aspect `image_aspect`, through the lens
  // point `lens` picks when the camera has a lens (camera.lens_radius > 0). What must hold (each
  // is a check, docs/handout/part1.md step 1): the film's edges span the field of view (hfov
  // across, the angle the aspect gives up and down); camera_to_world places the ray: the origin
  // is the camera's position, or a point of its aperture, the direction turned as a direction;
  // the direction has unit length; tmin is 0 and tmax reaches the far plane z = -zfar; lens rays
  // through one film point meet on the plane in focus (z = -camera.focal_distance) and are
  // uniform over the aperture.
  PT_STUDENT_TODO("part 1", "generate_camera_ray");
  (void)camera, (void)image_aspect, (void)film, (void)lens;
  return Ray{};
}

}  // namespace pt
