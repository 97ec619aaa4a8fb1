// Part 5, step 2 (adaptive_loop), graded under the assignment's stopping rule (the checks are in
// adaptive_loop_checks.h; step2_adaptive_loop_stress_test.cpp runs them under the other rule).
#include <gtest/gtest.h>

#include "parts/5-adaptive/tests/adaptive_loop_checks.h"

namespace pt {
namespace {

using namespace test::adaptive_loop;
constexpr StoppingRule kRule = kAssignmentStoppingRule;

TEST(adaptive_loop, stops_at_the_first_batch_where_the_rule_holds) {
  stops_at_the_first_batch_where_the_rule_holds(kRule);
}

TEST(adaptive_loop, never_more_than_the_maximum) { never_more_than_the_maximum(kRule); }

TEST(adaptive_loop, constant_pixel_stops_after_one_batch) {
  constant_pixel_stops_after_one_batch(kRule);
}

TEST(adaptive_loop, constant_scene_stops_every_pixel_after_the_first_batch) {
  constant_scene_stops_every_pixel_after_the_first_batch(kRule);
}

TEST(adaptive_loop, sample_rate_image_shows_the_samples_taken) {
  sample_rate_image_shows_the_samples_taken(kRule);
}

// The heavy-tailed pixel tells the rules apart; each assignment is held to what its rule is for.
#if PT_COURSE_STOPPING_RULE
TEST(adaptive_loop, heavy_tailed_image_is_what_the_course_rule_gives) {
  heavy_tailed_image_is_what_the_course_rule_gives();
}
#else
TEST(adaptive_loop, heavy_tailed_image_matches_the_non_adaptive_one) {
  heavy_tailed_image_matches_the_non_adaptive_one();
}
#endif

}  // namespace
}  // namespace pt
