// What the Part 4 step tests share: the light a hit sends back after at least one bounce as a
// test estimator (step 2's and 3's function called at the hit the rig found, without step 1's
// estimate_global_illumination), the closed enclosure whose answer is known at every depth, a
// t-test of a mean against its answer, and the mirror under a panel that disagrees with its
// light.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "framework/testing/lighting_rig.h"
#include "parts/4-global/global_illumination.h"

namespace pt::test {

/// Significance of each known-answer t-test.
constexpr double kPathAlpha = 0.001;

/// Part 4's estimator of a camera ray's radiance (step 1's estimate_global_illumination), for
/// sample_values.
inline Estimator gi(const LightingContext& ctx) {
  return [&ctx](const Ray& r, Rng& g) { return estimate_global_illumination(ctx, r, g); };
}

/// A hit of the rig's query, shaded with the rig's Lambertian in place of Part 3's DiffuseBsdf.
using RigPoint = ShadedByRig<ShadingPoint, DiffuseBsdf>;

/// The light the first hit of `ray` sends back after at least one bounce: steps 2-3's
/// at_least_one_bounce_radiance at depth 1, called at the hit the rig's query finds, so that the
/// camera ray's own emission (step 1's) is not in it. Zero when the ray hits nothing.
inline glm::vec3 bounced_at_hit(const LightingContext& ctx, const Ray& ray, Rng& rng) {
  SurfaceHit hit;
  if (!ctx.query.intersect(ray, &hit)) return glm::vec3(0.0f);
  return at_least_one_bounce_radiance(ctx, ShadingPoint(ctx.scene, ray, hit), 1, rng);
}

/// bounced_at_hit as sample_values wants it.
inline Estimator bounced(const LightingContext& ctx) {
  return [&ctx](const Ray& r, Rng& g) { return bounced_at_hit(ctx, r, g); };
}

/// A closed box of albedo rho emitting E everywhere on its inside.
inline Scene enclosure(float rho, float E) {
  Scene s;
  uint32_t m = add_material(s, glm::vec3(rho), glm::vec3(E));
  add_closed_cube(s, m);
  return s;
}

/// Expects the mean of `xs` to be `expected` within chance (t-test at kPathAlpha); `hint`
/// (ratio_hint's words for what a wrong ratio means here) follows the numbers.
inline void expect_mean(const std::vector<double>& xs, double expected, const std::string& what,
                        std::initializer_list<RatioCause> causes = {}) {
  auto c = t_test_mean(xs, expected, kPathAlpha);
  // Float rounding is not a difference: a lossless glass sphere's estimate is 1 within a few
  // ulps and almost no variance, which a t-test alone would call biased.
  const bool within_rounding =
      std::abs(c.mean - expected) <= 1e-5 * std::max(1.0, std::abs(expected));
  EXPECT_TRUE(c.pass || within_rounding) << what << ": mean " << c.mean << " ± " << c.stderr_ << ", expected "
                      << expected << ratio_hint(c.mean, expected, causes);
}

/// Whether two sets of estimates share their mean within chance (Welch's z at kPathAlpha,
/// two-sided; the sets are thousands of samples each): their means and the comparison in words.
struct SameMean {
  double x = 0, y = 0;
  bool pass = false;
  std::string text;
};
inline SameMean same_mean(const std::vector<double>& xs, const std::vector<double>& ys) {
  auto moments = [](const std::vector<double>& v) {
    double m = 0, m2 = 0;
    for (double x : v) m += x;
    m /= double(v.size());
    for (double x : v) m2 += (x - m) * (x - m);
    return std::make_pair(m, m2 / double(v.size() - 1) / double(v.size()));
  };
  const auto [mx, vx] = moments(xs);
  const auto [my, vy] = moments(ys);
  const double z = (mx - my) / std::sqrt(vx + vy);
  SameMean r;
  r.x = mx;
  r.y = my;
  r.pass = std::isfinite(z) && std::abs(z) < 3.29;  // two-sided 0.001
  r.text = "mean " + std::to_string(mx) + " ± " + std::to_string(std::sqrt(vx)) + " against " +
           std::to_string(my) + " ± " + std::to_string(std::sqrt(vy)) + " (z = " +
           std::to_string(z) + ")";
  return r;
}

/// What the camera sees in a mirror floor under CBcoil's disagreeing panel and light
/// (disagreeing_panel_scene with a mirror floor), at depth 1, after the bounce at the mirror (the
/// mirror emits nothing): the panel with the radiance light sampling gives it, the light's (5,
/// not the panel's 10). `hemisphere`, `mis` choose the estimator.
inline glm::vec3 panel_in_a_mirror(bool hemisphere, bool mis) {
  Rig rig(disagreeing_panel_scene(MaterialKind::mirror));
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.mis = mis;
  rig.ctx.max_depth = 1;
  rig.ctx.russian_roulette = false;  // step 3's: an exact value needs none of its noise
  Ray r;
  r.o = glm::vec3(0.1f, 0.05f, 0.2f);
  r.d = glm::normalize(glm::vec3(0.05f, 0.02f, -1.0f));
  Rng rng(3);
  return bounced_at_hit(rig.ctx, r, rng);
}

}  // namespace pt::test
