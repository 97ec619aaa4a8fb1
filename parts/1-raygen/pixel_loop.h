// Part 1, step 2 (pixel_loop): a pixel's camera rays, and its value as the average of their
// radiance: camera_ray_through_pixel, estimate_pixel.
#pragma once

#include <functional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/math/ray.h"
#include "framework/render/pixel_stats.h"
#include "framework/sampling/rng.h"
#include "framework/scene/camera.h"

namespace pt {

/// Radiance arriving along a camera ray (normals at Part 1, light from Part 3 on).
using RadianceFn = std::function<glm::vec3(const Ray& ray, Rng& rng)>;

/// Which pixel of which image.
struct PixelRef {
  int x = 0, y = 0;            ///< column from the left, row from the top
  int width = 1, height = 1;   ///< image size in pixels
};

/// Step 2 (pixel_loop).
/// The camera ray through the point `offset` of pixel `px`, where (0,0) is the pixel's top-left
/// corner and (0.5,0.5) its centre, with `lens` the thin lens's sample (generate_camera_ray).
/// The one place a pixel becomes film coordinates: the pixel loop calls it, and so does the
/// adaptive sampler's pixel (with a random offset).
Ray camera_ray_through_pixel(const Camera& camera, const PixelRef& px, glm::vec2 offset,
                             glm::vec2 lens);

/// Estimates pixel `px`: with samples == 1, the one ray through the pixel's centre; otherwise
/// `samples` rays through uniformly jittered points of the pixel. Each ray's radiance is added
/// to *stats, whose mean is the pixel's value (and whose variance the graders read). Each
/// sample draws its offset in the pixel first, then (for a thin lens) its lens point.
void estimate_pixel(const Camera& camera, const PixelRef& px, int samples, Rng& rng,
                    const RadianceFn& radiance, PixelStats* stats);

}  // namespace pt
