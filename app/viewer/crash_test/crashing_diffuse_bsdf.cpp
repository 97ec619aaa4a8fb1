// A student's Part 3 diffuse BSDF whose sample_f writes through a null pointer: linked into the
// crash test's viewer in place of parts/3-direct/diffuse_bsdf.cpp, so that the viewer's server
// really crashes in a part's function, as a student's would. f is not Part 3's answer: the test
// needs only a render that does not sample the BSDF (-m 1) to finish.
#include "framework/sampling/warp.h"
#include "parts/3-direct/diffuse_bsdf.h"

namespace pt {

namespace {
// Where the student meant to keep the sampled direction, never set: volatile, so the compiler
// keeps the write and the crash.
glm::vec3* volatile g_sampled = nullptr;
}  // namespace

glm::vec3 DiffuseBsdf::f(const glm::vec3&, const glm::vec3&) const { return albedo_; }

glm::vec3 DiffuseBsdf::sample_f(const glm::vec3& wo, glm::vec2 u, glm::vec3* wi,
                                float* pdf) const {
  *g_sampled = glm::vec3(u, 1.0f);  // SIGSEGV: g_sampled is null
  *wi = *g_sampled;
  *pdf = 1.0f;
  return f(wo, *wi);
}

float DiffuseBsdf::pdf(const glm::vec3&, const glm::vec3& wi) const {
  return cosine_hemisphere_pdf(wi);
}

}  // namespace pt
