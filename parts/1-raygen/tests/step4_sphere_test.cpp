// Part 1: ray-sphere roots against a long-double reference, on the cases that break the textbook
// quadratic: far spheres, near-tangent rays, origins inside or on the sphere.
//
// REFERENCE. Every float input is exact in long double (64-bit significand). The reference roots
// are not a formula: each is found by bisection in long double of g(t) = |o + t·d - c|^2 - r^2,
// on one side or the other of the ray's closest approach to the centre (g is a parabola, so it
// is monotone there), until the bracket cannot shrink. g is evaluated to about 2^-64 of its
// terms, so the reference is 2^40 times closer to the exact root than the float bound below.
//
// BOUND. With f = o - c, the closest approach t_m = -(f·d)/|d|^2, the ray's distance |v| from the
// centre and the half-chord w = sqrt(r^2 - |v|^2) / |d|, the exact roots are t_m ± w. Rounding
// f = o - c alone moves the origin by up to u|f| per axis, which moves t_m by u|f|/|d| and |v|
// by u|f|, hence w by u|f|·|v| / (|d|·sqrt(r^2 - |v|^2)); a cancellation-free evaluation adds a
// dozen or so roundings, each relative to a quantity of size |f| + r (lengths) or (|f| + r)^2
// (products). So, with room for their constants:
//   |t_float - t| <= 32·u·(|f| + r)/|d| · (1 + r / sqrt(r^2 - |v|^2)).
// The first term is the float resolution of the scene itself (far spheres lose nothing more: with
// |f| = 1e4 and r = 1 it is about 2e-3 absolute, 2e-7 relative to t ≈ 1e4). The second is the
// genuine ill-conditioning of a near-tangent ray (the roots move like the square root of the
// miss distance), and the reason the textbook b^2 - 4ac, whose cancellation is of size (|f|^2)u
// instead of (|f| + r)·r·u, fails far spheres. The relative bound is that divided by t.
// Hit/miss must agree except where rounding can decide it: the ray within 32·u·(|f| + r) of
// tangency, or only roots within their bound of tmin = 0 (an origin on the surface) or tmax.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "framework/sampling/rng.h"
#include "framework/testing/probe_mode.h"
#include "parts/1-raygen/sphere_intersect.h"
#include "parts/1-raygen/tests/scene_queries.h"

namespace pt {
namespace {

using LD = long double;
constexpr LD kU = 0x1p-24L;

struct Tally {
  long cases = 0, hits = 0, excluded = 0, disagreements = 0, over_bound = 0;
  LD max_rel = 0, max_ratio = 0;
};

/// The root of g(t) = |f + t·d|^2 - r^2 in [lo, hi], where g changes sign, by bisection.
LD bisect_root(const LD f[3], const LD d[3], LD r, LD lo, LD hi) {
  auto g = [&](LD t) {
    LD sum = 0;
    for (int i = 0; i < 3; ++i) sum += (f[i] + t * d[i]) * (f[i] + t * d[i]);
    return sum - r * r;
  };
  const bool rising = g(hi) > 0;
  for (int i = 0; i < 400; ++i) {
    const LD mid = lo + (hi - lo) / 2;
    if (!(mid > lo && mid < hi)) break;
    if ((g(mid) > 0) == rising) hi = mid;
    else lo = mid;
  }
  return lo + (hi - lo) / 2;
}

void check(const Ray& ray, const Sphere& s, Tally* tally, const char* kind) {
  ++tally->cases;
  float tf = 0;
  const bool fhit = intersect_sphere(ray, s, &tf);
  if (test::is_probe()) return;  // the reference roots are the judge's to compute

  LD f[3], d[3];
  for (int i = 0; i < 3; ++i) f[i] = LD(ray.o[i]) - LD(s.center[i]), d[i] = ray.d[i];
  const LD a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const LD h = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
  LD v2 = 0, f2 = 0;
  for (int i = 0; i < 3; ++i) {
    LD vi = f[i] - h / a * d[i];
    v2 += vi * vi, f2 += f[i] * f[i];
  }
  const LD r = s.radius, vlen = std::sqrt(v2), flen = std::sqrt(f2), dlen = std::sqrt(a);
  const LD scale = 32 * kU * (flen + r);
  if (std::abs(r - vlen) <= scale) {  // within rounding of tangency
    ++tally->excluded;
    return;
  }
  // Roots within their bound of tmin or tmax may count or not: the float code may return such a
  // root or skip it. Roots clear of both ends decide the answer.
  LD t = 0, bound = 0;
  LD certain = INFINITY, uncertain[2];
  int n_uncertain = 0;
  if (vlen < r) {
    bound = scale / dlen * (1 + r / std::sqrt((r - vlen) * (r + vlen)));
    const LD tm = -h / a, reach = 2 * r / dlen;  // past reach the ray is outside the sphere
    for (LD root : {bisect_root(f, d, r, tm - reach, tm), bisect_root(f, d, r, tm, tm + reach)}) {
      if (std::abs(root - LD(ray.tmin)) <= bound || std::abs(root - LD(ray.tmax)) <= bound)
        uncertain[n_uncertain++] = root;
      else if (root > ray.tmin && root < ray.tmax)
        certain = std::min(certain, root);
    }
  }
  const bool ehit = certain < INFINITY;
  if (!ehit && n_uncertain > 0) {
    ++tally->excluded;
    return;
  }
  t = certain;
  // The float code may legitimately return an uncertain root nearer than the certain one.
  for (int i = 0; i < n_uncertain; ++i)
    if (fhit && uncertain[i] < certain && std::abs(LD(tf) - uncertain[i]) <= bound) t = uncertain[i];
  if (ehit != fhit) {
    if (++tally->disagreements <= 5)
      ADD_FAILURE() << kind << ": reference " << (ehit ? "hit" : "miss") << " at " << double(t)
                    << ", float " << (fhit ? "hit" : "miss") << " at " << tf;
    return;
  }
  if (!ehit) return;
  ++tally->hits;
  const LD err = std::abs(LD(tf) - t);
  if (t == certain) tally->max_rel = std::max(tally->max_rel, err / std::abs(t));
  tally->max_ratio = std::max(tally->max_ratio, err / bound);
  if (err > bound && ++tally->over_bound <= 5)
    ADD_FAILURE() << kind << ": t " << tf << " reference " << double(t) << " bound "
                  << double(bound);
}

class SphereCases {
 public:
  explicit SphereCases(uint64_t seed) : rng_(seed) {}
  float uni(float lo, float hi) { return lo + (hi - lo) * rng_.next_float(); }
  glm::vec3 unit() {
    glm::vec3 v;
    do v = glm::vec3(uni(-1, 1), uni(-1, 1), uni(-1, 1));
    while (glm::dot(v, v) > 1 || glm::dot(v, v) < 1e-4f);
    return glm::normalize(v);
  }
  /// A direction of random length (the roots must not assume |d| = 1).
  glm::vec3 stretch(glm::vec3 d) { return d * std::pow(10.0f, uni(-2, 2)); }

