// LightSampler: whatever an estimate draws, every sample it is given is LightSet::sample's for
// the light, point and numbers it passed, and spawn_shadow_ray gives spawn_ray_to's ray for it; it
// foresees the numbers of an estimate that draws them one sample after another, and stops
// foreseeing for one that draws otherwise.
#include "framework/lights/light_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "framework/sampling/rng.h"
#include "framework/testing/test_scenes.h"

namespace pt {
namespace {

/// A room's ceiling light: a quad panel (two triangles) under an area light, and a mesh light.
Scene lit_scene() {
  Scene s;
  const uint32_t lamp = test::add_material(s, glm::vec3(0), glm::vec3(4.0f));
  test::add_square_ceiling_light(s, 0.5f, 2.0f, glm::vec3(4.0f), lamp);
  const uint32_t glow = test::add_material(s, glm::vec3(0), glm::vec3(1.0f, 2.0f, 3.0f));
  test::add_triangle(s, {-2, -1, 0}, {-2, 1, 0.5f}, {-2, 0, 1.5f}, glow);
  return s;
}

bool same_sample(const LightSample& a, const LightSample& b) {
  // Field by field (not the padding), to the bit.
  return std::memcmp(&a.wi, &b.wi, sizeof a.wi) == 0 && std::memcmp(&a.L, &b.L, sizeof a.L) == 0 &&
         std::memcmp(&a.pdf, &b.pdf, sizeof a.pdf) == 0 &&
         std::memcmp(&a.distance, &b.distance, sizeof a.distance) == 0 &&
         std::memcmp(&a.p, &b.p, sizeof a.p) == 0 &&
         std::memcmp(&a.p_error, &b.p_error, sizeof a.p_error) == 0 &&
         std::memcmp(&a.n, &b.n, sizeof a.n) == 0 && a.delta == b.delta;
}

SurfaceHit hit_at(const glm::vec3& p) {
  SurfaceHit h;
  h.p = p;
  return h;
}

/// How an estimate draws its numbers between light samples.
enum class Draws { one_pair_a_sample, an_extra_number_between, its_own_generator };

/// An estimate's light loop over `points`: `per_light` samples of each light from each point,
/// drawn as `draws` says; every sample checked against LightSet::sample, and its shadow ray
/// against spawn_ray_to's; counts the samples that carried their ray into `shadow_rays_made`.
/// Returns the sampler's counts of calls answered ahead and samples made in vain.
std::pair<int, int> run_loop(const LightSet& set, int per_light, Draws draws, int points,
                             int* shadow_rays_made = nullptr) {
  Rng rng(5, 9), own(77, 1);
  const LightSampler sampler(set, &rng, per_light);
  for (int i = 0; i < points; ++i) {
    SurfaceHit at = hit_at(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 0.25f * (i % 3)));
    at.ng = glm::normalize(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 1.0f - 2.0f * (i % 2)));
    at.p_error = glm::vec3(1e-6f * float(i % 4));
    for (int k = 0; k < int(set.lights().size()); ++k) {
      for (int j = 0; j < per_light; ++j) {
        if (draws == Draws::an_extra_number_between && j % 3 == 2) rng.next_float();
        const glm::vec2 u = draws == Draws::its_own_generator ? own.next_2d() : rng.next_2d();
        const LightSample got = sampler.sample(k, at, u);
        EXPECT_TRUE(same_sample(got, set.sample(k, at, u)))
            << "light " << k << ", point " << i << ", sample " << j;
        // Its shadow ray, carried or not, is the one spawn_ray_to makes.
        const Ray ray = spawn_shadow_ray(at, got);
        const Ray want = std::isfinite(got.distance) ? spawn_ray_to(at, got.wi, got.p, got.p_error, got.n)
                                                     : spawn_ray(at, got.wi);
        EXPECT_EQ(std::memcmp(&ray, &want, sizeof(Ray)), 0)
            << "shadow ray: light " << k << ", point " << i << ", sample " << j;
        if (testing::Test::HasFailure()) return {0, 0};
        if (shadow_rays_made) *shadow_rays_made += got.shadow_ray_made;
      }
    }
  }
  return {sampler.answered_ahead(), sampler.made_in_vain()};
}

