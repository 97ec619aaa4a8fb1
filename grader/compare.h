// Compares a render with its reference and says, in a student's terms, what is off.
#pragma once

#include <string>

#include "framework/stats/block_ttest.h"

namespace pt::grader {

/// The verdict on one render: the block t-test's, plus a diagnosis and the diff image's path.
struct Comparison {
  bool pass = false;
  BlockTestResult test;
  std::string message;    ///< the t-test's summary, then what that pattern usually means
  std::string diff_path;  ///< empty when no diff image was written
};

/// Runs the block t-test; on a failure, matches the failing blocks' ratios against the usual
/// mistakes (a uniform factor of 2, π, 2π, a few percent; light missing only in places) and
/// writes a diff image to `diff_path` (when not empty) that the message names.
Comparison compare_render(const RenderEstimate& render, const RenderEstimate& reference,
                          const BlockTestOptions& options, const std::string& diff_path);

/// What a failing pattern of block ratios suggests, or "" when nothing known fits.
std::string diagnose(const BlockTestResult& result);

/// Writes a PNG: grey where the render matches, red where it is too bright, blue where too
/// dark (full colour at a 50% difference), the failing blocks outlined in yellow.
void write_diff_image(const std::string& path, const RenderEstimate& render,
                      const RenderEstimate& reference, const BlockTestResult& result,
                      int block_size);

}  // namespace pt::grader
