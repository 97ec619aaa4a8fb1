// Not needed for the assignment.
// How much any per-pixel sample allocation (adaptive sampling) can save over uniform sampling
// for a given error measure: the ceiling a convergence study holds adaptive sampling against.
#pragma once

#include <vector>

#include "framework/image/image.h"
#include "framework/image/render_estimate.h"
#include "framework/stats/image_error.h"

namespace pt {

/// The best a per-pixel allocation of samples can do for relative MSE, worked out from each
/// pixel's variance of one sample (σ², from a render's estimate) and the reference's value.
///
/// With n_i samples, pixel i adds a_i / n_i to the relMSE, where a_i is the mean over channels of
/// σ²_ic / (ref²_ic + ε). For a fixed total of samples that sum is smallest with n_i ∝ √a_i
/// (a Lagrange multiplier gives a_i / n_i² equal for every pixel), and then the error equals
/// uniform sampling's with a fraction (mean √a)² / mean a of its samples (Cauchy–Schwarz: at most
/// 1, and 1 only when every a_i is equal). No adaptive sampler, however it decides, reaches
/// uniform's relMSE with fewer samples than that fraction.
///
/// Samples differ in cost, though (a ray into the sky costs a box test, one into a bunny a whole
/// path), and what counts is time. With c_i the time of one of pixel i's samples, the best
/// allocation for a fixed time is n_i ∝ √(a_i / c_i), and it reaches uniform's relMSE in a
/// fraction (mean √(a c))² / (mean a · mean c) of uniform's time.
struct AllocationBound {
  /// (mean √a)² / mean a: the fewest samples, as a fraction of uniform's, that reach uniform's
  /// relMSE. 1 when no pixel has any variance (nothing to gain, nothing to lose).
  double best_sample_fraction = 1.0;
  /// (mean √(a c))² / (mean a · mean c): the least time, as a fraction of uniform's, that reaches
  /// uniform's relMSE. NaN when no per-pixel costs were given.
  double best_time_fraction = 0.0;
  /// The share of pixels with a = 0 (no variance at all): these cost uniform sampling samples
  /// that an adaptive sampler stops taking after its first batch.
  double zero_variance_share = 0.0;
};

/// The bound for relMSE with the given ε, from `estimate`'s per-sample variances, the reference
/// image's values and, when not empty, `sample_cost`: each pixel's time per sample, row by row
/// (any unit). A noisy variance estimate only lowers the fractions a little (mean √â ≤ √mean â:
/// the bound then promises slightly more than can be had, never less). Throws
/// std::invalid_argument naming both sizes when they differ or are empty, or naming the pixel
/// where a value is not finite, a variance negative or a cost not positive.
AllocationBound relmse_allocation_bound(const RenderEstimate& estimate, const Image& reference,
                                        const std::vector<double>& sample_cost = {},
                                        double epsilon = kRelMseEpsilon);

}  // namespace pt
