// Not needed for the assignment.
// Counters a test reads after it calls a graded function (the rig's ray counts, a tree's
// primitive tests). A test registers them while they live, so that the grader's probe can record
// how far a call moved them and its judge can move its own as far (grader/judge/record.h).
// Outside the grader the list is kept and never read.
#pragma once

#include <cstdint>
#include <vector>

namespace pt::test {

struct ObservedCounter {
  void* at;
  bool wide;  ///< a uint64_t; else a long
};

void observe_counter(long* counter);
void observe_counter(uint64_t* counter);
void forget_counter(const void* counter);
/// The live counters, in the order they were registered.
const std::vector<ObservedCounter>& observed_counters();

}  // namespace pt::test
