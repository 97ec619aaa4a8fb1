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
  material = h.material < scene.materials.size() ? &scene.materials[h.material] : &kDefault;
  if (!usable(hit.ng)) hit.ng = glm::vec3(0.0f, 0.0f, 1.0f);
  hit.ng = glm::normalize(hit.ng);
  hit.n = usable(hit.n) ? glm::normalize(hit.n) : hit.ng;
  glm::vec3 to_viewer = usable(ray.d) ? -glm::normalize(ray.d) : hit.ng;
  switch (material->kind) {
    case MaterialKind::glass:
      glass_ = GlassBsdf(material->reflectance, material->transmittance, material->ior);
      bsdf = &glass_;
      break;
    case MaterialKind::mirror:
      mirror_ = MirrorBsdf(material->reflectance);
      bsdf = &mirror_;
      break;
    case MaterialKind::emission:  // the course's emitters glow and reflect nothing
      bsdf = &black_;
      break;
    default:  // diffuse; microfacet is rendered by its diffuse albedo until a part renders it
      break;  // ShadingPointWith makes the diffuse BSDF
  }
  if (material->kind != MaterialKind::glass && glm::dot(to_viewer, hit.ng) < 0.0f) {
    hit.ng = -hit.ng;
    hit.n = -hit.n;
  }
  if (glm::dot(hit.n, hit.ng) < 0.0f) hit.n = hit.ng;  // a normal map pointing inside: ignore it
  frame = Frame(hit.n);
  wo = frame.to_local(to_viewer);
}

}  // namespace pt
