#include "app/viewer/pixel_paths.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/pixel_function.h"
#include "framework/render/normal_shading.h"
#include "framework/render/tile_renderer.h"
#include "pipeline/4-global/integrator.h"

namespace pt {

bool RecordingRayQuery::intersect(const Ray& ray, SurfaceHit* hit) const {
  TracedRay r;
  r.ray = ray;
  r.hit = inner_.intersect(ray, hit);
  if (r.hit) r.surface = *hit;
  rays_->push_back(r);
  return r.hit;
}

bool RecordingRayQuery::occluded(const Ray& ray) const {
  TracedRay r;
  r.shadow = true;
  r.ray = ray;
  r.hit = inner_.occluded(ray);
  rays_->push_back(r);
  return r.hit;
}

namespace {

nlohmann::json v3(const glm::vec3& v) {
  // JSON has no NaN or infinity: a stub's NaN direction is shown as null, not a broken page.
  auto f = [](float x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  return {f(v.x), f(v.y), f(v.z)};
}

nlohmann::json ray_json(const TracedRay& r) {
  nlohmann::json j = {{"kind", r.shadow ? "shadow" : "trace"},
                      {"o", v3(r.ray.o)},
                      {"d", v3(r.ray.d)},
                      {"tmin", std::isfinite(r.ray.tmin) ? nlohmann::json(r.ray.tmin) : nullptr},
                      {"tmax", std::isfinite(r.ray.tmax) ? nlohmann::json(r.ray.tmax) : nullptr}};
  if (r.shadow) {
    j["blocked"] = r.hit;
  } else {
    j["hit"] = r.hit;
    if (r.hit) {
      j["t"] = r.surface.t;
      j["p"] = v3(r.surface.p);
      j["n"] = v3(r.surface.n);
      j["primitive"] = r.surface.primitive;
      j["material"] = r.surface.material;
    }
  }
  return j;
}

}  // namespace

nlohmann::json record_pixel(const RenderSettings& settings, const Scene& scene, const Camera& camera,
                            const RayQuery& query, int x, int y) {
  std::unique_ptr<Integrator> integrator;
  std::vector<std::unique_ptr<Integrator>> bounces;
  const bool normals = settings.shading == ShadingMode::normals;
  if (!normals) {
    std::string error;
    integrator = Integrator::create(settings, scene, query, &error);
    if (!integrator) throw std::runtime_error(error);
    // The light each bounce brought: the same estimator stopped at depth K (-m K), run from the
    // sample's own random numbers, less the one stopped at K - 1. A path to depth K draws the
    // numbers its first K - 1 bounces drew, so these are the very path's bounces (the page says
    // whether they add up to the sample's value).
    if (!integrator->shows_normals() && settings.only_bounce < 0)
      for (int k = 0; k <= std::min(settings.max_depth, 8); ++k) {
        RenderSettings upto = settings;
        upto.max_depth = k;
        bounces.push_back(Integrator::create(upto, scene, query, &error));
        if (!bounces.back()) throw std::runtime_error(error);
      }
  }
  nlohmann::json samples = nlohmann::json::array();
  long taken = 0;
  const TracedRadianceFn recorded = [&](const Ray& ray, Rng& rng, TraceContext& context) {
    std::vector<TracedRay> rays;
    const RecordingRayQuery recorder(query, &rays);
    const Rng before = rng;
    const glm::vec3 L = normals ? normal_shading(recorder, ray) : integrator->radiance(ray, rng, recorder);
    context.rays.add(rays.size());
    ++taken;
    if (samples.size() >= size_t(kMaxRecordedSamples)) return L;
    nlohmann::json sample = {{"radiance", v3(L)}, {"rays", nlohmann::json::array()}};
    for (const TracedRay& r : rays) sample["rays"].push_back(ray_json(r));
    nlohmann::json per_bounce = nlohmann::json::array();
    glm::vec3 below(0.0f);
    for (const auto& b : bounces) {
      Rng again = before;
      const glm::vec3 upto = b->radiance(ray, again, query);
      per_bounce.push_back(v3(upto - below));
      below = upto;
    }
    sample["bounces"] = per_bounce;
    // Whether the bounces add up to the sample (they do unless the depth is past 8, or the
    // estimator draws its random numbers differently when it stops sooner).
    if (!bounces.empty()) {
      const glm::vec3 gap = below - L;
      sample["bounces_add_up"] = std::fabs(gap.x) + std::fabs(gap.y) + std::fabs(gap.z) <=
                                 1e-4f * (1.0f + std::fabs(L.x) + std::fabs(L.y) + std::fabs(L.z));
    }
    samples.push_back(std::move(sample));
    return L;
  };
  const PixelFn pixel = make_pixel_fn(settings, camera, recorded);
  Rng rng(settings.seed, uint64_t(y) * uint64_t(settings.width) + uint64_t(x));
  TraceContext context;
  PixelStats stats;
  pixel(x, y, rng, context, &stats);
  const glm::dvec3 var = stats.variance();
  return {{"x", x},
          {"y", y},
          {"value", v3(glm::vec3(stats.mean))},
          {"variance", v3(glm::vec3(var))},
          {"samples_taken", stats.samples_taken()},
          {"samples_in_value", stats.count},
          {"samples_recorded", samples.size()},
          {"calls", taken},
          {"rays", context.rays.rays},
          {"nonfinite_samples", context.nonfinite_samples},
          {"normals_view", normals || (integrator && integrator->shows_normals())},
          {"max_depth", settings.max_depth},
          {"samples", samples}};
}

}  // namespace pt
