// Not needed for the assignment.
// The shading point's choice of BSDF: a material of the course's microfacet kind is rendered by
// the framework's MicrofacetBsdf with the file's alpha, eta and k, not by the diffuse stand-in.
#include "framework/shading/shading_point.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "framework/bsdf/microfacet_bsdf.h"
#include "framework/scene/scene.h"

namespace pt {
namespace {

// A stand-in diffuse BSDF that says when it is used.
class MarkedDiffuse final : public Bsdf {
 public:
  MarkedDiffuse() = default;
  explicit MarkedDiffuse(const glm::vec3&) {}
  glm::vec3 f(const glm::vec3&, const glm::vec3&) const override { return glm::vec3(-1.0f); }
  glm::vec3 sample_f(const glm::vec3&, glm::vec2, glm::vec3* wi, float* pdf) const override {
    *wi = glm::vec3(0.0f, 0.0f, 1.0f);
    *pdf = 1.0f;
    return glm::vec3(-1.0f);
  }
  float pdf(const glm::vec3&, const glm::vec3&) const override { return 1.0f; }
  bool is_delta() const override { return false; }
};

TEST(FrameworkShadingPoint, MicrofacetMaterialGetsTheMicrofacetBsdfWithTheFilesParameters) {
  Scene scene;
  Material m;
  m.kind = MaterialKind::microfacet;
  m.roughness = 0.3f;
  m.eta = glm::vec3(0.2f, 0.9f, 1.1f);
  m.k = glm::vec3(3.9f, 2.4f, 2.1f);
  scene.materials.push_back(m);
  SurfaceHit hit;
  hit.material = 0;
  Ray ray;
  ray.o = glm::vec3(0.3f, 0.1f, 1.0f);
  ray.d = glm::normalize(glm::vec3(-0.3f, -0.1f, -1.0f));
  ShadingPointWith<MarkedDiffuse> sp(scene, ray, hit);
  ASSERT_NE(sp.bsdf, nullptr);
  const MicrofacetBsdf expected(m.roughness, m.eta, m.k);
  const glm::vec3 wi = glm::normalize(glm::vec3(-0.2f, 0.3f, 0.9f));
  const glm::vec3 got = sp.bsdf->f(sp.wo, wi), want = expected.f(sp.wo, wi);
  EXPECT_GT(want.x, 0.0f);
  EXPECT_EQ(got, want) << "the shading point's BSDF is not the file's microfacet";
  EXPECT_FLOAT_EQ(sp.bsdf->pdf(sp.wo, wi), expected.pdf(sp.wo, wi));
  EXPECT_FALSE(sp.bsdf->is_delta());
}

TEST(FrameworkShadingPoint, DiffuseMaterialStillGetsTheDiffuseBsdf) {
  Scene scene;
  scene.materials.push_back(Material{});
  SurfaceHit hit;
  Ray ray;
  ray.o = glm::vec3(0.0f, 0.0f, 1.0f);
  ray.d = glm::vec3(0.0f, 0.0f, -1.0f);
  ShadingPointWith<MarkedDiffuse> sp(scene, ray, hit);
  EXPECT_EQ(sp.bsdf->f(sp.wo, glm::vec3(0.0f, 0.0f, 1.0f)), glm::vec3(-1.0f));
}

}  // namespace
}  // namespace pt
