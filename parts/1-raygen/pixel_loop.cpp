// Part 1, step 2 (pixel_loop): camera_ray_through_pixel, estimate_pixel.
#include "parts/1-raygen/pixel_loop.h"

#include "framework/student/todo.h"
#include "parts/1-raygen/camera_ray.h"

namespace pt {

Ray camera_ray_through_pixel(const Camera& camera, const PixelRef& px, glm::vec2 offset,
                             glm::vec2 lens) {
  // BEGIN SOLUTION
  const float aspect = float(px.width) / float(px.height);
  // Rows count down from the top, the film up from the bottom.
  const glm::vec2 film((float(px.x) + offset.x) / float(px.width),
                       1.0f - (float(px.y) + offset.y) / float(px.height));
  return generate_camera_ray(camera, aspect, film, lens);
  // END SOLUTION
  // STUDENT: return the camera ray through the point `offset` of pixel `px` ((0,0) the pixel's
  // top-left corner, (1,1) its bottom-right; rows count from the image's top), with `lens` as
  // the lens sample. The film has (0,0) at the image's bottom-left, and the image's aspect is its
  // width over its height; generate_camera_ray makes the ray. Checked: docs/handout/part1.md
  // step 2.
  PT_STUDENT_TODO("part 1", "camera_ray_through_pixel");
  (void)camera, (void)px, (void)offset, (void)lens;
  return Ray{};
}

void estimate_pixel(const Camera& camera, const PixelRef& px, int samples, Rng& rng,
                    const RadianceFn& radiance, PixelStats* stats) {
  // BEGIN SOLUTION
  for (int i = 0; i < samples; ++i) {
    const glm::vec2 offset = (samples == 1) ? glm::vec2(0.5f) : rng.next_2d();
    const glm::vec2 lens = (camera.lens_radius > 0.0f) ? rng.next_2d() : glm::vec2(0.5f);
    stats->add(radiance(camera_ray_through_pixel(camera, px, offset, lens), rng));
  }
  return;
  // END SOLUTION
  // STUDENT: add the radiance of `samples` camera rays through pixel `px` to *stats, one add per
  // sample. What must hold (docs/handout/part1.md step 2): one sample goes through the pixel's
  // centre and draws no offset; several go through uniform random points of the pixel; for each
  // sample its offset is drawn first (rng.next_2d()), then its lens sample only when the camera
  // has a lens, then whatever its radiance draws.
  PT_STUDENT_TODO("part 1", "estimate_pixel");
  (void)camera, (void)px, (void)samples, (void)rng, (void)radiance;
  stats->add(glm::vec3(0.0f));
}

}  // namespace pt
