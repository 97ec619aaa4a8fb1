#include "app/viewer/sampling_check.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "framework/math/frame.h"
#include "framework/sampling/chi2_test_util.h"
#include "framework/sampling/rng.h"
#include "framework/sampling/warp.h"
#include "parts/3-direct/diffuse_bsdf.h"

namespace pt {

namespace {

constexpr int kPoints = 3000;

struct Sampler {
  DirectionSampler sample;
  DirectionPdf pdf;
  std::string says;
};

Sampler sampler_named(const std::string& name, const DiffuseBsdf& bsdf, const glm::vec3& wo) {
  if (name == "diffuse_bsdf")
    return {[&bsdf, wo](glm::vec2 u, glm::vec3* w) {
              float pdf = 0.0f;
              bsdf.sample_f(wo, u, w, &pdf);
              return pdf > 0.0f || !std::isfinite(pdf);
            },
            [&bsdf, wo](const glm::vec3& w) { return double(bsdf.pdf(wo, w)); },
            "Part 3's DiffuseBsdf::sample_f (albedo 0.5, wo (0.3, -0.2, 0.93)) against "
            "DiffuseBsdf::pdf"};
  if (name == "cosine_hemisphere")
    return {[](glm::vec2 u, glm::vec3* w) { *w = square_to_cosine_hemisphere(u); return true; },
            [](const glm::vec3& w) { return double(cosine_hemisphere_pdf(w)); },
            "the framework's square_to_cosine_hemisphere against cosine_hemisphere_pdf"};
  if (name == "uniform_hemisphere")
    return {[](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_hemisphere(u); return true; },
            [](const glm::vec3& w) { return double(uniform_hemisphere_pdf(w)); },
            "the framework's square_to_uniform_hemisphere against uniform_hemisphere_pdf"};
  if (name == "uniform_sphere")
    return {[](glm::vec2 u, glm::vec3* w) { *w = square_to_uniform_sphere(u); return true; },
            [](const glm::vec3&) { return double(uniform_sphere_pdf()); },
            "the framework's square_to_uniform_sphere against uniform_sphere_pdf"};
  throw std::invalid_argument("no sampler named '" + name + "'");
}

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

}  // namespace

std::vector<std::string> sampling_names() {
  return {"diffuse_bsdf", "cosine_hemisphere", "uniform_hemisphere", "uniform_sphere"};
}

nlohmann::json sampling_check(const std::string& name, long samples) {
  if (samples < 1000 || samples > 2000000)
    throw std::invalid_argument("samples must be from 1000 to 2000000 (got " +
                                std::to_string(samples) + ")");
  const DiffuseBsdf bsdf(glm::vec3(0.5f));
  const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 0.93f));
  const Sampler s = sampler_named(name, bsdf, wo);
  Chi2Options options;
  options.samples = samples;
  const Chi2Result r = chi2_direction_test(s.sample, s.pdf, Frame(glm::vec3(0.0f, 0.0f, 1.0f)), options);
  std::vector<float> points;
  Rng rng(2, 11);
  for (int i = 0; i < kPoints; ++i) {
    glm::vec3 w;
    if (!s.sample(rng.next_2d(), &w)) continue;
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) continue;
    w = glm::normalize(w);
    points.insert(points.end(), {w.x, w.y, w.z});
  }
  nlohmann::json observed = nlohmann::json::array(), expected = nlohmann::json::array();
  for (double v : r.observed) observed.push_back(v);
  for (double v : r.expected) expected.push_back(finite_or_null(v));
  return {{"name", name},
          {"says", s.says},
          {"samples", samples},
          {"statistic", finite_or_null(r.statistic)},
          {"dof", r.dof},
          {"p_value", finite_or_null(r.p_value)},
          {"pdf_integral", finite_or_null(r.pdf_integral)},
          {"nonfinite", r.nonfinite},
          {"passes", chi2_fits(r)},
          {"summary", r.summary},
          {"cos_bins", options.cos_bins},
          {"phi_bins", options.phi_bins},
          {"observed", observed},
          {"expected", expected},
          {"points", points}};
}

}  // namespace pt
