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
/// mistakes of that `kind` of render (the manifest's: normals, direct, hemisphere, path,
/// adaptive; a normals image gets geometry hints, never lighting advice) and writes a diff image
/// to `diff_path` (when not empty) that the message names.
Comparison compare_render(const RenderEstimate& render, const RenderEstimate& reference,
                          const BlockTestOptions& options, const std::string& kind,
                          const std::string& diff_path);

/// The render's mean per-sample variance over its pixels (all channels) divided by the
/// reference's: about 1 when both were made with the same estimator and settings, whatever their
/// sample counts. NaN when the reference has no variance.
double noise_ratio(const RenderEstimate& render, const RenderEstimate& reference);

/// The noise check of a render whose per-sample variance must match its reference's (the
/// manifest's `noise`): "" when the ratio is within [1/limit, limit], else what it means (a render
/// noisier than the reference at the same settings takes fewer samples than it is asked for:
/// -l ignored; a smoother one takes more).
std::string check_noise(const RenderEstimate& render, const RenderEstimate& reference, double limit);

/// What a failing pattern of block ratios suggests for that kind of render, or "" when nothing
/// known fits.
std::string diagnose(const BlockTestResult& result, const std::string& kind = "direct");

/// Writes a PNG: grey where the render matches, red where it is too bright, blue where too
/// dark (full colour at a 50% difference), the failing blocks outlined in yellow.
void write_diff_image(const std::string& path, const RenderEstimate& render,
                      const RenderEstimate& reference, const BlockTestResult& result,
                      int block_size);

}  // namespace pt::grader
