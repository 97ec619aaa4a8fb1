// Not needed for the assignment: the definitions of framework/scene/scene.h.
#include "framework/scene/scene.h"

namespace pt {

const char* to_string(MaterialKind kind) {
  switch (kind) {
    case MaterialKind::diffuse: return "diffuse";
    case MaterialKind::mirror: return "mirror";
    case MaterialKind::glass: return "glass";
    case MaterialKind::microfacet: return "microfacet";
    case MaterialKind::emission: return "emission";
  }
  return "unknown";
}

const char* to_string(LightKind kind) {
  switch (kind) {
    case LightKind::point: return "point";
    case LightKind::directional: return "directional";
    case LightKind::spot: return "spot";
    case LightKind::ambient: return "ambient";
    case LightKind::area: return "area";
  }
  return "unknown";
}

Bounds3 Scene::primitive_bounds(uint32_t primitive) const {
  Bounds3 b;
  if (is_triangle(primitive)) {
    const Triangle& tri = triangles[primitive];
    for (uint32_t v : tri.v) b.grow(positions[v]);
  } else {
    const Sphere& s = spheres[primitive - triangles.size()];
    b.grow(s.center - glm::vec3(s.radius));
    b.grow(s.center + glm::vec3(s.radius));
  }
  return b;
}

Bounds3 Scene::bounds() const {
  Bounds3 b;
  for (const Triangle& tri : triangles)
    for (uint32_t v : tri.v) b.grow(positions[v]);
  for (const Sphere& s : spheres) {
    b.grow(s.center - glm::vec3(s.radius));
    b.grow(s.center + glm::vec3(s.radius));
  }
  return b;
}

}  // namespace pt
