// A surface point made ready for shading: its frame, the direction to the viewer, its BSDF.
//
// The diffuse BSDF is the student's (Part 3), so the framework names it only as a template
// parameter: Part 3 says `using ShadingPoint = ShadingPointWith<DiffuseBsdf>;` and lighting code
// writes ShadingPoint(scene, ray, hit). The mirror, glass, the course's microfacet conductor and
// the emitters' black BSDF are the framework's own.
#pragma once

#include "framework/bsdf/bsdf.h"
#include "framework/bsdf/framework_bsdfs.h"
#include "framework/geometry/surface_hit.h"
#include "framework/math/frame.h"
#include "framework/math/ray.h"
#include "framework/scene/scene.h"

namespace pt {

/// Everything of a shading point but its diffuse BSDF. For opaque materials both normals are
/// turned to the viewer's side (surfaces are two-sided); glass keeps the primitive's own side as
/// its outside. A degenerate shading normal falls back to the geometric one, and that to +z, so
/// the frame is always orthonormal. Not copyable: `bsdf` points into the object itself.
class ShadingPointBase {
 public:
  ShadingPointBase(const ShadingPointBase&) = delete;
  ShadingPointBase& operator=(const ShadingPointBase&) = delete;

  SurfaceHit hit;
  Frame frame{glm::vec3(0.0f, 0.0f, 1.0f)};  ///< z is the shading normal
  glm::vec3 wo{0.0f, 0.0f, 1.0f};            ///< towards the viewer, in the local frame
  /// The material's BSDF; left null here for a diffuse material, whose BSDF the derived
  /// ShadingPointWith makes.
  const Bsdf* bsdf = nullptr;

 protected:
  ShadingPointBase(const Scene& scene, const Ray& ray, const SurfaceHit& hit);
  const Material* material_ = nullptr;  ///< the hit's material (its albedo makes the diffuse BSDF)

 private:
  FrameworkBsdfs own_;  ///< where `bsdf` points for a material that is not diffuse
};

/// A shading point whose diffuse materials get a `Diffuse(material->albedo)`.
template <class Diffuse>
class ShadingPointWith final : public ShadingPointBase {
 public:
  ShadingPointWith(const Scene& scene, const Ray& ray, const SurfaceHit& hit)
      : ShadingPointBase(scene, ray, hit) {
    if (!bsdf) {
      diffuse_ = Diffuse(material_->albedo);
      bsdf = &diffuse_;
    }
  }

 private:
  Diffuse diffuse_;
};

}  // namespace pt
