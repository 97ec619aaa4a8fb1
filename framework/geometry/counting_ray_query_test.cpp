// Not needed for the assignment.
// CountingRayQuery: every query is forwarded unchanged and counted once, on whichever thread.
#include "framework/geometry/counting_ray_query.h"

#include <atomic>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

namespace pt {
namespace {

/// Answers by the sign of the direction's x, and remembers how often it was asked.
class SignQuery final : public RayQuery {
 public:
  bool intersect(const Ray& ray, SurfaceHit* hit) const override {
    ++calls;
    hit->t = 2.0f;
    return ray.d.x > 0.0f;
  }
  bool occluded(const Ray& ray) const override {
    ++calls;
    return ray.d.x < 0.0f;
  }
  mutable std::atomic<uint64_t> calls{0};
};

Ray ray_along_x(float x) {
  Ray r;
  r.o = glm::vec3(0.0f);
  r.d = glm::vec3(x, 0.0f, 1.0f);
  return r;
}

TEST(CountingRayQuery, ForwardsAnswersUnchanged) {
  SignQuery inner;
  CountingRayQuery counting(inner);
  SurfaceHit hit;
  EXPECT_TRUE(counting.intersect(ray_along_x(1.0f), &hit));
  EXPECT_EQ(hit.t, 2.0f);
  EXPECT_FALSE(counting.intersect(ray_along_x(-1.0f), &hit));
  EXPECT_TRUE(counting.occluded(ray_along_x(-1.0f)));
  EXPECT_FALSE(counting.occluded(ray_along_x(1.0f)));
  EXPECT_EQ(counting.total(), 4u);
  EXPECT_EQ(counting.thread_count(), 4u);
}

TEST(CountingRayQuery, CountsEveryQueryAcrossThreads) {
  SignQuery inner;
  CountingRayQuery counting(inner);
  constexpr int kRays = 100000;
  // Each task checks that its own thread's count rose by exactly the rays it traced.
  std::atomic<int> mismatches{0};
  tbb::parallel_for(0, kRays / 100, [&](int chunk) {
    const uint64_t before = counting.thread_count();
    SurfaceHit hit;
    for (int i = 0; i < 100; ++i) {
      const float x = float((chunk * 100 + i) % 3) - 1.0f;
      if (i % 2) counting.occluded(ray_along_x(x));
      else counting.intersect(ray_along_x(x), &hit);
    }
    if (counting.thread_count() - before != 100) ++mismatches;
  });
  EXPECT_EQ(mismatches.load(), 0);
  EXPECT_EQ(counting.total(), uint64_t(kRays));
  EXPECT_EQ(inner.calls.load(), uint64_t(kRays));
}

}  // namespace
}  // namespace pt
