// Not needed for the assignment.
// Given code on Part 4: the radiance function a render calls per camera ray, built from the
// settings and the scene: the normals view, Part 3's direct light (-m 0 or 1), or Part 4's paths.
#pragma once

#include <memory>
#include <string>

#include <glm/vec3.hpp>

#include "framework/geometry/ray_query.h"
#include "framework/lights/environment_map.h"
#include "framework/lights/light_set.h"
#include "framework/render/render_settings.h"
#include "framework/sampling/rng.h"
#include "framework/scene/scene.h"
#include "framework/shading/lighting_context.h"

namespace pt {

/// Owns the scene's LightSet (and environment map) and answers radiance per camera ray: by
/// direct light alone (pipeline/3-direct, so Part 3 renders without Part 4) with --integrator
/// direct, or for -m 0 or 1 without MIS; by Part 4's paths otherwise. When the scene has nothing
/// that emits (no light, no emissive surface, no environment) it shows the surface normals
/// instead of a black image, and traces no shadow rays.
class Integrator {
 public:
  /// Builds one for `scene` answered by `query` (both must outlive it). Returns null and a
  /// message naming the file in *error if the environment map cannot be read.
  static std::unique_ptr<Integrator> create(const RenderSettings& settings, const Scene& scene,
                                            const RayQuery& query, std::string* error);

  glm::vec3 radiance(const Ray& ray, Rng& rng) const;
  /// The same estimate, drawing the same random numbers, with every ray asked of `query`
  /// instead (a counter of this one sample's rays around the query it was created with).
  glm::vec3 radiance(const Ray& ray, Rng& rng, const RayQuery& query) const;
  bool shows_normals() const { return normals_; }
  const LightSet& lights() const { return *lights_; }
  const EstimatorSettings& settings() const { return settings_; }

 private:
  Integrator(const Scene& scene, const RayQuery& query) : scene_(scene), query_(query) {}
  const Scene& scene_;
  const RayQuery& query_;
  EstimatorSettings settings_;
  std::unique_ptr<EnvironmentMap> environment_;
  std::unique_ptr<LightSet> lights_;
  bool normals_ = false;
  bool direct_only_ = false;  ///< Part 3's estimate is the whole answer (no Part 4 code runs)
};

}  // namespace pt
