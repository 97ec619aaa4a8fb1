#include "parts/1-raygen/pixel_loop.h"

#include "parts/1-raygen/camera_ray.h"
#include "framework/student/todo.h"

namespace pt {

void estimate_pixel(const Camera& camera, const PixelRef& px, int samples, Rng& rng,
                    const RadianceFn& radiance, PixelStats* stats) {
  // BEGIN SOLUTION
  const float aspect = float(px.width) / float(px.height);
  for (int i = 0; i < samples; ++i) {
    const glm::vec2 offset = (samples == 1) ? glm::vec2(0.5f) : rng.next_2d();
    // Rows count down from the top, the film up from the bottom.
    const glm::vec2 film((float(px.x) + offset.x) / float(px.width),
                         1.0f - (float(px.y) + offset.y) / float(px.height));
    const glm::vec2 lens = (camera.lens_radius > 0.0f) ? rng.next_2d() : glm::vec2(0.5f);
    stats->add(radiance(generate_camera_ray(camera, aspect, film, lens), rng));
  }
  return;
  // END SOLUTION
  // STUDENT: for each sample pick a point in the pixel (its centre when samples == 1, a uniform
  // random point otherwise), turn it into film coordinates ((0,0) bottom-left: rows count from
  // the top), shoot generate_camera_ray through it and add its radiance to *stats.
  PT_STUDENT_TODO("part 1", "estimate_pixel");
  (void)camera, (void)px, (void)samples, (void)rng, (void)radiance;
  stats->add(glm::vec3(0.0f));
}

}  // namespace pt
