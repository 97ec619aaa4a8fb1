// Part 5's stopping rules: which of an adaptive pixel's samples decide when it stops and which
// form its value, and the rule this assignment asks for.
#pragma once

#include <optional>
#include <string_view>

// Set by CMake for every target from the grading manifest (reference/manifest.json's
// stopping_rule, or -DPT_STOPPING_RULE), so that one build holds one assignment's rule.
#ifndef PT_COURSE_STOPPING_RULE
#define PT_COURSE_STOPPING_RULE 0
#endif

namespace pt {

/// One sample in kDecisionStride of a pixel decides under the split rule: the last of each stride.
constexpr int kDecisionStride = 4;

/// Which of a pixel's samples decide when to stop and which form its value.
enum class StoppingRule {
  /// One sample in kDecisionStride only decides, the others only count. When to stop then
  /// depends on samples the value never sees, so the value is unbiased whatever the pixel's
  /// distribution; a quarter of the samples is the price.
  split,
  /// Every sample decides and counts (the course's own rule, 1.96·σ/√n ≤ tol·μ over the pixel's
  /// samples). A pixel whose samples happened to miss its rare bright values looks converged
  /// and stops too dark: slightly biased.
  course,
};

/// The rule this assignment asks for: a render's default, and the one its tests hold Part 5 to.
constexpr StoppingRule kAssignmentStoppingRule =
    PT_COURSE_STOPPING_RULE ? StoppingRule::course : StoppingRule::split;

/// Whether the pixel's `index`-th sample (from 0) goes into the statistics that decide when to
/// stop.
constexpr bool sample_decides(StoppingRule rule, long index) {
  return rule == StoppingRule::course || index % kDecisionStride == kDecisionStride - 1;
}

/// Whether the pixel's `index`-th sample (from 0) goes into the pixel's value.
constexpr bool sample_counts(StoppingRule rule, long index) {
  return rule == StoppingRule::course || index % kDecisionStride != kDecisionStride - 1;
}

/// "split" or "course".
constexpr const char* stopping_rule_name(StoppingRule rule) {
  return rule == StoppingRule::course ? "course" : "split";
}

/// The rule of that name; nothing for any other text.
inline std::optional<StoppingRule> parse_stopping_rule(std::string_view name) {
  if (name == "split") return StoppingRule::split;
  if (name == "course") return StoppingRule::course;
  return std::nullopt;
}

}  // namespace pt
