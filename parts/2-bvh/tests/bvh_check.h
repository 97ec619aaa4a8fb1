// Test helpers of Part 2: random rays for a scene, and a BVH checked against brute force on them.
#pragma once

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/common.hpp>
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include "framework/math/float_error.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "framework/testing/probe_mode.h"
#include "framework/scene/collada_loader.h"
#include "parts/2-bvh/bvh.h"
#include "pipeline/1-raygen/scene_intersect.h"

namespace pt {
namespace test {

inline bool file_exists(const std::string& path) { return std::ifstream(path).good(); }

/// A random point of primitive `p`: uniform in a triangle, or on a sphere.
inline glm::vec3 point_on(const Scene& s, uint32_t p, Rng& rng) {
  if (s.is_triangle(p)) {
    const Triangle& t = s.triangles[p];
    float a = rng.next_float(), b = rng.next_float();
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    return s.positions[t.v[0]] + a * (s.positions[t.v[1]] - s.positions[t.v[0]]) +
           b * (s.positions[t.v[2]] - s.positions[t.v[0]]);
  }
  const Sphere& sp = s.spheres[p - s.triangles.size()];
  return sp.center + sp.radius * square_to_uniform_sphere(rng.next_2d());
}

/// `count` seeded rays for scene `s`, from points of its bounds (grown by a tenth) in a mix that
/// finds the hard cases: uniform directions (many misses); aimed at random points of random
/// primitives (hits); aimed exactly at triangle corners and edge midpoints (where neighbours
/// tie); and a fifth of them with a finite tmax or tmin > 0, so the interval matters.
inline std::vector<Ray> random_rays(const Scene& s, size_t count, uint64_t seed) {
  std::vector<Ray> rays(count);
  Bounds3 b = s.bounds();
  if (b.empty()) b = Bounds3{glm::vec3(-1.0f), glm::vec3(1.0f)};
  const glm::vec3 grow = 0.1f * glm::max(b.extent(), glm::vec3(1e-3f));
  const glm::vec3 lo = b.lo - grow, hi = b.hi + grow;
  const uint32_t n = s.primitive_count();
  Rng rng(seed, 7);
  for (size_t i = 0; i < count; ++i) {
    Ray& r = rays[i];
    r.o = lo + glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) * (hi - lo);
    const uint32_t kind = rng.next_u32() % 10;
    glm::vec3 target;
    if (n == 0 || kind < 3) {
      r.d = square_to_uniform_sphere(rng.next_2d());
    } else {
      const uint32_t p = rng.next_u32() % n;
      if (kind < 8 || !s.is_triangle(p)) {
        target = point_on(s, p, rng);
      } else {
        const Triangle& t = s.triangles[p];
        const uint32_t k = rng.next_u32() % 3;
        target = kind == 8 ? s.positions[t.v[k]]
                           : 0.5f * (s.positions[t.v[k]] + s.positions[t.v[(k + 1) % 3]]);
      }
      const glm::vec3 d = target - r.o;
      if (!(glm::dot(d, d) > 0.0f)) {
        r.d = glm::vec3(0, 0, 1);
      } else {
        r.d = glm::normalize(d);
      }
    }
    const uint32_t interval = rng.next_u32() % 10;
    if (interval == 0) r.tmax = rng.next_float() * 2.0f * glm::length(hi - lo);
    if (interval == 1) r.tmin = rng.next_float() * glm::length(hi - lo);
  }
  return rays;
}

/// What a comparison found: how many rays, how many disagreements, and the first few, described.
struct Comparison {
  size_t rays = 0, hits = 0, nearest_differ = 0, occluded_differ = 0, anyhit_vs_nearest = 0;
  size_t part1_differ = 0, part1_not_ulp_tie = 0;
  size_t outside_own_box = 0;  ///< disagreements over a Part 1 hit outside its primitive's box
  std::string examples;
};

/// Whether a hit (on primitive hit.primitive, at hit.t along `r`) lies outside that primitive's
/// bounding box by more than the rounding of the point itself (8 float ulps of its size): Part
/// 1's answer, valid for Part 1 (a Möller–Trumbore test's hits may stray so), but one no box
/// test needs to find. A BVH that misses such a hit is not wrong.
inline bool outside_own_box(const Scene& s, const Ray& r, const SurfaceHit& hit) {
  const Bounds3 b = s.primitive_bounds(hit.primitive);
  const glm::dvec3 p = glm::dvec3(r.o) + double(hit.t) * glm::dvec3(r.d);
  for (int i = 0; i < 3; ++i) {
    const double size = std::max({std::abs(p[i]), std::abs(double(b.lo[i])),
                                  std::abs(double(b.hi[i])), 1e-30});
    const double slack = 8.0 * 0x1p-24 * size;
    if (p[i] < double(b.lo[i]) - slack || p[i] > double(b.hi[i]) + slack) return true;
  }
  return false;
}

inline std::string describe(const Ray& r) {
  std::ostringstream os;
  os.precision(9);
  os << "o=(" << r.o.x << "," << r.o.y << "," << r.o.z << ") d=(" << r.d.x << "," << r.d.y << ","
     << r.d.z << ") t in (" << r.tmin << "," << r.tmax << ")";
  return os.str();
}

/// Brute force over every primitive, each judged on its own against the ray's interval: the
/// smallest reported t, the lower index on a tie. (Part 1's BruteForce shrinks tmax as it goes,
/// which can make it keep a hit an ulp farther than a later one; see compare_with_brute_force.)
/// To keep 100,000 rays over 30,000 triangles to seconds, a primitive is skipped when the part
/// of the ray inside its interval stays outside a ball around the primitive (its box's bounding
/// ball, grown by a part in 10^4), measured in double precision: a cull of another shape than a
/// BVH's box test, and one that cannot miss a point of the primitive.
class Reference {
 public:
  explicit Reference(const Scene& s) : s_(s) {
    for (uint32_t i = 0, n = s.primitive_count(); i < n; ++i) {
      const Bounds3 b = s.primitive_bounds(i);
      const glm::dvec3 lo(b.lo), hi(b.hi);
      const double scale = std::max(glm::length(lo), glm::length(hi));
      centre_.push_back(0.5 * (lo + hi));
      radius_.push_back(0.5 * glm::length(hi - lo) * (1 + 1e-4) + 1e-6 * scale + 1e-30);
    }
  }
  bool intersect(const Ray& r, SurfaceHit* best) const {
    bool found = false;
    for (uint32_t i = 0, n = s_.primitive_count(); i < n; ++i) {
      SurfaceHit h;
      if (may_hit(i, r) && intersect_primitive(s_, i, r, &h) && (!found || h.t < best->t))
        *best = h, found = true;
    }
    return found;
  }
  bool occluded(const Ray& r) const {
    for (uint32_t i = 0, n = s_.primitive_count(); i < n; ++i)
      if (may_hit(i, r) && primitive_occludes(s_, i, r)) return true;
    return false;
  }

