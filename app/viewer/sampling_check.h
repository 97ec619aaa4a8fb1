// Sampling, seen: the directions a warp or Part 3's diffuse BSDF draws, against the density it
// claims, with the chi-square verdict the tests compute (framework/sampling/chi2_test_util.h).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pt {

/// The samplers the page offers: "diffuse_bsdf" (Part 3's DiffuseBsdf::sample_f against its
/// pdf), and the framework's warps "cosine_hemisphere", "uniform_hemisphere", "uniform_sphere".
std::vector<std::string> sampling_names();

/// Runs the chi-square test of `name` over `samples` samples: the verdict (statistic, degrees of
/// freedom, p-value, the density's integral, non-finite samples, pass or fail at Nori's level), the
/// observed and expected counts per cell of the equal-area grid (cosθ rows, φ columns), and the
/// first few thousand directions drawn. Throws std::invalid_argument for an unknown name or a
/// sample count outside 1000 .. 2,000,000.
nlohmann::json sampling_check(const std::string& name, long samples);

}  // namespace pt
