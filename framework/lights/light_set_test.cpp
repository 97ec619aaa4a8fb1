// Not needed for the assignment.
// LightSet, the estimators' view of the lights: every answer is SampledLights' definition, to the
// bit, while no FasterLightSampling is installed, and the installed one's while one is; each
// light's traits are its kind's.
#include "framework/lights/light_set.h"

#include <gtest/gtest.h>

#include <cstring>

#include <glm/geometric.hpp>

#include "framework/lights/faster_light_sampling.h"
#include "framework/lights/sampled_lights.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/testing/test_scenes.h"

namespace pt {
namespace {

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool same_sample(const LightSample& a, const LightSample& b) {
  return same_bits(a.wi, b.wi) && same_bits(a.L, b.L) && same_bits(a.pdf, b.pdf) &&
         same_bits(a.target.distance, b.target.distance) && same_bits(a.target.p, b.target.p) &&
         same_bits(a.target.p_error, b.target.p_error) && same_bits(a.target.n, b.target.n) &&
         a.target.delta == b.target.delta;
}

/// A floor under a ceiling panel, a point light, a glowing sphere and an ambient light: a light of
/// every kind an estimator tells apart (delta, reachable, not reachable but sampled).
Scene every_kind() {
  Scene s;
  const uint32_t floor = test::add_material(s, glm::vec3(0.5f));
  test::add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  const uint32_t lamp = test::add_material(s, glm::vec3(0), glm::vec3(4.0f));
  test::add_square_ceiling_light(s, 0.5f, 2.0f, glm::vec3(4.0f), lamp);
  Light point;
  point.kind = LightKind::point;
  point.radiance = glm::vec3(3.0f);
  point.position = glm::vec3(1.0f, 1.0f, 1.5f);
  s.lights.push_back(point);
  const uint32_t glow = test::add_material(s, glm::vec3(0), glm::vec3(1.0f, 2.0f, 3.0f));
  s.spheres.push_back(Sphere{glm::vec3(-1.0f, 1.0f, 0.5f), 0.25f, glow});
  s.lights.push_back(test::ambient_light(glm::vec3(0.1f)));
  return s;
}

SurfaceHit floor_point(Rng& rng) {
  SurfaceHit h;
  h.p = glm::vec3(3.0f * rng.next_float() - 1.5f, 3.0f * rng.next_float() - 1.5f, 0.0f);
  h.primitive = 0;
  return h;
}

TEST(FrameworkLightSet, EachLightsTraitsAreItsKinds) {
  const Scene s = every_kind();
  const LightSet set(s);
  const auto& kinds = set.sampled().lights();
  ASSERT_EQ(set.lights().size(), kinds.size());
  int delta = 0, hittable = 0;
  for (size_t k = 0; k < kinds.size(); ++k) {
    EXPECT_EQ(set.lights()[k].is_delta(), kinds[k].is_delta()) << "light " << k;
    EXPECT_EQ(set.lights()[k].can_be_hit(), kinds[k].can_be_hit()) << "light " << k;
    delta += kinds[k].is_delta();
    hittable += kinds[k].can_be_hit();
  }
  // The point light is delta; the panel, the sphere and the ambient light can be hit.
  EXPECT_EQ(delta, 1);
  EXPECT_EQ(hittable, 3);
}

TEST(FrameworkLightSet, EveryAnswerIsTheDefinitionsToTheBit) {
  const Scene s = every_kind();
  const LightSet set(s);
  const SampledLights& def = set.sampled();
  const test::DoubleQuery query(s);
  ASSERT_EQ(FasterLightSampling::on_this_thread(), nullptr);
  Rng rng(3, 5);
  for (int i = 0; i < 200; ++i) {
    const SurfaceHit at = floor_point(rng);
    for (int k = 0; k < int(set.lights().size()); ++k) {
      const glm::vec2 u = rng.next_2d();
      const LightSample ls = set.sample(k, at, u);
      ASSERT_TRUE(same_sample(ls, def.make_sample(k, at, u))) << "light " << k << ", point " << i;
      const Ray shadow = spawn_shadow_ray(at, ls);
      ASSERT_TRUE(same_bits(shadow, make_shadow_ray(at, ls)));
      EXPECT_EQ(set.unoccluded(query, shadow, k), def.unoccluded(query, shadow, k));
    }
    // A direction of the upper hemisphere, as a hemisphere estimate traces it.
    const Ray r = spawn_ray(at, square_to_uniform_hemisphere(rng.next_2d()));
    SurfaceHit h;
    const SurfaceHit* hit = query.intersect(r, &h) ? &h : nullptr;
    ASSERT_TRUE(same_bits(set.radiance_along(r, hit), def.radiance_along(r, hit)));
    ASSERT_TRUE(same_bits(set.environment_radiance(r.d), def.environment_radiance(r.d)));
    for (int k = 0; k < int(set.lights().size()); ++k) {
      ASSERT_TRUE(same_bits(set.emitted_along(k, r, hit), def.emitted_along(k, r, hit)));
      ASSERT_TRUE(same_bits(set.pdf(k, at, r.d, hit), def.pdf(k, at, r.d, hit)));
    }
    if (hit) {
      const int light = set.light_of_primitive(hit->primitive);
      ASSERT_EQ(light, def.light_of_primitive(hit->primitive));
      if (light >= 0) {
        ASSERT_TRUE(same_bits(set.emitted(light, *hit, r.d), def.emitted(light, *hit, r.d)));
      }
    }
  }
}

/// Answers every call with a sample and a ray no definition makes, counting the calls.
class Marked final : public FasterLightSampling {
 public:
  LightSample sample(const SampledLights&, int, const SurfaceHit&, glm::vec2) override {
    ++samples;
    LightSample ls;
    ls.pdf = 42.0f;
    return ls;
  }
  Ray shadow_ray(const SurfaceHit&, const LightSample&) override {
    ++rays;
    Ray r;
    r.tmax = 7.0f;
    return r;
  }
  int samples = 0, rays = 0;
};

TEST(FrameworkLightSet, AnInstalledFasterSamplingAnswersWhileItLives) {
  const Scene s = every_kind();
  const LightSet set(s);
  Rng rng(1, 2);
  const SurfaceHit at = floor_point(rng);
  const glm::vec2 u(0.25f, 0.75f);
  Marked marked;
  {
    const FasterLightSampling::Installed installed(marked);
    EXPECT_EQ(set.sample(0, at, u).pdf, 42.0f);
    EXPECT_EQ(spawn_shadow_ray(at, LightSample{}).tmax, 7.0f);
  }
  EXPECT_EQ(marked.samples, 1);
  EXPECT_EQ(marked.rays, 1);
  EXPECT_TRUE(same_sample(set.sample(0, at, u), set.sampled().make_sample(0, at, u)));
  EXPECT_EQ(marked.samples, 1);
}

}  // namespace
}  // namespace pt
