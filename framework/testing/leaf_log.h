// Not needed for the assignment.
// The leaves a BVH walk tested, in order, as the given leaf tests saw them (Bvh::log_leaf_tests):
// the traversal tests hold a walk to what it must open and what it must not. In a grader's judge
// the leaf tests are the judge's own, run again from the probe's record, so the judge counts the
// work itself and a walk cannot claim less than it did (grader/judge/record.h).
#pragma once

#include <cstdint>
#include <vector>

namespace pt::test {

/// One leaf test: which node, and the far end of the ray it was tested with (for a nearest-hit
/// walk, the culling bound: the best hit found so far).
struct LeafTest {
  uint32_t node = 0;
  float tmax = 0.0f;
};

struct LeafLog {
  std::vector<LeafTest> tests;
  uint64_t primitives = 0;  ///< every primitive the leaf tests tested
};

/// One more leaf test: node `node`, of `count` primitives, tested with a ray ending at `tmax`.
void note_leaf_test(LeafLog* log, uint32_t node, uint32_t count, float tmax);

}  // namespace pt::test
