// Part 5, step 1 (convergence): the stopping rule on hand-computed cases.
#include <gtest/gtest.h>

#include "parts/5-adaptive/adaptive_sampling.h"

namespace pt {
namespace {

TEST(convergence, rule_on_hand_computed_cases) {
  IlluminanceStats s;
  for (double x : {1.0, 3.0}) s.add(x);  // μ = 2, σ² = 2
  // Two estimate samples: I = 1.96·√(2/2) = 1.96 against tolerance·2.
  EXPECT_TRUE(pixel_converged(s, 2, 0.98f + 1e-6f));
  EXPECT_FALSE(pixel_converged(s, 2, 0.97f));
  // Eight estimate samples: the half-width is the estimate's, I = 1.96·√(2/8) = 0.98.
  EXPECT_TRUE(pixel_converged(s, 8, 0.49f + 1e-6f));
  EXPECT_FALSE(pixel_converged(s, 8, 0.48f));
  EXPECT_FALSE(pixel_converged(s, 0, 1000.0f)) << "no estimate sample, nothing to report";
  IlluminanceStats one;
  one.add(5.0);
  EXPECT_FALSE(pixel_converged(one, 10, 1.0f)) << "one sample says nothing about the variance";
}

}  // namespace
}  // namespace pt