 private:
  // The point of the ray's interval nearest the ball's centre is within the radius.
  bool may_hit(uint32_t i, const Ray& r) const {
    const glm::dvec3 o(r.o), d(r.d), to_centre = centre_[i] - o;
    const double dd = glm::dot(d, d);
    if (!(dd > 0.0)) return true;
    const double lo = double(r.tmin) * (1 - 1e-6) - 1e-30;
    const double hi = double(r.tmax) * (1 + 1e-6) + 1e-30;
    const double t = std::min(std::max(glm::dot(to_centre, d) / dd, lo), hi);
    const glm::dvec3 gap = to_centre - t * d;
    return glm::dot(gap, gap) <= radius_[i] * radius_[i];
  }
  const Scene& s_;
  std::vector<glm::dvec3> centre_;
  std::vector<double> radius_;
};

/// Brute force's answers for one ray: the nearest hit and occlusion of nearest_reference's scan,
/// and Part 1's BruteForce's own (a full pass over the primitives, so asked of one ray in eight,
/// one in 64 on big meshes; elsewhere they repeat the reference's).
struct BruteForceAnswer {
  SurfaceHit nearest, part1;
  bool hit = false, occluded = false, part1_hit = false, part1_occluded = false;
};

/// Brute force's answers for `rays` in `s`, computed once for every tree compared with them. In a
/// probe none (probe_mode.h): the judge computes them itself.
inline std::vector<BruteForceAnswer> brute_force_answers(const Scene& s,
                                                       const std::vector<Ray>& rays) {
  std::vector<BruteForceAnswer> answers;
  if (is_probe()) return answers;
  answers.resize(rays.size());
  const BruteForce bf(s);
  const Reference ref(s);
  const size_t every = s.primitive_count() > 10000 ? 64 : 8;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256),
                    [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i < range.end(); ++i) {
      BruteForceAnswer& a = answers[i];
      a.hit = ref.intersect(rays[i], &a.nearest);
      a.occluded = ref.occluded(rays[i]);
      if (i % every == 0) {
        a.part1_hit = bf.intersect(rays[i], &a.part1);
        a.part1_occluded = bf.occluded(rays[i]);
      } else {
        a.part1_hit = a.hit, a.part1 = a.nearest, a.part1_occluded = a.occluded;
      }
    }
  });
  return answers;
}

