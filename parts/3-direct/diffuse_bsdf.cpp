// Part 3, step 1 (diffuse_bsdf): DiffuseBsdf::f, DiffuseBsdf::sample_f.
#include "parts/3-direct/diffuse_bsdf.h"

#include "framework/sampling/warp.h"
#include "framework/student/todo.h"

namespace pt {

glm::vec3 DiffuseBsdf::f(const glm::vec3& wo, const glm::vec3& wi) const {
  // BEGIN SOLUTION
  (void)wo;
  return wi.z > 0.0f ? albedo_ * kInvPi : glm::vec3(0.0f);
  // END SOLUTION
  // STUDENT: a Lambertian surface reflects albedo_/π for every wi above the surface (wi.z > 0)
  // and nothing below it.
  PT_STUDENT_TODO("part 3", "DiffuseBsdf::f");
  (void)wo, (void)wi;
  return glm::vec3(0.0f);
}

glm::vec3 DiffuseBsdf::sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi,
                                float* pdf) const {
  // BEGIN SOLUTION
  *wi = square_to_cosine_hemisphere(u);
  *pdf = cosine_hemisphere_pdf(*wi);
  return f(wo, *wi);
  // END SOLUTION
  // STUDENT: draw *wi with square_to_cosine_hemisphere(u) (sampling/warp.h), set *pdf to its
  // density cosine_hemisphere_pdf(*wi), and return f(wo, *wi).
  // sample_f returns f itself, not the estimator weight f·cosθ/pdf (the caller forms it).
  PT_STUDENT_TODO("part 3", "DiffuseBsdf::sample_f");
  (void)wo, (void)u;
  *wi = glm::vec3(0.0f, 0.0f, 1.0f);
  *pdf = 0.0f;
  return glm::vec3(0.0f);
}

float DiffuseBsdf::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
  (void)wo;
  return cosine_hemisphere_pdf(wi);
}

}  // namespace pt
