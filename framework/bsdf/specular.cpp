// Not needed for the assignment: the definitions of framework/bsdf/specular.h.
#include "framework/bsdf/specular.h"

#include <algorithm>
#include <cmath>

namespace pt {

float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, -1.0f, 1.0f);
  if (cos_i < 0.0f) {  // arriving from inside: swap the media
    eta = 1.0f / eta;
    cos_i = -cos_i;
  }
  float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  float cos_t = std::sqrt(std::max(0.0f, 1.0f - sin2_t));
  float r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (r_parl * r_parl + r_perp * r_perp);
}

glm::vec3 MirrorBsdf::sample_f(const glm::vec3& wo, glm::vec2, glm::vec3* wi, float* pdf) const {
  *wi = reflect_local(wo);
  float c = std::abs(wi->z);
  if (!(c > 0.0f)) {  // grazing: the reflected ray carries nothing
    *pdf = 0.0f;
    return glm::vec3(0.0f);
  }
  *pdf = 1.0f;
  return reflectance_ / c;
}

glm::vec3 GlassBsdf::sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi, float* pdf) const {
  *pdf = 0.0f;
  if (wo.z == 0.0f || !(ior_ > 0.0f)) return glm::vec3(0.0f);
  const float F = fresnel_dielectric(wo.z, ior_);
  if (u.x < F) {
    *wi = reflect_local(wo);
    *pdf = F;
    return F * reflectance_ / std::abs(wi->z);
  }
  const bool entering = wo.z > 0.0f;
  const float eta = entering ? ior_ : 1.0f / ior_;  // η_transmitted / η_incident
  const float cos_o = std::abs(wo.z);
  const float sin2_t = (1.0f - cos_o * cos_o) / (eta * eta);
  const float cos_t = std::sqrt(std::max(0.0f, 1.0f - sin2_t));
  *wi = glm::vec3(-wo.x / eta, -wo.y / eta, entering ? -cos_t : cos_t);
  if (!(cos_t > 0.0f)) {
    *pdf = 0.0f;
    return glm::vec3(0.0f);
  }
  *pdf = 1.0f - F;
  return (1.0f - F) * transmittance_ / (cos_t * eta * eta);
}

}  // namespace pt