/// Every ray through `bvh` and through brute force (`answers`, brute_force_answers of the same
/// rays): the same hit or miss, bit-identical t and the same primitive as nearest_reference;
/// occluded() equal to brute force's and to whether intersect() found a hit. Part 1's
/// BruteForce::intersect is compared too: where it differs, it must be by a near-tie (its t
/// within 4 ulps above the BVH's). In a probe (no answers) only the tree is asked, in the same
/// order as in the judge.
inline Comparison compare_with_brute_force(const Scene& s, const RayQuery& bvh,
                                           const std::vector<Ray>& rays,
                                           const std::vector<BruteForceAnswer>& answers) {
  const bool probe = answers.empty() && !rays.empty();
  if (!probe && answers.size() != rays.size())
    throw std::logic_error("compare_with_brute_force: answers of other rays");
  std::atomic<size_t> hits{0}, nearest{0}, occl{0}, any_vs{0}, p1{0}, p1_far{0}, stray{0};
  std::mutex m;
  std::string examples;
  int shown = 0;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256),
                    [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i < range.end(); ++i) {
      const Ray& r = rays[i];
      SurfaceHit a;
      const bool ha = bvh.intersect(r, &a);
      const bool oa = bvh.occluded(r);
      if (probe) continue;
      const BruteForceAnswer& want = answers[i];
      const SurfaceHit &b = want.nearest, &c = want.part1;
      const bool hb = want.hit, ob = want.occluded, hc = want.part1_hit;
      std::string why;
      if (want.part1_occluded != ob) ++occl, why += " Part 1 BruteForce::occluded differs";
      if (hb) ++hits;
      // The BVH missed (or passed) a brute-force hit that lies outside its own primitive's box:
      // Part 1's rounding, not the tree's (see outside_own_box); the BVH's answer then stands.
      const bool bvh_missed = hb && (!ha || b.t < a.t || (b.t == a.t && b.primitive < a.primitive));
      if (bvh_missed && outside_own_box(s, r, b)) {
        ++stray;
        continue;
      }
      if (ha != hb || (ha && (a.t != b.t || a.primitive != b.primitive))) {
        ++nearest;
        std::ostringstream os;
        os.precision(9);
        os << "nearest: bvh " << (ha ? std::to_string(a.primitive) : "miss") << " t=" << a.t
           << ", brute force " << (hb ? std::to_string(b.primitive) : "miss") << " t=" << b.t;
        why = os.str();
      }
      if (hc != hb || (hc && (c.t != b.t || c.primitive != b.primitive))) {
        ++p1;
        const bool tie = hc && hb && c.t >= b.t &&
                         float_to_bits(c.t) - float_to_bits(b.t) <= 4u;
        if (!tie) ++p1_far, why += " Part 1 BruteForce: t=" + std::to_string(c.t);
      }
      if (oa != ob) ++occl, why += " occluded: bvh " + std::to_string(oa) + " brute " + std::to_string(ob);
      if (oa != ha) ++any_vs, why += " any-hit " + std::to_string(oa) + " vs nearest " + std::to_string(ha);
      if (!why.empty()) {
        std::lock_guard<std::mutex> lock(m);
        if (shown++ < 5) examples += "\n  ray " + std::to_string(i) + " " + describe(r) + ": " + why;
      }
    }
  });
  return {rays.size(), hits, nearest, occl, any_vs, p1, p1_far, stray, examples};
}

