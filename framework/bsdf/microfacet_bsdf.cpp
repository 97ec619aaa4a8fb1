// Not needed for the assignment: the definitions of framework/bsdf/microfacet_bsdf.h.
#include "framework/bsdf/microfacet_bsdf.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "framework/sampling/warp.h"

namespace pt {

glm::vec3 fresnel_conductor(float cos_i, const glm::vec3& eta, const glm::vec3& k) {
  const float c = std::clamp(cos_i, 0.0f, 1.0f);
  const float c2 = c * c;
  const glm::vec3 ek = eta * eta + k * k;  // η² + k²
  const glm::vec3 two_eta_c = 2.0f * eta * c;
  const glm::vec3 rs = (ek - two_eta_c + c2) / (ek + two_eta_c + c2);
  const glm::vec3 rp = (ek * c2 - two_eta_c + 1.0f) / (ek * c2 + two_eta_c + 1.0f);
  return 0.5f * (rs + rp);
}

MicrofacetBsdf::MicrofacetBsdf(float alpha, const glm::vec3& eta, const glm::vec3& k)
    // A perfectly smooth surface is a mirror, which this model (a density) cannot be: alpha is
    // kept above 1e-3, where D is already a spike far narrower than a pixel's footprint.
    : alpha_(std::max(alpha, 1e-3f)), eta_(eta), k_(k) {}

float MicrofacetBsdf::distribution(const glm::vec3& h) const {
  const float cos2 = h.z * h.z;
  if (!(h.z > 0.0f)) return 0.0f;
  const float tan2 = std::max(0.0f, 1.0f - cos2) / cos2;
  const float a2 = alpha_ * alpha_;
  return std::exp(-tan2 / a2) / (kPi * a2 * cos2 * cos2);
}

float MicrofacetBsdf::lambda(const glm::vec3& w) const {
  const float cos_t = std::abs(w.z);
  const float sin_t = safe_sqrt(1.0f - cos_t * cos_t);
  if (!(sin_t > 0.0f)) return 0.0f;  // straight along the normal: nothing is shadowed
  const float a = cos_t / (alpha_ * sin_t);  // 1 / (α tanθ)
  if (a >= 1.6f) return 0.0f;
  return (1.0f - 1.259f * a + 0.396f * a * a) / (3.535f * a + 2.181f * a * a);
}

float MicrofacetBsdf::shadowing_masking(const glm::vec3& wo, const glm::vec3& wi) const {
  return 1.0f / (1.0f + lambda(wo) + lambda(wi));
}

glm::vec3 MicrofacetBsdf::f(const glm::vec3& wo, const glm::vec3& wi) const {
  if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 sum = wo + wi;
  const float length = glm::length(sum);
  if (!(length > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 h = sum / length;
  return fresnel_conductor(wi.z, eta_, k_) * (shadowing_masking(wo, wi) * distribution(h) /
                                             (4.0f * wo.z * wi.z));
}

// The half vector h is drawn from D(h)·cosθh (which integrates to 1 over the hemisphere):
//   tan²θh = −α² ln(1 − u.x),   φh = 2π u.y,
// whose density over h is p(h) = D(h) cosθh. wi is wo reflected about h, and the change of
// variables from h to wi divides by 4 (wi·h): p(wi) = D(h) cosθh / (4 (wi·h)).
glm::vec3 MicrofacetBsdf::sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const {
  *pdf = 0.0f;
  *wi = glm::vec3(0.0f, 0.0f, 1.0f);
  if (!(wo.z > 0.0f)) return glm::vec3(0.0f);
  const float tan2 = -alpha_ * alpha_ * std::log(std::max(1.0f - u.x, 1e-30f));
  const float cos_h = 1.0f / std::sqrt(1.0f + tan2);
  const float sin_h = safe_sqrt(1.0f - cos_h * cos_h);
  const float phi = 2.0f * kPi * u.y;
  const glm::vec3 h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
  const float wo_h = glm::dot(wo, h);
  *wi = 2.0f * wo_h * h - wo;
  if (!(wi->z > 0.0f) || !(wo_h > 0.0f)) return glm::vec3(0.0f);  // reflected below: nothing
  *pdf = this->pdf(wo, *wi);
  if (!(*pdf > 0.0f)) return glm::vec3(0.0f);
  return f(wo, *wi);
}

float MicrofacetBsdf::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
  if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
  const glm::vec3 sum = wo + wi;
  const float length = glm::length(sum);
  if (!(length > 0.0f)) return 0.0f;
  const glm::vec3 h = sum / length;
  const float wi_h = glm::dot(wi, h);
  if (!(wi_h > 0.0f)) return 0.0f;
  return distribution(h) * h.z / (4.0f * wi_h);
}

}  // namespace pt
