// The lights as the estimators of Parts 3 and 4 see them (ctx.lights): sample a light, ask what a
// ray brings back from them, ask whether a shadow ray is blocked. Which glowing things are lights,
// and why, is the emitter rule of docs/handout/part3.md; how they are stored and sampled is not
// the estimators' business (sampled_lights.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/geometry/surface_hit.h"
#include "framework/lights/shadow_target.h"
#include "framework/math/ray.h"

namespace pt {

struct Scene;
class EnvironmentMap;
class SampledLights;

/// One light sample seen from a shading point: the direction towards the light, the radiance
/// arriving from it, and the density (per steradian; 1 for a delta light) it was drawn with.
/// pdf == 0 means "no sample" (the light faces away, or is seen edge-on): skip it.
struct LightSample {
  glm::vec3 wi{0.0f};
  glm::vec3 L{0.0f};
  float pdf = 0.0f;
  ShadowTarget target;  ///< for spawn_shadow_ray only: an estimator never reads it
};

/// What an estimator needs to know of one light.
struct LightTraits {
  /// A point, spot or directional light: a single direction, so one sample is exact.
  bool is_delta() const { return delta; }
  /// Whether a ray (a BSDF sample) can reach it: only then do pdf() and emitted_along() answer.
  bool can_be_hit() const { return hittable; }

  bool delta = false;
  bool hittable = false;
};

/// Every light of a scene (its lights, its emissive surfaces, its environment), built once per
/// render; a light is named by its index in lights().
class LightSet {
 public:
  /// `environment` may be null; it must outlive the set.
  LightSet(const Scene& scene, const EnvironmentMap* environment = nullptr);
  ~LightSet();
  LightSet(LightSet&&) noexcept;

  /// The lights, by index: whether each is a delta light and whether a ray can reach it.
  const std::vector<LightTraits>& lights() const { return traits_; }

  /// A sample of light `index` seen from `hit`, for the numbers u in [0,1)² (direction, radiance,
  /// density per solid angle at hit).
  LightSample sample(int index, const SurfaceHit& hit, glm::vec2 u) const;
  /// The density with which sample() picks direction `wi` from `hit` for light `index`, where the
  /// ray in that direction hit `on_light` (null: it escaped); zero for a delta light.
  float pdf(int index, const SurfaceHit& hit, const glm::vec3& wi, const SurfaceHit* on_light) const;

  /// The light the primitive `primitive` belongs to, or -1: that surface emits nothing.
  int light_of_primitive(uint32_t primitive) const;
  /// What the camera, a mirror or glass sees: the radiance light `index` sends back along −wi from
  /// `on_light`, the point a ray in direction wi hit.
  glm::vec3 emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const;
  /// What light `index` sends along `ray`, traced from a non-specular point to estimate its direct
  /// light, whose nearest hit is `hit` (null: it escaped): the light as sample() draws it.
  glm::vec3 emitted_along(int index, const Ray& ray, const SurfaceHit* hit) const;
  /// emitted_along() summed over every light: all the direct light such a ray brings back.
  glm::vec3 radiance_along(const Ray& ray, const SurfaceHit* hit) const;
  /// The radiance of a ray that escapes the scene in direction `dir` (zero with no environment).
  glm::vec3 environment_radiance(const glm::vec3& dir) const;

  /// Whether nothing blocks the shadow ray `ray` made for a sample of light `index`.
  bool unoccluded(const RayQuery& query, const Ray& ray, int index) const;

  /// Not needed for the assignment: the lights as the framework stores and samples them.
  const SampledLights& sampled() const { return *sampled_; }

 private:
  std::unique_ptr<const SampledLights> sampled_;
  std::vector<LightTraits> traits_;
};

/// The shadow ray from `hit` towards light sample `ls`: it neither hits the surface it leaves nor
/// the light it aims at (no epsilon of your own).
Ray spawn_shadow_ray(const SurfaceHit& hit, const LightSample& ls);

}  // namespace pt