/// The same, brute force's answers computed for this one tree.
inline Comparison compare_with_brute_force(const Scene& s, const RayQuery& bvh,
                                           const std::vector<Ray>& rays) {
  return compare_with_brute_force(s, bvh, rays, brute_force_answers(s, rays));
}

/// Loads a scene, or explains why not in *why (so the caller can skip).
inline bool try_load(const std::string& path, Scene* scene, std::string* why) {
  if (!file_exists(path)) {
    *why = path + " is not there";
    return false;
  }
  *scene = load_collada(path, [](const std::string&) {});
  return true;
}

/// One brute-force comparison: a scene file, a split method and a leaf size, checked by
/// check_against_brute_force (shared by the regular and the stress suites).
constexpr size_t kRays = 100000;

/// A scene, a split method and a leaf size to check.
struct Case {
  std::string path;  ///< relative to the project's scenes/ or the course's scene folder
  BvhSplitMethod split;
  int leaf;
  size_t rays;
};

inline void PrintTo(const Case& c, std::ostream* os) {
  *os << c.path << (c.split == BvhSplitMethod::sah ? " sah" : " median") << " leaf " << c.leaf;
}

inline std::string case_name(const testing::TestParamInfo<Case>& info) {
  std::string name = info.param.path;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name + (info.param.split == BvhSplitMethod::sah ? "_sah" : "_median") + "_leaf" +
         std::to_string(info.param.leaf);
}

inline void check_against_brute_force(const Scene& scene, const Case& c) {
  BvhOptions options;
  options.split = c.split;
  options.max_leaf_size = c.leaf;
  const Bvh bvh(scene, options);
  const std::vector<Ray> rays = test::random_rays(scene, c.rays, 2024);
  const test::Comparison r = test::compare_with_brute_force(scene, bvh, rays);
  // The rays must exercise both answers, or agreement would say little.
  EXPECT_GT(r.hits, r.rays / 10) << "too few hits to be a test";
  EXPECT_LT(r.hits, r.rays) << "no misses at all";
  EXPECT_EQ(r.nearest_differ, 0u) << r.examples;
  EXPECT_EQ(r.occluded_differ, 0u) << r.examples;
  EXPECT_EQ(r.anyhit_vs_nearest, 0u) << r.examples;
  EXPECT_EQ(r.part1_not_ulp_tie, 0u) << r.examples;
  if (r.part1_differ > 0)
    std::printf("note: Part 1's BruteForce kept an ulp-farther tie on %zu of %zu rays\n",
                r.part1_differ, r.rays);
  if (r.outside_own_box > 0)
    std::printf("note: on %zu of %zu rays Part 1's nearest hit lies outside its primitive's box "
                "(not compared: no box test needs to find it)\n",
                r.outside_own_box, r.rays);
}

}  // namespace test
}  // namespace pt
