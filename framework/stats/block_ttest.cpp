// Not needed for the assignment.
// The block t-test: Welch's test per block and channel, Bonferroni over all of them.
#include "framework/stats/block_ttest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace pt {
namespace {

/// The sums one image contributes to one block and channel.
struct BlockSums {
  double mean_sum = 0.0;      // Σ mean_i
  double var_sum = 0.0;       // Σ variance_i / count_i  (variance of the sum of pixel means)
  double dof_denominator = 0.0;  // Σ (variance_i / count_i)² / (count_i − 1), for Welch–Satterthwaite
};

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// a / b as a ratio a person reads: 1 when both are zero, infinite when only b is.
float ratio_of(double a, double b) {
  if (b > 0.0) return float(a / b);
  if (a == b) return 1.0f;
  return a > b ? std::numeric_limits<float>::infinity() : 0.0f;
}

/// Checks one image's shape and values; returns an empty string when it is usable.
std::string validate(const RenderEstimate& e, const char* name) {
  char buf[200];
  size_t n = size_t(std::max(e.width, 0)) * size_t(std::max(e.height, 0));
  if (e.width <= 0 || e.height <= 0 || e.mean.size() != n || e.variance.size() != n ||
      e.count.size() != n) {
    std::snprintf(buf, sizeof buf,
                  "the %s is malformed: %dx%d pixels but %zu means, %zu variances, %zu counts",
                  name, e.width, e.height, e.mean.size(), e.variance.size(), e.count.size());
    return buf;
  }
  for (size_t i = 0; i < n; ++i) {
    int x = int(i % size_t(e.width)), y = int(i / size_t(e.width));
    if (!finite(e.mean[i]) || !finite(e.variance[i]) || !std::isfinite(e.count[i])) {
      std::snprintf(buf, sizeof buf, "the %s has a NaN or infinite value at pixel (%d,%d)", name,
                    x, y);
      return buf;
    }
    if (e.count[i] <= 0.0f || e.variance[i].x < 0.0f || e.variance[i].y < 0.0f ||
        e.variance[i].z < 0.0f) {
      std::snprintf(buf, sizeof buf,
                    "the %s has %g samples or a negative variance at pixel (%d,%d)", name,
                    double(e.count[i]), x, y);
      return buf;
    }
  }
  return {};
}

/// Two-sided p-value of a Welch t statistic. Degrees of freedom beyond a million are the
/// normal distribution to every digit that matters, and Student's t needs them finite.
double two_sided_p(double t, double dof) {
  double a = std::fabs(t);
  if (!(dof > 0.0) || dof > 1e6) {
    return 2.0 * boost::math::cdf(boost::math::complement(boost::math::normal_distribution<>(), a));
  }
  return 2.0 * boost::math::cdf(boost::math::complement(boost::math::students_t_distribution<>(dof), a));
}

}  // namespace

