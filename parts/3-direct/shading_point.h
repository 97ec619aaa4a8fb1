// What lighting code needs: the scene, its ray queries and lights, the settings of the estimator,
// and a surface point made ready for shading (its frame, the direction to the viewer, its BSDF).
#pragma once

#include "3-direct/diffuse_bsdf.h"
#include "bsdf/black.h"
#include "bsdf/specular.h"
#include "geometry/ray_query.h"
#include "geometry/surface_hit.h"
#include "lights/light_set.h"
#include "math/frame.h"
#include "math/ray.h"
#include "scene/scene.h"

namespace pt {

/// The scene as the lighting functions see it, and how they are asked to estimate.
struct LightingContext {
  const Scene& scene;
  const RayQuery& query;
  const LightSet& lights;
  int light_samples = 1;          ///< -l: samples per non-delta light (delta lights take one)
  bool hemisphere = false;        ///< -H: direct light by uniform hemisphere sampling
  bool mis = false;               ///< --mis: direct light by light and BSDF samples, weighted
  int max_depth = 1;              ///< -m: 0 emission only, 1 direct, 2 one indirect bounce, ...
  bool russian_roulette = true;   ///< end paths at random after the first bounce
  int only_bounce = -1;           ///< --bounce K: only light that took exactly K bounces
};

/// A hit made ready for shading. For opaque materials both normals are turned to the viewer's
/// side (surfaces are two-sided); glass keeps the primitive's own side as its outside. A
/// degenerate shading normal falls back to the geometric one, and that to +z, so the frame is
/// always orthonormal. Not copyable: `bsdf` points into the object itself.
struct ShadingPoint {
  ShadingPoint(const Scene& scene, const Ray& ray, const SurfaceHit& hit);
  ShadingPoint(const ShadingPoint&) = delete;
  ShadingPoint& operator=(const ShadingPoint&) = delete;

  SurfaceHit hit;
  Frame frame{glm::vec3(0.0f, 0.0f, 1.0f)};  ///< z is the shading normal
  glm::vec3 wo{0.0f, 0.0f, 1.0f};            ///< towards the viewer, in the local frame
  const Material* material = nullptr;
  const Bsdf* bsdf = nullptr;

 private:
  DiffuseBsdf diffuse_;
  MirrorBsdf mirror_;
  GlassBsdf glass_;
  BlackBsdf black_;
};

}  // namespace pt
