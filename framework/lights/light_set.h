// The lights a renderer samples: the scene's lights, its emissive geometry and the environment.
//
// The emitter rule: every estimator of the light arriving at a point samples or reaches the same
// emitter, with the same numbers, so light sampling, MIS and hemisphere sampling converge to one
// image; nothing is counted twice.
// - Point, spot and directional lights (COLLADA library_lights) are sampled once each (delta
//   lights); no ray can hit them.
// - A CGL area light with an emissive panel on it (triangles in its plane, within a thousandth of
//   its size, whose centroids lie inside it: the course's "light" mesh) is lit and seen as the
//   course's renderer lights and shows it. What lights the scene is the light's own rectangle
//   (its position, edges and side as the loader reads them) with the light's radiance, one-sided:
//   light samples are drawn on it, and a ray traced to estimate the light at a non-specular point
//   (a hemisphere sample, MIS's BSDF sample) receives emitted_along(): the light's radiance where
//   it crosses the rectangle from the front before anything but the light's own panel. What the
//   camera, a mirror or glass shows is the panel (light_of_primitive and emitted(), which a ray
//   from the camera or a specular bounce asks): the panel's triangles, glowing with the light's
//   radiance on the light's side. A specular bounce is never light sampled, so every estimator
//   counts what such a ray sees the same way, and the two views never add up to twice the light.
//   When the file's panel and light differ (CBspheres' panel is 0.8 × 0.6 where its light is
//   0.6 × 0.8), warnings() says so once for each such light. Where they agree the panel's own
//   parallelogram is sampled (a panel of two triangles that tile it, as every course panel does):
//   the same points, with their error boxes around the triangles.
// - A CGL area light with no panel is sampled over its parallelogram, one-sided; nothing in the
//   scene is it, so no ray can hit it (as in the course, the camera does not see it), and
//   hemisphere sampling cannot see it either, as it cannot see a point light.
// - Every other emissive triangle becomes a light: one mesh light per emissive material, its
//   triangles picked by area, each sampled by the solid angle it subtends where usable (else by
//   area), emitting on both sides (as the course's meshes do). Every emissive sphere: a sphere light.
// - Ambient lights add up to one uniform environment; -e adds an image-based one. Both are
//   sampled as lights; a ray that misses everything sees their sum.
// - Lights that cannot emit (zero area, zero radiance, degenerate triangles) are left out, so
//   nothing ever divides by a zero area.
// A surface emits only as a light of this set: emitted() is the one answer to "what does this
// hit send back" to the camera and after a specular bounce; emitted_along() (radiance_along(),
// summed over the lights) is the one answer for a hemisphere or BSDF sample of direct light.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/geometry/spawn_ray.h"
#include "framework/geometry/surface_hit.h"
#include "framework/lights/environment_map.h"
#include "framework/lights/faster_light_sampling.h"
#include "framework/math/ray.h"
#include "framework/sampling/distribution.h"
#include "framework/scene/scene.h"

namespace pt {

/// parallelogram: an area light without a panel; panel: an area light with a panel (sampled and
/// reached on its rectangle, seen by the camera as its panel, one-sided); mesh: emissive
/// triangles of one material (two-sided); sphere: an emissive sphere.
enum class SampledLightKind { point, spot, directional, parallelogram, panel, mesh, sphere,
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

/// Every light of a scene, built once per render under the emitter rule above.
class LightSet {
 public:
  /// `environment` may be null; it must outlive the set.
  LightSet(const Scene& scene, const EnvironmentMap* environment = nullptr);

  const std::vector<SampledLight>& lights() const { return lights_; }
  bool empty() const { return lights_.empty(); }

  /// Radiance of a ray that escapes the scene in direction `dir` (zero with no environment).
  glm::vec3 environment_radiance(const glm::vec3& dir) const;

  /// A sample of light `index` as seen from the surface point `hit`, for the numbers u in
  /// [0,1)²: make_sample's answer (see faster_light_sampling.h for who else may give it).
  LightSample sample(int index, const SurfaceHit& hit, glm::vec2 u) const {
    if (FasterLightSampling* faster = FasterLightSampling::on_this_thread())
      return faster->sample(*this, index, hit, u);
    return make_sample(index, hit, u);
  }
  /// The definition of a light sample, kind by kind (light_set.cpp).
  LightSample make_sample(int index, const SurfaceHit& hit, glm::vec2 u) const;

