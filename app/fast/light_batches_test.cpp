// LightBatches, installed as the thread's FasterLightSampling: whatever an estimate draws, every
// sample LightSet::sample gives it is make_sample's for the light, point and numbers it passed,
// and spawn_shadow_ray gives make_shadow_ray's ray for it, to the bit.
// SOLUTION-ONLY FILE: not in the student handout, since it tests the instructor's build's speed.
// It foresees the numbers of an estimate that draws them one sample after another, and stops
// foreseeing for one that draws otherwise.
#include "app/fast/light_batches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "framework/math/float_error.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
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
         std::memcmp(&a.target.distance, &b.target.distance, sizeof a.target.distance) == 0 &&
         std::memcmp(&a.target.p, &b.target.p, sizeof a.target.p) == 0 &&
         std::memcmp(&a.target.p_error, &b.target.p_error, sizeof a.target.p_error) == 0 &&
         std::memcmp(&a.target.n, &b.target.n, sizeof a.target.n) == 0 &&
         a.target.delta == b.target.delta;
}

void expect_same_sample_bits(const LightSample& got, const LightSample& want, int i) {
  ASSERT_TRUE(same_sample(got, want)) << "sample " << i << ": wi " << got.wi.x << " " << want.wi.x
                                      << ", pdf " << got.pdf << " " << want.pdf;
}

SurfaceHit hit_at(const glm::vec3& p) {
  SurfaceHit h;
  h.p = p;
  return h;
}

/// How an estimate draws its numbers between light samples.
enum class Draws { one_pair_a_sample, an_extra_number_between, its_own_generator };

bool same_ray(const Ray& a, const Ray& b) { return std::memcmp(&a, &b, sizeof(Ray)) == 0; }

/// An estimate's light loop over `points`: `per_light` samples of each light from each point,
/// drawn as `draws` says, through LightSet::sample and spawn_shadow_ray with the batches
/// installed; every sample checked against make_sample, and its shadow ray against
/// make_shadow_ray; counts the rays handed out as made in a batch into `shadow_rays_made`.
/// Returns the counts of calls answered ahead and samples made in vain.
std::pair<int, int> run_loop(const LightSet& set, int per_light, Draws draws, int points,
                             int* shadow_rays_made = nullptr) {
  Rng rng(5, 9), own(77, 1);
  LightBatches sampler(&rng, per_light);
  const FasterLightSampling::Installed installed(sampler);
  for (int i = 0; i < points; ++i) {
    SurfaceHit at = hit_at(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 0.25f * (i % 3)));
    at.ng = glm::normalize(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 1.0f - 2.0f * (i % 2)));
    at.p_error = glm::vec3(1e-6f * float(i % 4));
    for (int k = 0; k < int(set.lights().size()); ++k) {
      for (int j = 0; j < per_light; ++j) {
        if (draws == Draws::an_extra_number_between && j % 3 == 2) rng.next_float();
        const glm::vec2 u = draws == Draws::its_own_generator ? own.next_2d() : rng.next_2d();
        const LightSample got = set.sample(k, at, u);
        EXPECT_TRUE(same_sample(got, set.sampled().make_sample(k, at, u)))
            << "light " << k << ", point " << i << ", sample " << j;
        // Its shadow ray, made in the batch or not, is the one make_shadow_ray makes.
        EXPECT_TRUE(same_ray(spawn_shadow_ray(at, got), make_shadow_ray(at, got)))
            << "shadow ray: light " << k << ", point " << i << ", sample " << j;
        if (testing::Test::HasFailure()) return {0, 0};
      }
    }
  }
  if (shadow_rays_made) *shadow_rays_made = sampler.rays_handed_out();
  return {sampler.answered_ahead(), sampler.made_in_vain()};
}

