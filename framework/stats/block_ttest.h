// Not needed for the assignment.
// Is a render statistically the same image as a reference? The block t-test of the design.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "framework/image/render_estimate.h"

namespace pt {

struct BlockTestOptions {
  int block_size = 16;   ///< blocks are block_size × block_size pixels (edge blocks smaller)
  double alpha = 0.01;   ///< family-wise significance: each block is tested at alpha / blocks
  /// Float rounding is not a difference: a block channel whose two means differ by at most
  /// relative_tolerance of the larger, or by absolute_tolerance, matches whatever its variance
  /// (blocks with zero or near-zero variance, a normals image or a directly seen light, would
  /// otherwise turn a rounding difference into an infinite t). 1e-5 is about 80 float ulps.
  double relative_tolerance = 1e-5;
  double absolute_tolerance = 1e-6;
};

/// One block whose mean differs from the reference's more than chance explains.
struct BlockDifference {
  int block_x = 0, block_y = 0;  ///< block column and row, from the top-left
  glm::vec3 ratio{1.0f};         ///< render mean / reference mean, per channel
  double t = 0.0;                ///< Welch t statistic of the worst channel
  double p_value = 1.0;          ///< two-sided p-value of the worst channel
};

struct BlockTestResult {
  bool pass = false;
  int blocks = 0;
  bool nonfinite = false;                ///< a NaN or infinite value anywhere: always a failure
  std::vector<BlockDifference> failing;  ///< worst first
  double min_p_value = 1.0;
  glm::vec3 overall_ratio{1.0f};         ///< mean of the render / mean of the reference
  std::string summary;                   ///< one line a person can act on
};

/// Splits both images into blocks; for each block and channel compares the block mean of the
/// render with the reference's by Welch's t-test, the variance of a block mean being
/// Σ variance_i / count_i / P² over its P pixels (the reference's own variance included; the
/// render's variance of one sample is taken as at least the reference's, since a render of few
/// samples that missed a pixel's rare bright samples underestimates it, often as zero), and
/// fails where the two-sided p-value is below alpha / blocks (Bonferroni), unless the means agree
/// within the options' rounding tolerance. Images of different sizes, or any non-finite value,
/// fail.
BlockTestResult block_t_test(const RenderEstimate& render, const RenderEstimate& reference,
                             const BlockTestOptions& options = {});

}  // namespace pt
