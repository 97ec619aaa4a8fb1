// What a BVH traversal is for, measured: the primitives its leaf tests test per ray, against
// what a good walk of the same tree needs. A walk that opens every leaf gives brute force's
// answers too, so answers alone cannot tell a traversal from a scan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/sampling/rng.h"
#include "framework/scene/scene.h"
#include "framework/testing/observed_counters.h"
#include "parts/2-bvh/bvh.h"
#include "parts/2-bvh/tests/bvh_test_inputs.h"

namespace pt::test {

/// Primitives tested per ray by a tree's two walks.
struct TraversalWork {
  double nearest = 0.0;   ///< per nearest-hit query (Bvh::intersect, the student's traverse_nearest)
  double occluded = 0.0;  ///< per occlusion query (Bvh::occluded)
};

/// 4,000 triangles (up to 1.5 across) scattered through a 10-unit cube: a ray crosses many boxes, and a walk
/// that goes nearest first and drops what lies beyond its best hit opens few of them.
inline Scene scattered_triangles() {
  Scene s;
  Rng rng(71);
  for (int i = 0; i < 4000; ++i) {
    const glm::vec3 p = 10.0f * glm::vec3(rng.next_float(), rng.next_float(), rng.next_float());
    const glm::vec3 a = 1.5f * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f);
    const glm::vec3 b = 1.5f * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f);
    add_triangle(&s, p, p + a, p + b);
  }
  return s;
}

/// Rays from outside the cube through it (nearest) and segments between two points inside it
/// (occlusion, as shadow rays are), `count` of each.
inline TraversalWork measure_work(const Bvh& tree_in, size_t count = 2000) {
  Bvh& tree = const_cast<Bvh&>(tree_in);
  uint64_t tested = 0;
  tree.count_primitive_tests(&tested);
  test::observe_counter(&tested);
  Rng rng(72);
  auto point = [&] { return 10.0f * glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()); };
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 from = glm::vec3(5.0f) + 12.0f * glm::normalize(point() - glm::vec3(5.0f) + glm::vec3(1e-3f));
    Ray r;
    r.o = from;
    r.d = glm::normalize(point() - from);
    SurfaceHit hit;
    tree.intersect(r, &hit);
  }
  TraversalWork w;
  w.nearest = double(tested) / double(count);
  tested = 0;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 a = point(), b = point();
    Ray r;
    r.o = a;
    r.d = glm::normalize(b - a);
    r.tmax = glm::length(b - a);
    tree.occluded(r);
  }
  w.occluded = double(tested) / double(count);
  tree.count_primitive_tests(nullptr);
  test::forget_counter(&tested);
  return w;
}

/// The most primitives per ray a traversal of the scattered triangles' SAH tree (leaves of 4)
/// may test: twice what the complete solution's walk tests (nearest 8.4, occlusion 7.9 per
/// ray). A walk that visits both children whatever the first one found, or that does not skip a
/// node the ray enters beyond its best hit, tests several times as many; a scan of every leaf
/// tests all 4,000.
inline constexpr double kMaxNearestWork = 2.0 * 8.4;
inline constexpr double kMaxOccludedWork = 2.0 * 7.9;

/// Fails (fatally, so a test calling it from SetUp does not run) unless both walks test at
/// most the bounds above: the answers a traversal gives count only when it is one.
inline void expect_a_traversal() {
  static const Scene scene = scattered_triangles();
  const Bvh tree(scene, BvhOptions{BvhSplitMethod::sah, 4, 16, {}});
  const TraversalWork w = measure_work(tree);
  ASSERT_LE(w.nearest, kMaxNearestWork)
      << "Bvh::traverse_nearest tests " << w.nearest << " primitives per ray of " << scene.triangles.size()
      << " scattered triangles, where a nearest-first walk needs about " << kMaxNearestWork / 2.0
      << ": does it open every leaf, visit both children whatever it found, or keep going into "
         "nodes the ray enters beyond its best hit (st.cull.tmax)?";
  ASSERT_LE(w.occluded, kMaxOccludedWork)
      << "Bvh::occluded tests " << w.occluded << " primitives per shadow ray, where a walk "
      << "that skips the boxes the ray misses needs about " << kMaxOccludedWork / 2.0
      << ": does it open every leaf, or not stop at the first occluder?";
}

}  // namespace pt::test
