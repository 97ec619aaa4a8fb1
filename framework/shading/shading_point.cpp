// Not needed for the assignment: the definitions of framework/shading/shading_point.h.
#include "framework/shading/shading_point.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace pt {
namespace {

bool usable(const glm::vec3& v) {
  float l = glm::dot(v, v);
  return std::isfinite(l) && l > 0.0f;
}

}  // namespace

ShadingPointBase::ShadingPointBase(const Scene& scene, const Ray& ray, const SurfaceHit& h)
    : hit(h) {
  static const Material kDefault;
  material_ = h.material < scene.materials.size() ? &scene.materials[h.material] : &kDefault;
  // The normals are worked on in locals read from h and stored once at the end: reading them
  // back from the copy just made (hit) waited on that copy's stores, which a load spanning two
  // of them cannot take its value from.
  glm::vec3 ng = usable(h.ng) ? h.ng : glm::vec3(0.0f, 0.0f, 1.0f);
  ng = glm::normalize(ng);
  glm::vec3 n = usable(h.n) ? glm::normalize(h.n) : ng;
  glm::vec3 to_viewer = usable(ray.d) ? -glm::normalize(ray.d) : ng;
  switch (material_->kind) {
    case MaterialKind::glass:
      own_.glass = GlassBsdf(material_->reflectance, material_->transmittance, material_->ior);
      bsdf = &own_.glass;
      break;
    case MaterialKind::mirror:
      own_.mirror = MirrorBsdf(material_->reflectance);
      bsdf = &own_.mirror;
      break;
    case MaterialKind::microfacet:
      own_.microfacet = MicrofacetBsdf(material_->roughness, material_->eta, material_->k);
      bsdf = &own_.microfacet;
      break;
    case MaterialKind::emission:  // the course's emitters glow and reflect nothing
      bsdf = &own_.black;
      break;
    default:  // diffuse: ShadingPointWith makes the diffuse BSDF
      break;
  }
  if (material_->kind != MaterialKind::glass && glm::dot(to_viewer, ng) < 0.0f) {
    ng = -ng;
    n = -n;
  }
  if (glm::dot(n, ng) < 0.0f) n = ng;  // a normal map pointing inside: ignore it
  hit.ng = ng;
  hit.n = n;
  frame = Frame(n);
  wo = frame.to_local(to_viewer);
}

}  // namespace pt