  /// Density (per steradian) with which sample() would pick direction `wi` from `hit` for light
  /// `index`, where the ray hit `on_light` (null for an escaping ray). Zero for delta lights. For
  /// an area light, the density of the direction where it crosses the light's rectangle (whether
  /// the ray got there is emitted_along's to say).
  float pdf(int index, const SurfaceHit& hit, const glm::vec3& wi, const SurfaceHit* on_light) const;

  /// Which light a ray that hit primitive `primitive` reached: a mesh or sphere light, or the
  /// area light whose panel it is; -1 for none (the surface emits nothing).
  int light_of_primitive(uint32_t primitive) const {
    return primitive < primitive_light_.size() ? primitive_light_[primitive] : -1;
  }
  /// What the camera, a mirror or glass sees: the radiance light `index` sends back along −wi from
  /// the point `on_light` that a ray in direction wi reached (light_of_primitive's light): a
  /// panel only from its light's side, two-sided emitters from both.
  glm::vec3 emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const;

  /// What light `index` sends along `ray`, traced from a non-specular point to estimate its direct
  /// light (a hemisphere sample, MIS's BSDF sample), whose nearest hit is `hit` (null: it
  /// escaped): the light as sample() draws it. An area light with a panel: its radiance where
  /// the ray crosses its rectangle from the front, unless something other than its own panel was
  /// hit first (so the ceiling just above a panel is dark by every estimator); a mesh or sphere
  /// light: emitted() if the hit is its own; an environment: its radiance if the ray escaped;
  /// zero for lights no ray reaches.
  glm::vec3 emitted_along(int index, const Ray& ray, const SurfaceHit* hit) const;
  /// emitted_along() summed over every light: all the light such a ray brings back.
  glm::vec3 radiance_along(const Ray& ray, const SurfaceHit* hit) const;

  /// One line per area light whose panel differs from it in shape or radiance, naming the light
  /// element and saying what is rendered (see the emitter rule above); empty when they agree.
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// Whether nothing blocks the shadow ray `ray` built for a sample of light `index` (a panel
  /// light's own panel does not; it lies past the end of every shadow ray but those leaving from
  /// between it and its light, panel_slack).
  bool unoccluded(const RayQuery& query, const Ray& ray, int index) const {
    return !query.occluded(ray) || meets_only_own_panel(query, ray, index);
  }

 private:
  /// For a shadow ray of light `index` that something blocks: whether all it meets is that
  /// light's own panel.
  bool meets_only_own_panel(const RayQuery& query, const Ray& ray, int index) const;
  /// sample() for every kind but panels and meshes.
  LightSample sample_other(const SampledLight& l, const SurfaceHit& hit, glm::vec2 u) const;

  const Scene& scene_;
  const EnvironmentMap* environment_ = nullptr;
  std::vector<SampledLight> lights_;
  std::vector<int> primitive_light_;
  std::vector<std::string> warnings_;
  glm::vec3 ambient_{0.0f};
};

/// The shadow ray from `hit` towards light sample `ls`: spawn_ray_to its point, or a ray in its
/// direction for a distant light. It neither hits the surface it leaves nor the light it aims at.
inline Ray make_shadow_ray(const SurfaceHit& hit, const LightSample& ls) {
  return std::isfinite(ls.distance) ? spawn_ray_to(hit, ls.wi, ls.p, ls.p_error, ls.n)
                                    : spawn_ray(hit, ls.wi);
}

/// The shadow ray an estimate traces for `ls`: make_shadow_ray's answer.
inline Ray spawn_shadow_ray(const SurfaceHit& hit, const LightSample& ls) {
  if (FasterLightSampling* faster = FasterLightSampling::on_this_thread())
    return faster->shadow_ray(hit, ls);
  return make_shadow_ray(hit, ls);
}

}  // namespace pt
