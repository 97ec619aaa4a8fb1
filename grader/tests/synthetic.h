// Synthetic renders for the grader's tests: a known truth, sampled with noise, and the usual
// student mistakes applied to it.
#pragma once

#include <cstdint>
#include <functional>

#include <glm/vec3.hpp>

#include "framework/render/pixel_stats.h"
#include "framework/sampling/rng.h"
#include "framework/stats/block_ttest.h"

namespace pt::grader::testing {

constexpr int kWidth = 160, kHeight = 120;

/// A Cornell-box-like truth: a black border (no noise), a wall lit directly on the left half
/// (direct + indirect) and only indirectly on the right half.
struct Truth {
  static glm::vec3 direct(int x, int y) {
    if (x < 16 || y < 8) return glm::vec3(0.0f);
    return x < kWidth / 2 ? glm::vec3(0.6f, 0.5f, 0.4f) * (1.0f - float(y) / (2 * kHeight))
                          : glm::vec3(0.0f);
  }
  static glm::vec3 indirect(int x, int y) {
    if (x < 16 || y < 8) return glm::vec3(0.0f);
    return glm::vec3(0.15f, 0.2f, 0.25f);
  }
};

/// Samples value(x, y) `samples` times per pixel with uniform noise of the value's size.
inline RenderEstimate sample(const std::function<glm::vec3(int, int)>& value, int samples,
                             uint64_t seed) {
  RenderEstimate e;
  e.width = kWidth;
  e.height = kHeight;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      Rng rng(seed, uint64_t(y) * kWidth + x);
      glm::vec3 v = value(x, y);
      PixelStats stats;
      for (int s = 0; s < samples; ++s) {
        float u = 2.0f * rng.next_float();  // mean 1; one number for all channels, as in a render
        stats.add(v * u);
      }
      e.mean.push_back(glm::vec3(stats.mean));
      e.variance.push_back(glm::vec3(stats.variance()));
      e.count.push_back(float(stats.count));
    }
  }
  return e;
}

inline RenderEstimate full_render(int samples, uint64_t seed, float scale = 1.0f) {
  return sample([scale](int x, int y) { return scale * (Truth::direct(x, y) + Truth::indirect(x, y)); },
                samples, seed);
}

}  // namespace pt::grader::testing
