// What the Part 4 step tests share: the path estimator as a test estimator, the closed
// enclosure whose answer is known at every depth, a t-test of a mean against its answer, and the
// mirror under a panel that disagrees with its light.
#pragma once

#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "framework/testing/lighting_rig.h"
#include "parts/4-global/global_illumination.h"

namespace pt::test {

/// Significance of each known-answer t-test.
constexpr double kPathAlpha = 0.001;

/// Part 4's estimator of a camera ray's radiance, for sample_values.
inline Estimator gi(const LightingContext& ctx) {
  return [&ctx](const Ray& r, Rng& g) { return estimate_global_illumination(ctx, r, g); };
}

/// A closed box of albedo rho emitting E everywhere on its inside.
inline Scene enclosure(float rho, float E) {
  Scene s;
  uint32_t m = add_material(s, glm::vec3(rho), glm::vec3(E));
  add_closed_cube(s, m);
  return s;
}

/// Expects the mean of `xs` to be `expected` within chance (t-test at kPathAlpha).
inline void expect_mean(const std::vector<double>& xs, double expected, const std::string& what) {
  auto c = t_test_mean(xs, expected, kPathAlpha);
  EXPECT_TRUE(c.pass) << what << ": mean " << c.mean << " ± " << c.stderr_ << ", expected "
                      << expected;
}

/// What the camera sees in a mirror floor under CBcoil's disagreeing panel and light
/// (disagreeing_panel_scene with a mirror floor), at depth 1: the panel with the radiance light
/// sampling gives it, the light's (5, not the panel's 10). `hemisphere`, `mis` choose the
/// estimator.
inline glm::vec3 panel_in_a_mirror(bool hemisphere, bool mis) {
  Rig rig(disagreeing_panel_scene(MaterialKind::mirror));
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.mis = mis;
  rig.ctx.max_depth = 1;
  Ray r;
  r.o = glm::vec3(0.1f, 0.05f, 0.2f);
  r.d = glm::normalize(glm::vec3(0.05f, 0.02f, -1.0f));
  Rng rng(3);
  return estimate_global_illumination(rig.ctx, r, rng);
}

}  // namespace pt::test
