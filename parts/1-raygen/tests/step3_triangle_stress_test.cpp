// SOLUTION-ONLY FILE: not in the student handout (its control is a float Möller–Trumbore test,
// a working answer to step 3); the instructor's CI runs it, it is not a graded check.
// Part 1 stress test: a million rays aimed exactly at shared edges and vertices of closed meshes
// never leak (watertight_rays.h says how they are aimed), and the control that shows such rays
// find the cracks of a test that is not watertight. The graded watertight step
// (step5_watertight_test.cpp) shoots the same kind of rays, fewer of them.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "parts/1-raygen/tests/watertight_rays.h"

namespace pt {
namespace {

using namespace pt::test;

TEST(triangle, watertight_shared_edges_and_vertices) {
  const auto start = std::chrono::steady_clock::now();
  const Count total = shoot_all(45000, intersect_triangle);
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("watertight: %ld rays at shared edges and vertices, %ld leaks (%.2f s)\n",
              total.rays, total.leaks, secs);
  EXPECT_GE(total.rays, 1000000);
  EXPECT_EQ(total.leaks, 0);
}

/// The textbook Moller-Trumbore test, in float, with its edge tests b >= 0 done on values that
/// each triangle computes differently: the kind of test the one above must catch leaking.
bool moller_trumbore(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                     const glm::vec3& p2, TriangleHit* hit) {
  const glm::vec3 e1 = p1 - p0, e2 = p2 - p0, pv = glm::cross(ray.d, e2);
  const float det = glm::dot(e1, pv);
  if (det == 0.0f) return false;
  const float inv = 1.0f / det;
  const glm::vec3 tv = ray.o - p0;
  const float b1 = glm::dot(tv, pv) * inv;
  if (b1 < 0.0f || b1 > 1.0f) return false;
  const glm::vec3 qv = glm::cross(tv, e1);
  const float b2 = glm::dot(ray.d, qv) * inv;
  if (b2 < 0.0f || b1 + b2 > 1.0f) return false;
  const float t = glm::dot(e2, qv) * inv;
  if (!(t > ray.tmin && t < ray.tmax)) return false;
  *hit = TriangleHit{t, 1.0f - b1 - b2, b1, b2};
  return true;
}

// The control: the same rays leak through a test that is not watertight, so the zero above
// means something.
TEST(triangle, no_leak_where_a_non_watertight_test_leaks) {
  // The control shows these rays find cracks (so the zero leaks above mean something); the
  // student's test must close every one of them on the very same rays.
  Count control = shoot(icosphere(4), Placement{10.0f, 1e5f}, 200000, 99, moller_trumbore, false);
  std::printf("control (Moller-Trumbore): %ld rays, %ld leaks\n", control.rays, control.leaks);
  EXPECT_GT(control.leaks, 0);
  Count yours = shoot(icosphere(4), Placement{10.0f, 1e5f}, 200000, 99, intersect_triangle, false);
  std::printf("intersect_triangle: %ld rays, %ld leaks\n", yours.rays, yours.leaks);
  EXPECT_EQ(yours.rays, control.rays);
  EXPECT_EQ(yours.leaks, 0);
}

}  // namespace
}  // namespace pt