  Rng rng_;
};

Tally run(const char* name, long n, const std::function<std::pair<Ray, Sphere>()>& gen) {
  Tally t;
  for (long i = 0; i < n; ++i) {
    auto [ray, s] = gen();
    check(ray, s, &t, name);
  }
  std::printf("%-22s cases %6ld  hits %6ld  excluded %5ld  disagreements %ld  max rel t err "
              "%.3Lg (%.3Lg of bound)\n",
              name, t.cases, t.hits, t.excluded, t.disagreements, t.max_rel, t.max_ratio);
  EXPECT_EQ(t.disagreements, 0) << name;
  EXPECT_EQ(t.over_bound, 0) << name;
  EXPECT_GT(t.hits, n / 10) << name;
  return t;
}

TEST(sphere, roots_match_long_double_reference) {
  SphereCases g(5);
  const long n = 40000;
  run("far (1e4, small r)", n, [&] {
    Sphere s;
    s.center = std::pow(10.0f, g.uni(3.5f, 4.5f)) * g.unit();
    s.radius = std::pow(10.0f, g.uni(-2, 1));
    Ray ray;
    ray.o = g.unit() * g.uni(0, 2);
    ray.d = g.stretch(s.center + 1.5f * s.radius * g.unit() - ray.o);
    return std::make_pair(ray, s);
  });
  run("near tangent", n, [&] {
    Sphere s;
    s.center = g.unit() * g.uni(0, 100);
    s.radius = std::pow(10.0f, g.uni(-1, 2));
    Ray ray;
    ray.o = s.center + s.radius * g.uni(2, 50) * g.unit();
    // Aim at a point beside the sphere at a relative miss distance from 1e-7 to 1e-1, inside or
    // outside the silhouette.
    const glm::vec3 to_c = glm::normalize(s.center - ray.o);
    glm::vec3 side = glm::normalize(glm::cross(to_c, g.unit()));
    const float miss = std::pow(10.0f, g.uni(-7, -1)) * (g.uni(0, 1) < 0.5f ? -1 : 1);
    ray.d = g.stretch(s.center + s.radius * (1 + miss) * side - ray.o);
    return std::make_pair(ray, s);
  });
  run("origin inside", n, [&] {
    Sphere s;
    s.center = g.unit() * g.uni(0, 1e3f);
    s.radius = std::pow(10.0f, g.uni(-2, 3));
    Ray ray;
    ray.o = s.center + s.radius * g.uni(0, 0.999f) * g.unit();
    ray.d = g.stretch(g.unit());
    return std::make_pair(ray, s);
  });
  run("origin near surface", n, [&] {
    Sphere s;
    s.center = g.unit() * g.uni(0, 1e2f);
    s.radius = std::pow(10.0f, g.uni(-1, 2));
    Ray ray;
    ray.o = s.center + s.radius * g.unit();  // on the surface up to rounding
    ray.d = g.stretch(g.unit());
    return std::make_pair(ray, s);
  });
}

// Both roots count, the nearer one inside (tmin, tmax) wins.
TEST(sphere, nearest_root_inside_the_interval) {
  const Sphere s{glm::vec3(0, 0, -10), 2.0f, 0};
  Ray ray;  // from the origin down -z: roots 8 and 12
  float t = 0;
  ASSERT_TRUE(intersect_sphere(ray, s, &t));
  EXPECT_FLOAT_EQ(t, 8.0f);
  ray.tmin = 9.0f;
  ASSERT_TRUE(intersect_sphere(ray, s, &t));
  EXPECT_FLOAT_EQ(t, 12.0f);
  ray.tmin = 0.0f, ray.tmax = 7.0f;
  EXPECT_FALSE(intersect_sphere(ray, s, &t));
  ray.tmax = 1e30f, ray.o = glm::vec3(0, 0, -10);  // from the centre: the far side, at r
  ASSERT_TRUE(intersect_sphere(ray, s, &t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  ray.o = glm::vec3(0, 0, 5);  // sphere behind the origin
  ray.d = glm::vec3(0, 0, 1);
  EXPECT_FALSE(intersect_sphere(ray, s, &t));
}

// --- The sphere inside a scene, through the given brute-force query (only spheres in it) -------

/// Two unit spheres on the -z axis, centred at -6 and -4.5 (they overlap): primitive 0 has
/// material 6, primitive 1 material 7.
Scene sphere_stack() {
  Scene s;
  s.spheres.push_back(Sphere{glm::vec3(0, 0, -6), 1.0f, 6});
  s.spheres.push_back(Sphere{glm::vec3(0, 0, -4.5f), 1.0f, 7});
  return s;
}

TEST(sphere, brute_force_finds_the_nearest_of_overlapping_spheres) {
  Scene s = sphere_stack();
  BruteForce bf(s);
  SurfaceHit hit;
  Ray ray;  // from the origin down -z
  ASSERT_TRUE(bf.intersect(ray, &hit));
  EXPECT_FLOAT_EQ(hit.t, 3.5f) << "the nearer sphere's front is at t = 3.5: the far root?";
  EXPECT_EQ(hit.primitive, 1u);
  EXPECT_EQ(hit.material, 7u);
  ray.tmin = 5.2f;  // inside both spheres: the far side of the nearer one at 5.5
  ASSERT_TRUE(bf.intersect(ray, &hit)) << "from inside a sphere, its far side is a hit";
  EXPECT_FLOAT_EQ(hit.t, 5.5f);
  EXPECT_EQ(hit.primitive, 1u);
  ray.tmin = 5.6f;  // inside the first sphere only: its far side at 7
  ASSERT_TRUE(bf.intersect(ray, &hit)) << "from inside a sphere, its far side is a hit";
  EXPECT_FLOAT_EQ(hit.t, 7.0f);
  EXPECT_EQ(hit.primitive, 0u);
  ray.tmin = 7.5f;
  EXPECT_FALSE(bf.intersect(ray, &hit)) << "tmin = 7.5: both spheres are behind the interval";
}

TEST(sphere, occlusion_respects_the_interval) {
  Scene s = sphere_stack();
  BruteForce bf(s);
  Ray ray;
  ray.tmax = 3.49f;
  EXPECT_FALSE(bf.occluded(ray)) << "tmax 3.49, the first sphere at t = 3.5";
  ray.tmax = 3.51f;
  EXPECT_TRUE(bf.occluded(ray));
  ray.tmin = 7.01f, ray.tmax = 100.0f;
  EXPECT_FALSE(bf.occluded(ray)) << "tmin 7.01, the last sphere's far side at t = 7";
  ray.o = glm::vec3(50, 0, 0);  // beside everything
  ray.tmin = 0.0f;
  EXPECT_FALSE(bf.occluded(ray));
}

// The error box around every sphere hit point contains a point of the exact sphere (long double).
TEST(sphere, hit_error_bounds_contain_the_exact_surface) {
  test::expect_hit_error_bounds_contain_the_exact_surface(true);
}

// A sphere's normal points out, whichever side the ray comes from.
TEST(sphere, normal_points_out_from_inside_too) {
  Scene sp;
  sp.spheres.push_back(Sphere{glm::vec3(0, 0, -5), 2.0f, 0});
  Ray inside;
  inside.o = glm::vec3(0, 0, -5);
  inside.d = glm::vec3(0, 1, 0);
  SurfaceHit hit;
  ASSERT_TRUE(intersect_primitive(sp, 0, inside, &hit)) << "a ray from the centre must hit";
  EXPECT_NEAR(glm::length(hit.n - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(hit.p - glm::vec3(0, 2, -5)), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace pt
