// The student's values in the grader's words: how many of them, and how many characters each, the
// results may quote (docs/grading.md, "What reaches the student"). A judge writes its failure in
// its own words, but the numbers in them are the student's answers (or were computed from them),
// and so are a probe's exit status and a render's statistics: each is a channel out of the
// grader. Each such number is marked where the grader takes the text in, printed again in a
// bounded form, and released into the results only while the submission's budget lasts.
#pragma once

#include <string>

namespace pt::grader {

/// A value is printed with this many significant digits (an integer below 10^6 exactly), so that
/// it is at most kValueChars characters ("-1.235e-308").
constexpr int kValueDigits = 4;
constexpr int kValueChars = 11;
/// The values one step's message may quote (its first failing check's), and one results file.
constexpr int kValuesPerStep = 6;
constexpr int kValuesPerResults = 20;

/// `text` (a judge's failure, a render's comparison, a process's ending) with every number in it
/// marked as a student value and printed in at most kValueChars characters, a byte dump or a
/// character GoogleTest quotes masked, and any marker the text held already removed. Digits
/// inside a word ("part1.step3"), one or two glued to the word after them ("1-raygen") and the
/// line of a test's source ("x_test.cpp:45") are the grader's own and left as they are; every
/// other run of digits is a value.
std::string mark_values(const std::string& text);

/// `text` with its first `*left` marked values (at most `per_text`) shown and the rest replaced by
/// "…"; `*left` goes down by the number shown. A null `left` shows every value (a developer's tool
/// that prints nothing to a student).
std::string release_values(const std::string& text, int* left, int per_text = kValuesPerStep);

/// How many marked values `text` holds.
int marked_values(const std::string& text);

}  // namespace pt::grader