TEST(FastLightBatches, ForeseesAnEstimateThatDrawsOnePairASample) {
  const Scene s = lit_scene();
  const LightSet set(s);
  ASSERT_EQ(set.lights().size(), 2u);
  ASSERT_TRUE(set.sampled().lights()[0].quad);
  ASSERT_EQ(set.sampled().lights()[1].kind, SampledLightKind::mesh);
  // 16 samples a light: two batches of eight; 5: one of five; 12: eight and four.
  for (int per_light : {16, 5, 12}) {
    int rays = 0;
    const auto [ahead, in_vain] = run_loop(set, per_light, Draws::one_pair_a_sample, 50, &rays);
    if (HasFailure()) return;
    const int batches = (per_light + 7) / 8;
    EXPECT_EQ(ahead, 50 * 2 * (per_light - batches)) << per_light << " a light";
    EXPECT_EQ(in_vain, 0) << per_light << " a light";
    // The quad's batches make their shadow rays (the mesh's, made one by one, do not).
    EXPECT_GT(rays, 50 * per_light / 2) << per_light << " a light";
  }
}

TEST(FastLightBatches, AnswersAnEstimateThatDrawsOtherwiseAndStopsForeseeing) {
  const Scene s = lit_scene();
  const LightSet set(s);
  for (Draws draws : {Draws::an_extra_number_between, Draws::its_own_generator}) {
    const auto [ahead, in_vain] = run_loop(set, 16, draws, 50);
    if (HasFailure()) return;
    // The first batch is the only one: its foreseen samples go (partly) unasked, and the
    // sampler makes each later sample on the spot.
    EXPECT_GT(in_vain, 0);
    EXPECT_LE(ahead + in_vain, LightBatches::kBatch - 1);
  }
}

TEST(FastLightBatches, AnotherPointOrLightWithTheForeseenNumbersIsSampledAnew) {
  const Scene s = lit_scene();
  const LightSet set(s);
  Rng rng(3, 3);
  LightBatches sampler(&rng, 8);
  const FasterLightSampling::Installed installed(sampler);
  const SurfaceHit a = hit_at({0.1f, 0.2f, 0.0f}), b = hit_at({0.1f, 0.2f, -0.0f});
  const glm::vec2 u0 = rng.next_2d();
  ASSERT_TRUE(same_sample(set.sample(0, a, u0), set.sampled().make_sample(0, a, u0)));
  // The numbers the batch was made for, asked from a point that differs only in a zero's sign
  // (the same position to ==, not to the bit), then of the other light: neither is in the batch.
  Rng peek = rng;
  const glm::vec2 u1 = peek.next_2d(), u2 = peek.next_2d();
  EXPECT_TRUE(same_sample(set.sample(0, b, u1), set.sampled().make_sample(0, b, u1)));
  EXPECT_TRUE(same_sample(set.sample(1, a, u2), set.sampled().make_sample(1, a, u2)));
  EXPECT_EQ(sampler.answered_ahead(), 0);
  EXPECT_GT(sampler.made_in_vain(), 0);
}

// Another set with the light index, point and numbers a batch was made for is not answered from
// it; and without a generator every sample is made on its own. Uninstalled, the set answers
// by its definition again.
TEST(FastLightBatches, AnotherSetOrNoGeneratorIsSampledOnItsOwn) {
  const Scene s = lit_scene();
  const LightSet set(s), other(s);
  Rng rng(4, 4);
  const SurfaceHit at = hit_at({0.0f, 0.0f, 0.5f});
  {
    LightBatches sampler(&rng, 8);
    const FasterLightSampling::Installed installed(sampler);
    EXPECT_EQ(FasterLightSampling::on_this_thread(), &sampler);
    const glm::vec2 u0 = rng.next_2d();
    EXPECT_TRUE(same_sample(set.sample(0, at, u0), set.sampled().make_sample(0, at, u0)));
    const glm::vec2 u1 = rng.next_2d();
    EXPECT_TRUE(same_sample(other.sample(0, at, u1), other.sampled().make_sample(0, at, u1)));
    EXPECT_EQ(sampler.answered_ahead(), 0);
  }
  EXPECT_EQ(FasterLightSampling::on_this_thread(), nullptr);
  LightBatches sampler;
  const FasterLightSampling::Installed installed(sampler);
  for (int j = 0; j < 20; ++j) {
    const glm::vec2 u = rng.next_2d();
    EXPECT_TRUE(same_sample(set.sample(0, at, u), set.sampled().make_sample(0, at, u)));
  }
  EXPECT_EQ(sampler.answered_ahead(), 0);
  EXPECT_EQ(sampler.made_in_vain(), 0);
}