BlockTestResult block_t_test(const RenderEstimate& render, const RenderEstimate& reference,
                             const BlockTestOptions& options) {
  BlockTestResult result;
  char buf[300];
  if (render.width != reference.width || render.height != reference.height) {
    std::snprintf(buf, sizeof buf, "the render is %dx%d pixels but the reference is %dx%d",
                  render.width, render.height, reference.width, reference.height);
    result.summary = buf;
    return result;
  }
  for (auto [e, name] : {std::pair{&render, "render"}, std::pair{&reference, "reference"}}) {
    std::string problem = validate(*e, name);
    if (!problem.empty()) {
      result.nonfinite = problem.find("NaN") != std::string::npos;
      result.summary = problem;
      return result;
    }
  }
  if (options.block_size <= 0 || !(options.alpha > 0.0 && options.alpha < 1.0) ||
      !(options.relative_tolerance >= 0.0) || !(options.absolute_tolerance >= 0.0)) {
    std::snprintf(buf, sizeof buf, "bad block test options: block size %d, alpha %g",
                  options.block_size, options.alpha);
    result.summary = buf;
    return result;
  }

  const int w = render.width, h = render.height, bs = options.block_size;
  const int bw = (w + bs - 1) / bs, bh = (h + bs - 1) / bs;
  result.blocks = bw * bh;
  // Three channels per block are three tests: the block fails at alpha / blocks in all.
  const double threshold = options.alpha / (3.0 * result.blocks);

  glm::dvec3 total_render(0.0), total_reference(0.0);
  for (int by = 0; by < bh; ++by) {
    for (int bx = 0; bx < bw; ++bx) {
      BlockSums sums[2][3];
      int pixels = 0;
      for (int y = by * bs; y < std::min(h, (by + 1) * bs); ++y) {
        for (int x = bx * bs; x < std::min(w, (bx + 1) * bs); ++x) {
          size_t i = size_t(y) * size_t(w) + size_t(x);
          ++pixels;
          const RenderEstimate* images[2] = {&render, &reference};
          for (int k = 0; k < 2; ++k) {
            double n = images[k]->count[i];
            for (int c = 0; c < 3; ++c) {
              // The render's variance of one sample is at least the reference's: both estimate
              // the same quantity when the render is right (the hypothesis under test), and a
              // render of few samples often sees none of a pixel's rare bright samples (an edge,
              // a silhouette, a caustic), so its own estimate is zero where the true one is not.
              double per_sample = images[k]->variance[i][c];
              if (k == 0) per_sample = std::max(per_sample, double(reference.variance[i][c]));
              double s = per_sample / n;
              sums[k][c].mean_sum += images[k]->mean[i][c];
              sums[k][c].var_sum += s;
              if (n > 1.0) sums[k][c].dof_denominator += s * s / (n - 1.0);
            }
          }
        }
      }
      BlockDifference worst;
      worst.block_x = bx;
      worst.block_y = by;
      double worst_abs_t = -1.0;
      bool differs = false;
      for (int c = 0; c < 3; ++c) {
        double m_render = sums[0][c].mean_sum / pixels, m_ref = sums[1][c].mean_sum / pixels;
        total_render[c] += sums[0][c].mean_sum;
        total_reference[c] += sums[1][c].mean_sum;
        worst.ratio[c] = ratio_of(m_render, m_ref);
        double var = (sums[0][c].var_sum + sums[1][c].var_sum) / (double(pixels) * pixels);
        double diff = m_render - m_ref;
        double t, p;
        const double tolerance =
            std::max(options.absolute_tolerance,
                     options.relative_tolerance * std::max(std::fabs(m_render), std::fabs(m_ref)));
        if (std::fabs(diff) <= tolerance) {
          // Within float rounding (the only difference a zero-variance block can have between
          // two correct images): the same, however small the variance makes the t.
          t = 0.0;
          p = 1.0;
        } else if (var > 0.0) {
          t = diff / std::sqrt(var);
          double den = (sums[0][c].dof_denominator + sums[1][c].dof_denominator) /
                       (double(pixels) * pixels * double(pixels) * pixels);
          double dof = den > 0.0 ? var * var / den : std::numeric_limits<double>::infinity();
          p = two_sided_p(t, dof);
        } else {
          t = std::copysign(std::numeric_limits<double>::infinity(), diff);
          p = 0.0;
        }
        result.min_p_value = std::min(result.min_p_value, p);
        if (p < threshold) differs = true;
        if (std::fabs(t) > worst_abs_t) {
          worst_abs_t = std::fabs(t);
          worst.t = t;
          worst.p_value = p;
        }
      }
      if (differs) result.failing.push_back(worst);
    }
  }
  for (int c = 0; c < 3; ++c) result.overall_ratio[c] = ratio_of(total_render[c], total_reference[c]);

  // p-values underflow to 0 for gross errors, so |t| orders the worst first.
  std::stable_sort(result.failing.begin(), result.failing.end(),
                   [](const BlockDifference& a, const BlockDifference& b) {
                     return std::fabs(a.t) > std::fabs(b.t);
                   });
  result.pass = result.failing.empty();
  if (result.pass) {
    std::snprintf(buf, sizeof buf,
                  "all %d blocks match the reference (smallest p-value %.3g, threshold %.3g)",
                  result.blocks, result.min_p_value, threshold);
  } else {
    const BlockDifference& b = result.failing.front();
    // The channel of the worst t tells the direction; the mean of the finite channel ratios
    // tells by how much, which is what a person compares with "twice", "π", "5%".
    double r = 0.0;
    int finite_channels = 0;
    for (int c = 0; c < 3; ++c) {
      if (std::isfinite(b.ratio[c])) {
        r += b.ratio[c];
        ++finite_channels;
      }
    }
    std::string how;
    if (finite_channels == 0) {
      how = "is lit where the reference is black";
    } else {
      r /= finite_channels;
      bool darker = b.t < 0.0;
      double percent = std::fabs(1.0 - r) * 100.0;
      char what[80];
      if (percent >= 0.5) {
        std::snprintf(what, sizeof what, "is %.0f%% too %s", percent, darker ? "dark" : "bright");
      } else {
        std::snprintf(what, sizeof what, "is slightly too %s", darker ? "dark" : "bright");
      }
      how = what;
    }
    std::snprintf(buf, sizeof buf, "block (%d,%d) %s (t = %.3g; %zu of %d blocks differ, threshold p < %.3g)",
                  b.block_x, b.block_y, how.c_str(), b.t, result.failing.size(), result.blocks,
                  threshold);
  }
  result.summary = buf;
  return result;
}

}  // namespace pt
