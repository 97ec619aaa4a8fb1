// Not needed for the assignment.
// Is a render's own noise plausible for its estimator? The block t-test divides a block's mean
// difference by the render's stated variance, so a render that overstates its variance (or
// understates its sample count) makes any bias look like noise. This check compares the
// render's variance channels with the reference's, which estimate the same per-sample variance
// when the estimator is the same, and its sample counts with the ones the grader asked for.
#pragma once

#include <string>

#include "framework/image/render_estimate.h"

namespace pt {

struct VarianceConsistencyOptions {
  int block_size = 16;
  /// A block fails when its mean per-sample variance is more than this many times the
  /// reference's (plus the floor below); measured on correct renders the largest ratio stays
  /// far below it (docs/grading.md gives the figures).
  double max_block_ratio = 16.0;
  /// The whole image fails when its mean variance is more than this many times the reference's.
  double max_image_ratio = 3.0;
  /// At most this fraction of blocks may fail (a few fireflies in a path-traced block).
  double max_failing_fraction = 0.02;
  /// The variance a block may have over a reference block of (near) zero variance, relative to
  /// the square of the reference block's mean: a normals image or a directly seen light.
  double relative_floor = 1e-3;
  /// The sample count every pixel must have (0: not checked); with `adaptive`, the most a pixel
  /// may have (an adaptive render stops pixels early, never late).
  int expected_count = 0;
  bool adaptive = false;
};

struct VarianceConsistencyResult {
  bool pass = false;
  int blocks = 0, failing_blocks = 0;
  double image_ratio = 1.0;       ///< mean variance of the render over the reference's
  double worst_block_ratio = 1.0;
  std::string summary;            ///< why it failed, in a student's terms; "" when it passes
};

/// Checks the render's variance and count channels against the reference's (same size needed);
/// any non-finite or negative variance fails.
VarianceConsistencyResult check_variance_consistency(const RenderEstimate& render,
                                                     const RenderEstimate& reference,
                                                     const VarianceConsistencyOptions& options = {});

}  // namespace pt
