// Not needed for the assignment.
// The rule every estimator handed an Rng states: rng is its only source of random numbers. Then
// the same inputs and an Rng in the same state give the same answer, to the bit, and leave the
// Rng in the same state; the same seed gives the same image, and a tile or one pixel re-rendered
// (the viewer's inspector) gives what the whole render gave. A generator of its own (std::rand,
// a static engine) or anything kept from an earlier call breaks it, however right the mean.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "framework/sampling/rng.h"

namespace pt::test {

/// Calls `estimate` twice for each seed 1..`seeds`, each time with a new Rng of that seed, and
/// expects the two answers equal to the bit and both Rngs left in the same state. `name` is the
/// graded function's. The inputs must make the answer depend on the numbers drawn (a lit point):
/// the test fails when every answer is zero, since it could then tell nothing.
inline void expect_draws_from_rng_only(const std::string& name,
                                       const std::function<glm::vec3(Rng&)>& estimate,
                                       int seeds = 8) {
  bool any_light = false;
  for (uint64_t seed = 1; seed <= uint64_t(seeds); ++seed) {
    Rng a(seed), b(seed);
    const glm::vec3 first = estimate(a);
    const glm::vec3 second = estimate(b);
    any_light = any_light || first != glm::vec3(0.0f);
    if (std::memcmp(&first, &second, sizeof first) != 0) {
      std::ostringstream os;
      os.precision(9);
      os << name << " gave (" << first.x << ", " << first.y << ", " << first.z << ") and then ("
         << second.x << ", " << second.y << ", " << second.z
         << ") for the same inputs and an Rng of the same seed (" << seed
         << "): rng must be its only source of random numbers (no generator of its own, no "
            "std::rand, nothing kept from an earlier call)";
      ADD_FAILURE() << os.str();
      return;
    }
    if (a.next_u32() != b.next_u32()) {
      ADD_FAILURE() << name << " left the Rng in two different states after two calls with the "
                    << "same inputs and an Rng of the same seed (" << seed
                    << "): it drew from rng a different number of times, so something else "
                       "decides its draws (a generator of its own, or state kept between calls)";
      return;
    }
  }
  EXPECT_TRUE(any_light) << name << " returned 0 at a lit point for every seed, so whether it "
                                    "draws from rng alone cannot be told (is it written yet?)";
}

}  // namespace pt::test
