#include "1-raygen/camera_ray.h"

#include "student/todo.h"

namespace pt {

Ray generate_camera_ray(const Camera& camera, float image_aspect, glm::vec2 film, glm::vec2 lens) {
  // BEGIN SOLUTION
  // END SOLUTION
  // STUDENT: place the point `film` on the sensor plane z = -1 of the camera's own space (its
  // half-width is tan(hfov/2), its half-height that divided by image_aspect), turn the direction
  // through it into world space with camera.camera_to_world, normalise it.
  PT_STUDENT_TODO("part 1", "generate_camera_ray");
  (void)camera, (void)image_aspect, (void)film, (void)lens;
  return Ray{};
}

}  // namespace pt
