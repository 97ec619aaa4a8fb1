// A heavy-tailed pixel, the case where a stopping rule that decides on the samples it averages is
// biased: the stream, its settings and its non-adaptive reference, shared by Part 5's
// unbiasedness test and the controls that show the test can fail.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "framework/image/render_estimate.h"
#include "framework/render/film.h"
#include "framework/sampling/rng.h"
#include "parts/5-adaptive/adaptive_sampling.h"

namespace pt::test {

/// A heavy-tailed pixel: a dim background most of the time, a rare bright firefly (p = 0.05,
/// mean 0.3 in all). A batch that misses every firefly has zero spread and looks converged.
inline glm::vec3 heavy_tailed_sample(Rng& rng) {
  return glm::vec3(rng.next_float() < 0.05f ? 2.2f : 0.2f);
}

// 128 × 128 pixels in 32-pixel blocks: each block mean has a standard error near 1% of the
// mean, so a bias of about 4% in a block is caught at the Bonferroni threshold.
constexpr int kUnbiasW = 128, kUnbiasH = 128, kUnbiasBlock = 32, kReferenceSamples = 256;
constexpr AdaptiveSettings kUnbiasSettings{256, 32, 0.05f};

/// Non-adaptive: every pixel takes kReferenceSamples samples, on random numbers of its own.
inline RenderEstimate non_adaptive_reference() {
  Film film(kUnbiasW, kUnbiasH);
  for (int y = 0; y < kUnbiasH; ++y)
    for (int x = 0; x < kUnbiasW; ++x) {
      Rng rng(1000003, uint64_t(y) * kUnbiasW + x);
      for (int i = 0; i < kReferenceSamples; ++i) film.at(x, y).add(heavy_tailed_sample(rng));
    }
  return film.estimate();
}

}  // namespace pt::test
