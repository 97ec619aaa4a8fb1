// One pixel explained: its samples as the render takes them, every ray each one traced (camera,
// bounce, shadow) recorded through a RayQuery that writes them down, and the light each bounce
// brought.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/render/render_settings.h"
#include "framework/scene/camera.h"
#include "framework/scene/scene.h"

namespace pt {

/// One ray a sample traced: a nearest-hit query (the camera ray, a bounce) or a shadow ray.
struct TracedRay {
  bool shadow = false;
  Ray ray;
  bool hit = false;      ///< nearest-hit: something was hit; shadow: the ray was blocked
  SurfaceHit surface;    ///< nearest-hit rays that hit
};

/// A RayQuery that answers through another and writes every query and its answer down, in the
/// order the lighting code asked them. Lighting code only ever traces through the query it is
/// given, so this sees every ray of a sample without touching the code that traces them.
class RecordingRayQuery final : public RayQuery {
 public:
  RecordingRayQuery(const RayQuery& inner, std::vector<TracedRay>* rays) : inner_(inner), rays_(rays) {}
  bool intersect(const Ray& ray, SurfaceHit* hit) const override;
  bool occluded(const Ray& ray) const override;

 private:
  const RayQuery& inner_;
  std::vector<TracedRay>* rays_;
};

/// Most samples whose rays are kept for drawing; the pixel's value still takes every sample.
constexpr int kMaxRecordedSamples = 64;

/// Pixel (x, y) rendered as the render job renders it (Part 1's or Part 5's pixel loop, the same
/// Rng, the same integrator) through `query`, recording each sample: its rays, its radiance, and
/// the light each bounce added (the estimate stopped at depth K less the one stopped at K - 1,
/// both from the sample's own random numbers).
nlohmann::json record_pixel(const RenderSettings& settings, const Scene& scene, const Camera& camera,
                            const RayQuery& query, int x, int y);

}  // namespace pt
