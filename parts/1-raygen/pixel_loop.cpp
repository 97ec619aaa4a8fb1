#include "1-raygen/pixel_loop.h"

#include "1-raygen/camera_ray.h"
#include "student/todo.h"

namespace pt {

void estimate_pixel(const Camera& camera, const PixelRef& px, int samples, Rng& rng,
                    const RadianceFn& radiance, PixelStats* stats) {
  // BEGIN SOLUTION
  // END SOLUTION
  // STUDENT: for each sample pick a point in the pixel (its centre when samples == 1, a uniform
  // random point otherwise), turn it into film coordinates ((0,0) bottom-left: rows count from
  // the top), shoot generate_camera_ray through it and add its radiance to *stats.
  PT_STUDENT_TODO("part 1", "estimate_pixel");
  (void)camera, (void)px, (void)samples, (void)rng, (void)radiance;
  stats->add(glm::vec3(0.0f));
}

}  // namespace pt
