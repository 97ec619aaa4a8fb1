// Not needed for the assignment: the definitions of framework/sampling/distribution.h.
#include "framework/sampling/distribution.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pt {

Distribution1D::Distribution1D(std::vector<float> func) : func_(std::move(func)) {
  if (func_.empty()) func_.push_back(1.0f);
  const int n = int(func_.size());
  for (float& f : func_)
    if (!(std::isfinite(f) && f > 0.0f)) f = 0.0f;
  // The CDF is summed in double: a million small cells summed in float lose the last ones.
  std::vector<double> cdf(n + 1, 0.0);
  for (int i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + double(func_[i]) / n;
  integral_ = float(cdf[n]);
  cdf_.resize(n + 1);
  if (cdf[n] > 0.0) {
    for (int i = 0; i <= n; ++i) cdf_[i] = float(cdf[i] / cdf[n]);
  } else {
    std::fill(func_.begin(), func_.end(), 1.0f);
    integral_ = 1.0f;
    for (int i = 0; i <= n; ++i) cdf_[i] = float(i) / n;
  }
  cdf_[n] = 1.0f;
  for (int i = 0; i < n; ++i) has_empty_cell_ = has_empty_cell_ || !(cdf_[i + 1] > cdf_[i]);
  if (n <= kCountedCells) cdf_.resize((cdf_.size() + 3) / 4 * 4, std::numeric_limits<float>::infinity());
}

float Distribution1D::pdf_continuous(float x) const {
  int i = std::clamp(int(x * size()), 0, size() - 1);
  return func_[i] / integral_;
}

Distribution2D::Distribution2D(const std::vector<float>& func, int width, int height) {
  rows_.reserve(height);
  std::vector<float> row_integrals(height);
  for (int y = 0; y < height; ++y) {
    rows_.emplace_back(std::vector<float>(func.begin() + size_t(y) * width,
                                          func.begin() + size_t(y + 1) * width));
    // A row of zeros is made uniform by Distribution1D; its marginal weight stays zero.
    float sum = 0.0f;
    for (int x = 0; x < width; ++x) sum += std::max(0.0f, func[size_t(y) * width + x]);
    row_integrals[y] = std::isfinite(sum) ? sum / float(width) : 0.0f;
  }
  marginal_ = Distribution1D(std::move(row_integrals));
}

glm::vec2 Distribution2D::sample_continuous(glm::vec2 u, float* pdf) const {
  float pdf_v, pdf_u;
  int row;
  float v = marginal_.sample_continuous(u.y, &pdf_v, &row);
  float x = rows_[row].sample_continuous(u.x, &pdf_u);
  if (pdf) *pdf = pdf_v * pdf_u;
  return {x, v};
}

float Distribution2D::pdf(glm::vec2 p) const {
  int row = std::clamp(int(p.y * float(rows_.size())), 0, int(rows_.size()) - 1);
  return marginal_.pdf_continuous(p.y) * rows_[row].pdf_continuous(p.x);
}

}  // namespace pt
