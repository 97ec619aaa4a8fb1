// Not needed for the assignment: the BSDFs a shading point makes for the materials that are not
// diffuse (mirror, glass, the course's microfacet conductor, an emitter's black), held in the
// point itself so that making one allocates nothing.
#pragma once

#include "framework/bsdf/black.h"
#include "framework/bsdf/microfacet_bsdf.h"
#include "framework/bsdf/specular.h"

namespace pt {

/// One of each; the shading point's `bsdf` points at the one its material asks for.
struct FrameworkBsdfs {
  MirrorBsdf mirror;
  GlassBsdf glass;
  MicrofacetBsdf microfacet;
  BlackBsdf black;  ///< a CGL emission material: it glows and reflects nothing
};

}  // namespace pt
