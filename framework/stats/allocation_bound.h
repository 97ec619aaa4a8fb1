// How much any per-pixel sample allocation (adaptive sampling) can save over uniform sampling
// for a given error measure: the ceiling a convergence study holds adaptive sampling against.
#pragma once

#include "image/image.h"
#include "stats/block_ttest.h"
#include "stats/image_error.h"

namespace pt {

/// The best a per-pixel allocation of samples can do for relative MSE, worked out from each
/// pixel's variance of one sample (σ², from a render's estimate) and the reference's value.
///
/// With n_i samples, pixel i adds a_i / n_i to the relMSE, where a_i is the mean over channels of
/// σ²_ic / (ref²_ic + ε). For a fixed total of samples that sum is smallest with n_i ∝ √a_i
/// (a Lagrange multiplier gives a_i / n_i² equal for every pixel), and then the error equals
/// uniform sampling's with a fraction (mean √a)² / mean a of its samples (Cauchy–Schwarz: at most
/// 1, and 1 only when every a_i is equal). No adaptive sampler, however it decides, reaches
/// uniform's relMSE with fewer samples than that fraction, save by changing what one sample costs.
struct AllocationBound {
  /// (mean √a)² / mean a: the fewest samples, as a fraction of uniform's, that reach uniform's
  /// relMSE. 1 when no pixel has any variance (nothing to gain, nothing to lose).
  double best_sample_fraction = 1.0;
  /// The share of pixels with a = 0 (no variance at all): these cost uniform sampling samples
  /// that an adaptive sampler stops taking after its first batch.
  double zero_variance_share = 0.0;
};

/// The bound for relMSE with the given ε, from `estimate`'s per-sample variances and the
/// reference image's values (a noisy variance estimate only lowers the fraction a little, since
/// mean √â ≤ √mean â: the bound then promises slightly more than can be had, never less).
/// Throws std::invalid_argument naming both sizes when they differ or are empty, or naming the
/// pixel where a value is not finite or a variance is negative.
AllocationBound relmse_allocation_bound(const RenderEstimate& estimate, const Image& reference,
                                        double epsilon = kRelMseEpsilon);

}  // namespace pt
