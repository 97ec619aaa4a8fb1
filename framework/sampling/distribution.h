// Not needed for the assignment.
// Piecewise-constant distributions in 1D and 2D: what an image-based light and a mesh light
// sample by (pixels in proportion to their power, triangles in proportion to their area).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace pt {

/// A piecewise-constant density on [0,1) with n equal cells whose weights are `func`.
/// Negative or non-finite weights count as zero; if every weight is zero the distribution is
/// uniform, so sampling never divides by zero.
class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(std::vector<float> func);

  int size() const { return int(func_.size()); }
  /// Sum of the weights times the cell width: the integral of the unnormalised function.
  float integral() const { return integral_; }
  /// A point of [0,1) with density func(x)/integral; *pdf gets that density, *cell its cell.
  /// Inline: a mesh light's every sample starts here.
  float sample_continuous(float u, float* pdf, int* cell = nullptr) const {
    const int i = find_cell(u);
    const float width = cdf_[i + 1] - cdf_[i];
    float du = width > 0.0f ? (u - cdf_[i]) / width : 0.5f;
    du = std::clamp(du, 0.0f, 1.0f);
    if (pdf) *pdf = func_[i] / integral_;
    if (cell) *cell = i;
    const float x = (float(i) + du) / float(size());
    return std::min(x, 0x1.fffffep-1f);
  }
  float pdf_continuous(float x) const;

 private:
  int find_cell(float u) const {
    // Last i with cdf_[i] <= u, and never a cell of zero probability.
    int i;
    if (size() <= kCountedCells) {
      // upper_bound's very answer (the number of entries u is not below: the CDF is sorted),
      // counted without a branch on u. A light of a few triangles picks its cell here for every
      // sample, and a binary search's branch on a uniform u is mispredicted every other time.
      // The padding (+inf) is never counted but for a NaN u, which upper_bound also sends past
      // the last cell: the clamp below makes both the last cell.
      const float* cdf = cdf_.data();
      int not_below = 0;
      for (size_t k = 0; k < cdf_.size(); ++k) not_below += !(u < cdf[k]);
      i = not_below - 1;
    } else {
      i = int(std::upper_bound(cdf_.begin(), cdf_.begin() + size() + 1, u) - cdf_.begin()) - 1;
    }
    i = std::clamp(i, 0, size() - 1);
    if (!has_empty_cell_) return i;  // the walks below would not move
    while (i > 0 && cdf_[i + 1] <= cdf_[i]) --i;
    while (i < size() - 1 && cdf_[i + 1] <= cdf_[i]) ++i;
    return i;
  }
  /// Distributions of at most this many cells find a cell by counting (see find_cell).
  static constexpr int kCountedCells = 16;
  std::vector<float> func_;
  /// n+1 entries, cdf_[0] = 0, cdf_[n] = 1; for n <= kCountedCells, then +inf up to a multiple
  /// of four (never counted: a loop of whole fours, which the compiler may count in vector steps)
  std::vector<float> cdf_;
  float integral_ = 0.0f;
  bool has_empty_cell_ = false;  ///< whether some cdf_[i + 1] <= cdf_[i] (zero, or rounded away)
};

/// A piecewise-constant density on [0,1)^2 given on a width × height grid (row-major, row 0 at
/// v = 0): the marginal picks a row, that row's conditional distribution picks the column.
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(const std::vector<float>& func, int width, int height);

  /// A point of [0,1)^2 with density func/integral; *pdf gets that density.
  glm::vec2 sample_continuous(glm::vec2 u, float* pdf) const;
  float pdf(glm::vec2 p) const;

 private:
  std::vector<Distribution1D> rows_;
  Distribution1D marginal_;
};

}  // namespace pt