/// A panel of the two triangles (a, b, c) and (a, c, d) on an area light of their shape.
Scene two_triangle_panel(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                         const glm::vec3& d) {
  Scene s;
  const uint32_t lamp = test::add_material(s, glm::vec3(0), glm::vec3(10.0f));
  Light l;
  l.kind = LightKind::area;
  l.radiance = glm::vec3(10.0f);
  l.position = 0.25f * (a + b + c + d);
  l.edge_u = b - a;
  l.edge_v = d - a;
  l.direction = -glm::normalize(glm::cross(b - a, d - a));
  s.lights.push_back(l);
  s.positions = {a, b, c, d};
  s.triangles = {Triangle{{0, 1, 2}, lamp}, Triangle{{0, 2, 3}, lamp}};
  return s;
}

/// Shading point i: anywhere around a panel near the origin, on a plane of zeros of either sign
/// (every fifth), far away (every seventh) or on the course panel (every eleventh), with a
/// normal of any direction and an error box from none to large.
SurfaceHit point_around(Rng& rng, int i) {
  SurfaceHit at;
  at.p = glm::vec3(rng.next_float() * 6 - 3, rng.next_float() * 6 - 3, rng.next_float() * 6 - 3);
  if (i % 5 == 0) at.p[i % 3] = i % 2 ? 0.0f : -0.0f;
  if (i % 7 == 0) at.p *= 1e4f;
  if (i % 11 == 0) at.p = glm::vec3(0.1f, 0.05f, 1.0f);
  at.ng = square_to_uniform_sphere(rng.next_2d());
  if (i % 9 == 0) at.ng = glm::vec3(0.0f, i % 2 ? -0.0f : 0.0f, i % 4 < 2 ? 1.0f : -1.0f);
  const float scale = std::max({std::abs(at.p.x), std::abs(at.p.y), std::abs(at.p.z), 1.0f});
  at.p_error = i % 3 == 0 ? glm::vec3(0.0f)
                          : glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) *
                                (i % 3 == 1 ? 1e-6f : 1e-3f) * scale;
  return at;
}

