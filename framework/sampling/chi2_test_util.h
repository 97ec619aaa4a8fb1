// Not needed for the assignment.
// Chi-square goodness-of-fit of a direction sampler against the density it claims, for tests.
//
// The method of Nori, pbrt and Mitsuba: bin many sampled directions on a grid over the sphere,
// integrate the claimed density over each cell numerically, pool cells whose expected count is
// small, and ask Pearson's statistic how likely the observed histogram is under that density.
// Tests and the viewer's sampling panel include this header.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/math/frame.h"
#include "framework/sampling/rng.h"
#include "framework/stats/distributions.h"

namespace pt {

/// What a chi-square test found.
struct Chi2Result {
  double statistic = 0.0;
  int dof = 0;
  double p_value = 0.0;
  double pdf_integral = 0.0;  ///< the claimed density integrated over the sphere (should be 1)
  long nonfinite = 0;         ///< samples or densities that were NaN or infinite
  std::string summary;
  /// Samples per cell and the count the density expects there, cell ic * phi_bins + ip (cosθ
  /// row ic, φ column ip), then the cell of samples that drew nothing: what a plot draws.
  std::vector<double> observed, expected;
};

/// Sampler: from a uniform point of the square, a unit direction, or false when it draws
/// nothing (that mass goes to a cell of its own, whose expected share is 1 − ∫pdf).
using DirectionSampler = std::function<bool(glm::vec2 u, glm::vec3* w)>;
/// The density per steradian the sampler claims for a direction.
using DirectionPdf = std::function<double(const glm::vec3& w)>;

struct Chi2Options {
  int cos_bins = 16;       ///< cells in cosθ ∈ [−1, 1] (equal solid angle)
  int phi_bins = 32;       ///< cells in φ ∈ [0, 2π)
  int quadrature = 8;      ///< midpoint-rule points per cell edge for integrating the pdf
  long samples = 200000;
  double min_expected = 5.0;  ///< cells expected to hold fewer samples are pooled
  uint64_t seed = 1;
};

/// Runs the test in the frame `frame` (its n is the grid's pole, so aim it where the density
/// lives). The grid is equal-area: cells in (cosθ, φ) have the same solid angle.
inline Chi2Result chi2_direction_test(const DirectionSampler& sample, const DirectionPdf& pdf,
                                      const Frame& frame, const Chi2Options& opt = {}) {
  const int nc = opt.cos_bins, np = opt.phi_bins, cells = nc * np;
  const double two_pi = 2.0 * 3.14159265358979323846;
  Chi2Result r;
  std::vector<double> observed(cells + 1, 0.0), expected(cells + 1, 0.0);
  Rng rng(opt.seed, 0x9e3779b97f4a7c15ULL);
  for (long i = 0; i < opt.samples; ++i) {
    glm::vec3 w;
    if (!sample(rng.next_2d(), &w)) {
      observed[cells] += 1;
      continue;
    }
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) {
      ++r.nonfinite;
      continue;
    }
    glm::vec3 l = frame.to_local(glm::normalize(w));
    double c = std::clamp(double(l.z), -1.0, 1.0);
    double phi = std::atan2(double(l.y), double(l.x));
    if (phi < 0) phi += two_pi;
    int ic = std::clamp(int((c + 1.0) * 0.5 * nc), 0, nc - 1);
    int ip = std::clamp(int(phi / two_pi * np), 0, np - 1);
    observed[ic * np + ip] += 1;
  }
  const int q = opt.quadrature;
  const double dc = 2.0 / nc, dp = two_pi / np;
  for (int ic = 0; ic < nc; ++ic)
    for (int ip = 0; ip < np; ++ip) {
      double sum = 0.0;
      for (int a = 0; a < q; ++a)
        for (int b = 0; b < q; ++b) {
          double c = -1.0 + (ic + (a + 0.5) / q) * dc;
          double phi = (ip + (b + 0.5) / q) * dp;
          double s = std::sqrt(std::max(0.0, 1.0 - c * c));
          glm::vec3 w = frame.to_world(
              glm::vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c)));
          double p = pdf(w);
          if (!std::isfinite(p)) ++r.nonfinite;
          else sum += p;
        }
      double integral = sum * dc * dp / (q * q);  // dω = dcosθ dφ
      expected[ic * np + ip] = integral;
      r.pdf_integral += integral;
    }
  expected[cells] = std::max(0.0, 1.0 - r.pdf_integral);
  for (double& e : expected) e *= double(opt.samples);
  r.observed = observed;
  r.expected = expected;

  // Pool small cells, smallest first (Nori's rule).
  std::vector<int> order(cells + 1);
  for (int i = 0; i <= cells; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
  double pool_obs = 0.0, pool_exp = 0.0, stat = 0.0;
  int used = 0;
  for (int i : order) {
    // The smallest cells form one pool until it is expected to hold min_expected samples. A
    // cell the quadrature found empty may still hold a sliver of the domain (an edge of a
    // light): it joins the pool, where samples far beyond the pool's expectation still fail.
    if (expected[i] < opt.min_expected || pool_exp < opt.min_expected) {
      pool_obs += observed[i];
      pool_exp += expected[i];
    } else {
      stat += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
      ++used;
    }
  }
  if (pool_exp > 0.0) {
    stat += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
    ++used;
  } else if (pool_obs > 0.0) {  // samples where the density says none can be: certain failure
    r.p_value = 0.0;
    r.statistic = INFINITY;
    r.summary = "samples fall where the claimed density is zero";
    return r;
  }
  r.statistic = stat;
  r.dof = std::max(1, used - 1);
  r.p_value = chi_squared_upper_tail(r.dof, stat);
  std::ostringstream os;
  os << "chi2 = " << stat << " with " << r.dof << " dof, p = " << r.p_value
     << ", integral of pdf = " << r.pdf_integral << ", non-finite = " << r.nonfinite;
  r.summary = os.str();
  return r;
}

/// Whether a sampler passed: no non-finite sample or density, a p-value above `alpha` (0.01 is
/// Nori's level), and a claimed density that integrates to 1 within `integral_tolerance`.
/// r.summary says which failed.
inline bool chi2_fits(const Chi2Result& r, double alpha = 0.01, double integral_tolerance = 2e-3) {
  return r.nonfinite == 0 && r.p_value > alpha &&
         std::abs(r.pdf_integral - 1.0) <= integral_tolerance;
}

}  // namespace pt