TEST(FrameworkLightSampler, ForeseesAnEstimateThatDrawsOnePairASample) {
  const Scene s = lit_scene();
  const LightSet set(s);
  ASSERT_EQ(set.lights().size(), 2u);
  ASSERT_TRUE(set.lights()[0].quad);
  ASSERT_EQ(set.lights()[1].kind, SampledLightKind::mesh);
  // 16 samples a light: two batches of eight; 5: one of five; 12: eight and four.
  for (int per_light : {16, 5, 12}) {
    int rays = 0;
    const auto [ahead, in_vain] = run_loop(set, per_light, Draws::one_pair_a_sample, 50, &rays);
    if (HasFailure()) return;
    const int batches = (per_light + 7) / 8;
    EXPECT_EQ(ahead, 50 * 2 * (per_light - batches)) << per_light << " a light";
    EXPECT_EQ(in_vain, 0) << per_light << " a light";
    // The quad's batches carry their shadow rays (the mesh's, made one by one, do not).
    EXPECT_GT(rays, 50 * per_light / 2) << per_light << " a light";
  }
}

TEST(FrameworkLightSampler, AnswersAnEstimateThatDrawsOtherwiseAndStopsForeseeing) {
  const Scene s = lit_scene();
  const LightSet set(s);
  for (Draws draws : {Draws::an_extra_number_between, Draws::its_own_generator}) {
    const auto [ahead, in_vain] = run_loop(set, 16, draws, 50);
    if (HasFailure()) return;
    // The first batch is the only one: its foreseen samples go (partly) unasked, and the
    // sampler makes each later sample on the spot.
    EXPECT_GT(in_vain, 0);
    EXPECT_LE(ahead + in_vain, LightSampler::kBatch - 1);
  }
}

TEST(FrameworkLightSampler, AnotherPointOrLightWithTheForeseenNumbersIsSampledAnew) {
  const Scene s = lit_scene();
  const LightSet set(s);
  Rng rng(3, 3);
  const LightSampler sampler(set, &rng, 8);
  const SurfaceHit a = hit_at({0.1f, 0.2f, 0.0f}), b = hit_at({0.1f, 0.2f, -0.0f});
  const glm::vec2 u0 = rng.next_2d();
  ASSERT_TRUE(same_sample(sampler.sample(0, a, u0), set.sample(0, a, u0)));
  // The numbers the batch was made for, asked from a point that differs only in a zero's sign
  // (the same position to ==, not to the bit), then of the other light: neither is in the batch.
  Rng peek = rng;
  const glm::vec2 u1 = peek.next_2d(), u2 = peek.next_2d();
  const LightSample from_b = sampler.sample(0, b, u1);
  EXPECT_TRUE(same_sample(from_b, set.sample(0, b, u1)));
  EXPECT_TRUE(same_sample(sampler.sample(1, a, u2), set.sample(1, a, u2)));
  EXPECT_EQ(sampler.answered_ahead(), 0);
  EXPECT_GT(sampler.made_in_vain(), 0);
}

// What a student may write with ctx.lights, as with the set it used to be: take it as the set,
// or copy it; each answers the set's samples.
TEST(FrameworkLightSampler, StandsInForTheSetWhereCodeNamesTheSet) {
  const Scene s = lit_scene();
  const LightSet set(s);
  Rng rng(8, 1);
  const LightSampler sampler(set, &rng, 4);
  const LightSet& as_set = sampler;
  EXPECT_EQ(&as_set, &set);
  const auto copy = sampler;
  const SurfaceHit at = hit_at({0.2f, 0.1f, 0.3f});
  for (int j = 0; j < 4; ++j) {
    const glm::vec2 u = rng.next_2d();
    EXPECT_TRUE(same_sample(copy.sample(0, at, u), set.sample(0, at, u)));
  }
}

TEST(FrameworkLightSampler, WithoutAGeneratorEverySampleIsMadeOnItsOwn) {
  const Scene s = lit_scene();
  const LightSet set(s);
  const LightSampler sampler(set);
  Rng rng(1, 2);
  const SurfaceHit at = hit_at({0.0f, 0.0f, 0.5f});
  for (int j = 0; j < 20; ++j) {
    const glm::vec2 u = rng.next_2d();
    EXPECT_TRUE(same_sample(sampler.sample(0, at, u), set.sample(0, at, u)));
  }
  EXPECT_EQ(sampler.answered_ahead(), 0);
  EXPECT_EQ(sampler.made_in_vain(), 0);
}

}  // namespace
}  // namespace pt