// A batch of n samples (every n from 1 to 8) of a course-like quad, of two turned about two axes
// (every term of every coordinate counts: near the points, and far from the origin), of a
// trapezoid panel (sampled on its light's rectangle) and of a mesh: each is make_sample's to the bit, and each
// shadow ray make_shadow_ray's. And a quad's ray made in the batch is handed out only for the
// sample and point it was made for: a copy with any input changed (the sample's direction,
// point, error box, normal, whole or its z alone, or distance; the point's position, error box or
// normal, whole or its z alone) gets the ray made anew from its inputs.
TEST(FastLightBatches, BatchedSamplesAndShadowRaysAreTheDefinitionsBitForBit) {
  const glm::vec3 a(-0.4f, -0.3f, 1.0f), b(0.4f, -0.3f, 1.0f), c(0.4f, 0.3f, 1.0f), d(-0.4f, 0.3f, 1.0f);
  Scene course = two_triangle_panel(a, b, c, d);
  const uint32_t glow = test::add_material(course, glm::vec3(0), glm::vec3(2.0f, 3.0f, 4.0f));
  test::add_triangle(course, {-1, -0.5f, -1}, {1.5f, -0.7f, -1.2f}, {0.2f, 1.0f, -0.6f}, glow);
  test::add_triangle(course, {2, 2, 2}, {3, 2, 2.5f}, {2, 4, 2}, glow);
  const Scene trapezoid = two_triangle_panel(a, b, c, {-0.2f, 0.3f, 1.0f});
  auto turned = [](const glm::dvec3& o) {
    const glm::dvec3 eu(0.37, 0.21, -0.13), ev(-0.11, 0.29, 0.17);
    return two_triangle_panel(glm::vec3(o), glm::vec3(o + eu), glm::vec3(o + eu + ev), glm::vec3(o + ev));
  };
  const Scene near = turned({0.1, -0.2, 0.9}), far = turned({1234.5, -987.25, 321.125});
  const LightSet course_lights(course), trapezoid_lights(trapezoid), near_lights(near), far_lights(far);
  ASSERT_TRUE(course_lights.sampled().lights().at(0).quad);
  ASSERT_EQ(course_lights.sampled().lights().at(1).kind, SampledLightKind::mesh);
  // A panel unlike its light (a trapezoid) is sampled on the light's rectangle: a quad as well.
  ASSERT_TRUE(trapezoid_lights.sampled().lights().at(0).quad);
  ASSERT_TRUE(near_lights.sampled().lights().at(0).quad);
  ASSERT_TRUE(far_lights.sampled().lights().at(0).quad);
  struct Case { const LightSet* set; int index; };
  const Case cases[] = {{&course_lights, 0}, {&course_lights, 1}, {&trapezoid_lights, 0},
                        {&near_lights, 0}, {&far_lights, 0}};
  Rng points(21, 8);
  long kept = 0, tried[10] = {}, changed[10] = {};
  int handed_out = 0;
  for (int i = 0; i < 4000; ++i) {
    const SurfaceHit at = point_around(points, i);
    const int n = 1 + i % LightBatches::kBatch;
    for (const Case& k : cases) {
      Rng rng(i, 3);
      LightBatches sampler(&rng, n);
      const FasterLightSampling::Installed installed(sampler);
      for (int j = 0; j < n; ++j) {
        const glm::vec2 u = rng.next_2d();
        const LightSample ls = k.set->sample(k.index, at, u);
        expect_same_sample_bits(ls, k.set->sampled().make_sample(k.index, at, u), i);
        if (testing::Test::HasFatalFailure()) return;
        kept += ls.pdf > 0.0f;
        const Ray want = make_shadow_ray(at, ls);
        const int before = sampler.rays_handed_out();
        ASSERT_TRUE(same_ray(spawn_shadow_ray(at, ls), want)) << "point " << i << ", sample " << j;
        if (sampler.rays_handed_out() == before) continue;
        ++handed_out;
        // One input changed: the ray must be the one made from the inputs as they now are.
        LightSample other = ls;
        SurfaceHit from = at;
        switch ((i + j) % 10) {
          case 0: other.wi = -other.wi; break;  // the other side of both ends
          case 1: other.target.p.x += 0.01f; break;
          case 2: other.target.p_error *= 4.0f, other.target.p_error += glm::vec3(1e-4f); break;
          case 3:
            other.target.n = glm::normalize(other.target.n + glm::vec3(0.3f, -0.2f, 0.1f));
            break;
          case 4: other.target.distance = std::numeric_limits<float>::infinity(); break;
          case 5: from.p.y += 0.01f; break;
          case 6: from.p_error *= 4.0f, from.p_error += glm::vec3(1e-4f); break;
          case 7: from.ng = glm::normalize(from.ng + glm::vec3(0.2f, 0.3f, -0.1f)); break;
          case 8: from.ng.z += 0.5f; break;
          default: other.target.n.z += 0.5f; break;
        }
        const Ray fresh = make_shadow_ray(from, other);
        ASSERT_TRUE(same_ray(spawn_shadow_ray(from, other), fresh))
            << "point " << i << ", sample " << j << ", change " << (i + j) % 10;
        ++tried[(i + j) % 10];
        changed[(i + j) % 10] += !same_ray(fresh, want);
      }
    }
  }
  EXPECT_GT(kept, 10000) << "most samples should reach the point";
#if defined(__AVX2__)
  EXPECT_GT(handed_out, 5000) << "the quads' batches should make most samples' shadow rays";
  // A check that could not fail would hand out rays that equal the fresh ones anyway: each
  // change must make another ray for most samples (a changed normal does not where the point's
  // error box is empty).
  for (int c = 0; c < 10; ++c) EXPECT_GT(changed[c], tried[c] / 2) << "change " << c;
#endif
}

}  // namespace
}  // namespace pt
