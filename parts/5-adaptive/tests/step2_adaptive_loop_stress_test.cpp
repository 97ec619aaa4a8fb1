// Part 5, step 2 (adaptive_loop) under the stopping rule the assignment does not ask for: not
// graded (label stress), so that the instructor's CI keeps the other rule's checks, and the
// complete solution under that rule, working for the day the manifest switches rules.
#include <gtest/gtest.h>

#include "parts/5-adaptive/tests/adaptive_loop_checks.h"

namespace pt {
namespace {

using namespace test::adaptive_loop;
constexpr StoppingRule kOtherRule =
    kAssignmentStoppingRule == StoppingRule::course ? StoppingRule::split : StoppingRule::course;

TEST(adaptive_loop_other_rule, stops_at_the_first_batch_where_the_rule_holds) {
  stops_at_the_first_batch_where_the_rule_holds(kOtherRule);
}

TEST(adaptive_loop_other_rule, never_more_than_the_maximum) {
  never_more_than_the_maximum(kOtherRule);
}

TEST(adaptive_loop_other_rule, constant_pixel_stops_after_one_batch) {
  constant_pixel_stops_after_one_batch(kOtherRule);
}

TEST(adaptive_loop_other_rule, constant_scene_stops_every_pixel_after_the_first_batch) {
  constant_scene_stops_every_pixel_after_the_first_batch(kOtherRule);
}

TEST(adaptive_loop_other_rule, sample_rate_image_shows_the_samples_taken) {
  sample_rate_image_shows_the_samples_taken(kOtherRule);
}

TEST(adaptive_loop_other_rule, heavy_tailed_image_is_what_the_rule_is_for) {
  if (kOtherRule == StoppingRule::course)
    heavy_tailed_image_is_what_the_course_rule_gives();
  else
    heavy_tailed_image_matches_the_non_adaptive_one();
}

}  // namespace
}  // namespace pt
