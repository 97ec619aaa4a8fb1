// Not needed for the assignment: how the LightSet stores and samples its lights, kind by kind,
// under the emitter rule (docs/handout/part3.md). The estimators call light_set.h; this is the
// framework's side of it, and the fast layer's (faster_light_sampling.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/geometry/spawn_ray.h"
#include "framework/geometry/surface_hit.h"
#include "framework/lights/environment_map.h"
#include "framework/lights/light_set.h"
#include "framework/math/ray.h"
#include "framework/sampling/distribution.h"
#include "framework/scene/scene.h"

namespace pt {

/// parallelogram: an area light without a panel; panel: an area light with a panel (sampled and
/// reached on its rectangle, seen by the camera as its panel, one-sided); mesh: emissive
/// triangles of one material (two-sided); sphere: an emissive sphere.
enum class SampledLightKind { point, spot, directional, parallelogram, panel, mesh, sphere,
                              uniform_environment, image_environment };

/// A light ready to be sampled: its kind and the geometry it samples from.
struct SampledLight {
  SampledLightKind kind = SampledLightKind::point;
  glm::vec3 radiance{0.0f};       ///< intensity, irradiance or radiance, by kind
  const Light* source = nullptr;  ///< the scene light it came from, if any
  // parallelogram, panel: the area light's corner + s·edge_u + t·edge_v, normal on its emitting
  // side (a panel glows on the side of its triangles that agrees with it). Where a panel has the
  // light's shape, its own parallelogram (the same rectangle, to rounding) stands for it.
  glm::vec3 corner{0.0f}, edge_u{0.0f}, edge_v{0.0f}, normal{0.0f};
  /// panel: always; its samples are corner + u.x·edge_u + u.y·edge_v, uniform on the light's
  /// rectangle. panel_slack widens each sample's error box to take in the panel's triangles
  /// there: their corners' distance from the rectangle's plane, the rounding of a ray's hit on
  /// them and, where the rectangle is the panel's own parallelogram, its far corner's rounding. A
  /// shadow ray stops short of its sample's box, so it never meets its own light's panel.
  bool quad = false;
  glm::vec3 panel_slack{0.0f};
  float area = 0.0f;                    ///< the surface it samples: parallelogram, triangles or sphere
  std::vector<uint32_t> triangles;      ///< panel, mesh: its triangles (primitive indices)
  Distribution1D triangle_pick;         ///< panel, mesh: by area
  /// panel, mesh: each triangle's corners and unit normal (turned to `normal` for a panel; zero
  /// when degenerate), copied side by side once: every light sample of a render needs its
  /// triangle's, and reading them through the scene's triangle and position arrays was three
  /// dependent loads a sample
  struct SampledTriangle {
    glm::vec3 a{0.0f}, b{0.0f}, c{0.0f}, n{0.0f};
  };
  std::vector<SampledTriangle> sampled_triangles;
  float inv_area = 0.0f;                ///< 1 / area, once
  uint32_t sphere = 0;                  ///< sphere light: index into Scene::spheres
  bool is_delta() const {
    return kind == SampledLightKind::point || kind == SampledLightKind::spot ||
           kind == SampledLightKind::directional;
  }
  /// Whether a ray can reach it (a BSDF sample, a camera ray): everything but delta lights and
  /// area lights without a panel. Only then does pdf() answer for a ray that reached it.
  bool can_be_hit() const { return !is_delta() && kind != SampledLightKind::parallelogram; }
  bool is_infinite() const {
    return kind == SampledLightKind::uniform_environment ||
           kind == SampledLightKind::image_environment;
  }
};

/// Every light of a scene, built once per render under the emitter rule, with the definitions of
/// LightSet's answers (light_set.h states each one's contract; this adds how).
/// - An area light with a panel (triangles in its plane, within a thousandth of its size, whose
///   centroids lie inside it) is sampled and reached on its own rectangle (its position, edges
///   and side as the loader reads them); the camera, a mirror or glass sees the panel's
///   triangles. Where the panel is two triangles tiling the light's rectangle, that
///   parallelogram of the panel's is sampled (the same density); its samples' error boxes cover
///   the triangles (panel_slack).
/// - An area light with no panel is sampled over its parallelogram, one-sided; no ray reaches it.
/// - Every other emissive triangle: one mesh light per emissive material, its triangles picked by
///   area, each sampled by the solid angle it subtends where usable (else by area), two-sided.
///   Every emissive sphere: a sphere light, sampled by its cone.
/// - Ambient lights add up to one uniform environment; -e adds an image-based one.
/// - Lights that cannot emit (zero area, zero radiance, degenerate triangles) are left out.
class SampledLights {
 public:
  /// `environment` may be null; it must outlive the set.
  SampledLights(const Scene& scene, const EnvironmentMap* environment = nullptr);

