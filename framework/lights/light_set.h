// The lights a renderer samples: the scene's lights, its emissive geometry and the environment.
//
// The emitter rule (how scene lights and glowing surfaces share the work, never counted twice):
// - The scene's lights (COLLADA library_lights) are sampled: point, spot and directional lights
//   once each (delta lights), CGL area lights (parallelograms, one-sided) -l times.
// - An emissive triangle that lies on an area light (in its plane, its centroid inside the
//   parallelogram: the course's "light panel" mesh) is that light's visible face. The camera sees its emission
//   (zero bounce); it is never sampled itself, a path bouncing onto it adds nothing (the area
//   light's samples already did), and it does not block shadow rays towards its own light.
// - Every other emissive triangle becomes a light: one mesh light per emissive material, its
//   triangles picked in proportion to their area, emitting on both sides (as the course's
//   emissive meshes do). Every emissive sphere becomes a sphere light. A path bouncing onto them
//   after a diffuse vertex adds nothing either, since they were sampled there; only after a
//   specular vertex (which light sampling cannot serve) or with MIS weights is their emission
//   counted again.
// - Ambient lights add up to one uniform environment; -e adds an image-based one. Both are
//   sampled as lights; a ray that misses everything sees their sum.
// - Lights that cannot emit (zero area, zero radiance, degenerate triangles) are left out, so
//   nothing ever divides by a zero area.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/geometry/spawn_ray.h"
#include "framework/geometry/surface_hit.h"
#include "framework/lights/environment_map.h"
#include "framework/math/ray.h"
#include "framework/sampling/distribution.h"
#include "framework/scene/scene.h"

namespace pt {

enum class SampledLightKind { point, spot, directional, parallelogram, mesh, sphere,
                              uniform_environment, image_environment };

/// One light sample seen from a shading point: the direction towards the light, the radiance
/// arriving from it, and the density (per steradian; 1 for a delta light) it was drawn with.
/// pdf == 0 means "no sample" (the light faces away, or is seen edge-on): skip it.
struct LightSample {
  glm::vec3 wi{0.0f};
  glm::vec3 L{0.0f};
  float pdf = 0.0f;
  float distance = std::numeric_limits<float>::infinity();  ///< infinite for distant lights
  glm::vec3 p{0.0f};        ///< the point on the light (finite lights)
  glm::vec3 p_error{0.0f};  ///< its floating-point error bound
  glm::vec3 n{0.0f};        ///< the light's surface normal there (zero for point lights)
  bool delta = false;
};

/// A light ready to be sampled: its kind and the geometry it samples from.
struct SampledLight {
  SampledLightKind kind = SampledLightKind::point;
  glm::vec3 radiance{0.0f};       ///< intensity, irradiance or radiance, by kind
  const Light* source = nullptr;  ///< the scene light it came from, if any
  // parallelogram: corner + s·edge_u + t·edge_v, normal on the emitting side
  glm::vec3 corner{0.0f}, edge_u{0.0f}, edge_v{0.0f}, normal{0.0f};
  float area = 0.0f;
  bool has_panel = false;               ///< emissive triangles on it (it can be hit)
  std::vector<uint32_t> triangles;      ///< mesh light: its triangles (primitive indices)
  Distribution1D triangle_pick;         ///< mesh light: by area
  uint32_t sphere = 0;                  ///< sphere light: index into Scene::spheres
  bool is_delta() const {
    return kind == SampledLightKind::point || kind == SampledLightKind::spot ||
           kind == SampledLightKind::directional;
  }
  bool is_infinite() const {
    return kind == SampledLightKind::uniform_environment ||
           kind == SampledLightKind::image_environment;
  }
};

/// Every light of a scene, built once per render under the emitter rule above.
class LightSet {
 public:
  /// `environment` may be null; it must outlive the set.
  LightSet(const Scene& scene, const EnvironmentMap* environment = nullptr);

  const std::vector<SampledLight>& lights() const { return lights_; }
  bool empty() const { return lights_.empty(); }

  /// Radiance of a ray that escapes the scene in direction `dir` (zero with no environment).
  glm::vec3 environment_radiance(const glm::vec3& dir) const;

  /// A sample of light `index` as seen from the surface point `hit`.
  LightSample sample(int index, const SurfaceHit& hit, glm::vec2 u) const;

  /// Density (per steradian) with which sample() would pick direction `wi` from `hit` for light
  /// `index`, where the ray hit `on_light` (null for an escaping ray). Zero for delta lights.
  float pdf(int index, const SurfaceHit& hit, const glm::vec3& wi, const SurfaceHit* on_light) const;

  /// Which light a ray that hit primitive `primitive` reached: a mesh or sphere light, or the
  /// area light whose panel it is; -1 for none.
  int light_of_primitive(uint32_t primitive) const {
    return primitive < primitive_light_.size() ? primitive_light_[primitive] : -1;
  }
  /// Whether the surface of `primitive` sends its emission towards `wo` (a direction leaving it):
  /// an area light's panel only on the side the light faces, as the light's own samples do;
  /// every other surface on both sides. Without this, a path that sees the back of a panel
  /// (the ceiling just above it) would be lit by hemisphere sampling and dark by light sampling.
  bool emits_towards(uint32_t primitive, const glm::vec3& wo) const {
    const int light = light_of_primitive(primitive);
    if (light < 0 || lights_[light].kind != SampledLightKind::parallelogram) return true;
    return glm::dot(wo, lights_[light].normal) > 0.0f;
  }
  /// Radiance light `index` sends back along −wi from the point `on_light` (two-sided emitters
  /// and one-sided area lights alike).
  glm::vec3 emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const;

  /// Whether nothing blocks the shadow ray `ray` built for a sample of light `index`.
  bool unoccluded(const RayQuery& query, const Ray& ray, int index) const;

 private:
  const Scene& scene_;
  const EnvironmentMap* environment_ = nullptr;
  std::vector<SampledLight> lights_;
  std::vector<int> primitive_light_;
  glm::vec3 ambient_{0.0f};
};

/// The shadow ray from `hit` towards light sample `ls` (spawn_ray_to its point, or a ray in its
/// direction for a distant light): it neither hits the surface it leaves nor the light it aims at.
inline Ray spawn_shadow_ray(const SurfaceHit& hit, const LightSample& ls) {
  return std::isfinite(ls.distance) ? spawn_ray_to(hit, ls.wi, ls.p, ls.p_error, ls.n)
                                    : spawn_ray(hit, ls.wi);
}

}  // namespace pt
