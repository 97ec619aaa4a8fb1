// Part 5: per-pixel adaptive sampling — stop taking samples once a pixel has converged.
// Step 1 (convergence): pixel_converged; step 2 (adaptive_loop): sample_pixel_adaptive.
#pragma once

#include <functional>

#include <glm/vec3.hpp>

#include "framework/render/pixel_stats.h"
#include "framework/stats/illuminance_stats.h"

namespace pt {

/// One sample in kDecisionStride of a pixel decides when to stop and never enters the pixel's
/// value; the others form the value and never take part in the decision. The course's rule
/// decides on the very samples it averages, so a heavy-tailed pixel whose batch happened to miss
/// its rare bright samples looks converged and stops too dark: a quarter of the samples is the
/// price of an answer that is unbiased whatever the pixel's distribution.
constexpr int kDecisionStride = 4;

/// Whether the pixel's `index`-th sample (from 0) is a decision sample: the last of each stride.
inline bool is_decision_sample(long index) {
  return index % kDecisionStride == kDecisionStride - 1;
}

/// The course's adaptive-sampling settings (-a BATCH TOL with -s as the maximum).
struct AdaptiveSettings {
  int max_samples = 64;    ///< -s: never more than this many samples, decision samples included
  int batch = 32;          ///< -a BATCH: convergence is checked after every batch
  float tolerance = 0.05f; ///< -a TOL: stop when the 95% confidence half-width ≤ TOL · mean
};


/// The radiance of one more sample of the pixel being estimated, through a new uniformly jittered
/// point of it: each call takes a new sample (the renderer makes it from Part 1's camera ray).
using PixelSampleFn = std::function<glm::vec3()>;

/// Step 1 (convergence).
/// Whether a pixel has converged: the 95% confidence half-width of the estimate the pixel
/// reports, I = 1.96·σ/√n_E, is at most tolerance·μ, where σ and μ come from the decision
/// samples' illuminances (`decision`) and n_E = `estimate_count` is the number of samples in
/// the estimate. Fewer than two decision samples say nothing about σ: not converged. A pixel
/// whose decision samples are all equal (σ = 0) has converged, even a black one.
bool pixel_converged(const IlluminanceStats& decision, long estimate_count, float tolerance);

/// The stopping rule the loop asks after each batch, with pixel_converged's arguments: the
/// renderer hands it pixel_converged (step 1); step 2's tests hand it a rule of their own, so the
/// loop is graded apart from the rule.
using ConvergenceRule =
    std::function<bool(const IlluminanceStats& decision, long estimate_count, float tolerance)>;

/// Step 2 (adaptive_loop).
/// Samples a pixel in batches of settings.batch samples (each the radiance next_sample()
/// returns), stopping after the first whole batch after which converged(decision statistics,
/// estimate->count, settings.tolerance) holds, or at settings.max_samples. Sample i (from 0)
/// goes into the decision statistics (its illuminance) if is_decision_sample(i), else (its
/// radiance) into *estimate, the pixel's value, never both. Returns the number of samples
/// taken, decision samples included.
int sample_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                          PixelStats* estimate, const ConvergenceRule& converged);

}  // namespace pt
