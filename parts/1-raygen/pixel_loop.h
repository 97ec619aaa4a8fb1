// Part 1, step 4: a pixel's value as the average of the radiance of its camera rays.
#pragma once

#include <functional>

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

/// Estimates pixel `px`: with samples == 1, the one ray through the pixel's centre; otherwise
/// `samples` rays through uniformly jittered points of the pixel. Each ray's radiance is added
/// to *stats, whose mean is the pixel's value (and whose variance the graders read).
void estimate_pixel(const Camera& camera, const PixelRef& px, int samples, Rng& rng,
                    const RadianceFn& radiance, PixelStats* stats);

}  // namespace pt