  const std::vector<SampledLight>& lights() const { return lights_; }

  /// LightSet::environment_radiance.
  glm::vec3 environment_radiance(const glm::vec3& dir) const;
  /// The definition of a light sample, kind by kind: LightSet::sample's answer when no
  /// FasterLightSampling is installed.
  LightSample make_sample(int index, const SurfaceHit& hit, glm::vec2 u) const;
  /// LightSet::pdf: for an area light, the density of the direction where it crosses the light's
  /// rectangle (whether the ray got there is emitted_along's to say).
  float pdf(int index, const SurfaceHit& hit, const glm::vec3& wi, const SurfaceHit* on_light) const;
  /// LightSet::light_of_primitive.
  int light_of_primitive(uint32_t primitive) const {
    return primitive < primitive_light_.size() ? primitive_light_[primitive] : -1;
  }
  /// LightSet::emitted: a panel only from its light's side, two-sided emitters from both.
  glm::vec3 emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const;
  /// LightSet::emitted_along. An area light with a panel: its radiance where the ray crosses its
  /// rectangle from the front, unless something other than its own panel was hit first (so the
  /// ceiling just above a panel is dark by every estimator); a mesh or sphere light: emitted() if
  /// the hit is its own; an environment: its radiance if the ray escaped; zero for lights no ray
  /// reaches.
  glm::vec3 emitted_along(int index, const Ray& ray, const SurfaceHit* hit) const;
  /// LightSet::radiance_along.
  glm::vec3 radiance_along(const Ray& ray, const SurfaceHit* hit) const;
  /// LightSet::unoccluded: a panel light's own panel does not block its shadow rays; it lies
  /// past the end of every shadow ray but those leaving from between it and its light
  /// (panel_slack).
  bool unoccluded(const RayQuery& query, const Ray& ray, int index) const {
    return !query.occluded(ray) || meets_only_own_panel(query, ray, index);
  }

  /// One line per area light whose panel differs from it in shape or radiance (CBspheres' panel
  /// is 0.8 × 0.6 where its light is 0.6 × 0.8), naming the light element and saying what is
  /// rendered; empty when they agree.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  /// For a shadow ray of light `index` that something blocks: whether all it meets is that
  /// light's own panel.
  bool meets_only_own_panel(const RayQuery& query, const Ray& ray, int index) const;
  /// make_sample for every kind but panels and meshes.
  LightSample sample_other(const SampledLight& l, const SurfaceHit& hit, glm::vec2 u) const;

  const Scene& scene_;
  const EnvironmentMap* environment_ = nullptr;
  std::vector<SampledLight> lights_;
  std::vector<int> primitive_light_;
  std::vector<std::string> warnings_;
  glm::vec3 ambient_{0.0f};
};

/// The definition of the shadow ray from `hit` towards light sample `ls` (spawn_shadow_ray's
/// answer when no FasterLightSampling is installed): spawn_ray_to its point, or a ray in its
/// direction for a distant light. It neither hits the surface it leaves nor the light it aims at.
inline Ray make_shadow_ray(const SurfaceHit& hit, const LightSample& ls) {
  const ShadowTarget& to = ls.target;
  return std::isfinite(to.distance) ? spawn_ray_to(hit, ls.wi, to.p, to.p_error, to.n)
                                    : spawn_ray(hit, ls.wi);
}

}  // namespace pt
