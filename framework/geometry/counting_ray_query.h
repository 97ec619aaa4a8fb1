// Not needed for the assignment.
// Counts the rays a renderer asks of a RayQuery, so its summary's rays/s covers every ray.
#pragma once

#include <cstdint>

#include <tbb/enumerable_thread_specific.h>

#include "framework/geometry/ray_query.h"

namespace pt {

/// A RayQuery that forwards every query to another and counts it: camera, shadow and bounce rays
/// alike, since lighting code only ever traces through the query it was given. Each thread counts
/// into its own slot, so counting costs an increment, not a contended cache line.
class CountingRayQuery final : public RayQuery {
 public:
  explicit CountingRayQuery(const RayQuery& inner) : inner_(inner) {}

  bool intersect(const Ray& ray, SurfaceHit* hit) const override {
    ++counts_.local();
    return inner_.intersect(ray, hit);
  }
  bool occluded(const Ray& ray) const override {
    ++counts_.local();
    return inner_.occluded(ray);
  }

  /// The calling thread's running count: read it before and after some work to learn how many
  /// rays that work traced on this thread.
  uint64_t thread_count() const { return counts_.local(); }

  /// Every thread's count, summed; call it when no query is in flight.
  uint64_t total() const {
    uint64_t sum = 0;
    for (uint64_t c : counts_) sum += c;
    return sum;
  }

 private:
  const RayQuery& inner_;
  // One TLS key for this instance: local() is then a thread-local lookup, not a hash of the
  // thread id, which matters at one call per ray.
  mutable tbb::enumerable_thread_specific<uint64_t, tbb::cache_aligned_allocator<uint64_t>,
                                          tbb::ets_key_per_instance>
      counts_{0};
};

/// A RayQuery that forwards every query to a query of type Inner and counts it in a plain
/// counter: one thread's, for as long as one piece of work (a camera sample's path) lasts, made
/// on the stack around it. Counting is then an increment, with no thread-local lookup, and where
/// Inner is a final class its calls are direct ones, not a second virtual call per ray.
template <class Inner>
class LocalCountingRayQuery final : public RayQuery {
 public:
  explicit LocalCountingRayQuery(const Inner& inner) : inner_(inner) {}

  bool intersect(const Ray& ray, SurfaceHit* hit) const override {
    ++count_;
    ++intersect_count_;
    return inner_.intersect(ray, hit);
  }
  bool occluded(const Ray& ray) const override {
    ++count_;
    return inner_.occluded(ray);
  }

  /// The queries answered so far.
  uint64_t count() const { return count_; }
  /// Of those, the occlusion queries (shadow rays): counted as the rest, since they are nine in
  /// ten of a render's rays, and an increment more on each cost half a percent of its time.
  uint64_t occluded_count() const { return count_ - intersect_count_; }

 private:
  const Inner& inner_;
  mutable uint64_t count_ = 0, intersect_count_ = 0;
};

}  // namespace pt
