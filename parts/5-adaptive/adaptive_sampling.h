// Part 5: per-pixel adaptive sampling — stop taking samples once a pixel has converged.
// Step 1 (convergence): pixel_converged; step 2 (adaptive_loop): sample_pixel_adaptive.
#pragma once

#include <functional>

#include <glm/vec3.hpp>

#include "framework/render/pixel_stats.h"
#include "framework/render/stopping_rule.h"
#include "framework/stats/illuminance_stats.h"

namespace pt {

// Which samples decide and which count is the assignment's stopping rule (split or course,
// framework/render/stopping_rule.h; `grader --part 5` prints the one your assignment asks for):
// sample_decides(rule, i) and sample_counts(rule, i) say it for the pixel's i-th sample.

/// The course's adaptive-sampling settings (-a BATCH TOL with -s as the maximum).
struct AdaptiveSettings {
  int max_samples = 64;    ///< -s: never more than this many samples, decision samples included
  int batch = 32;          ///< -a BATCH: convergence is checked after every batch
  float tolerance = 0.05f; ///< -a TOL: stop when the 95% confidence half-width ≤ TOL · mean
  StoppingRule rule = kAssignmentStoppingRule;  ///< which samples decide, which count
};

/// The radiance of one more sample of the pixel being estimated, through a new uniformly jittered
/// point of it: each call takes a new sample (the renderer makes it from Part 1's camera ray).
using PixelSampleFn = std::function<glm::vec3()>;

/// Step 1 (convergence).
/// Whether a pixel has converged: the 95% confidence half-width of the estimate the pixel
/// reports, I = 1.96·σ/√n_E, is at most tolerance·μ, where σ and μ come from the decision
/// samples' illuminances (`decision`) and n_E = `estimate_count` is the number of samples in
/// the estimate (under the course's rule every sample is both, so the two counts are equal).
/// Fewer than two decision samples say nothing about σ, and no estimate sample leaves nothing to
/// report: not converged. A pixel whose decision samples are all equal (σ = 0) has converged,
/// even a black one.
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
/// goes into the decision statistics (its illuminance) if sample_decides(settings.rule, i), and
/// (its radiance) into *estimate, the pixel's value, if sample_counts(settings.rule, i): under
/// the split rule each sample does one of the two, under the course's rule both. Returns the
/// number of samples taken, decision samples included.
int sample_pixel_adaptive(const AdaptiveSettings& settings, const PixelSampleFn& next_sample,
                          PixelStats* estimate, const ConvergenceRule& converged);

}  // namespace pt
