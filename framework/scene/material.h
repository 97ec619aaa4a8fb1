// Not needed for the assignment.
// Surface materials as the scene file states them; the BSDFs that render them live elsewhere.
#pragma once

#include <string>

#include <glm/vec3.hpp>

namespace pt {

/// Which scattering model a material asks for. The course's CGL extension adds mirror, glass,
/// microfacet and emission to COLLADA's diffuse (phong/lambert) colour. An emission material is
/// the course's emitter: it glows and reflects nothing (its BSDF is black), whatever diffuse
/// colour the file gives it beside its radiance.
enum class MaterialKind { diffuse, mirror, glass, microfacet, emission };

const char* to_string(MaterialKind kind);

/// A material with every parameter the file gave, kept even where no part renders it yet.
struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::diffuse;
  glm::vec3 albedo{0.8f};          ///< diffuse reflectance (COLLADA diffuse colour)
  glm::vec3 emission{0.0f};        ///< emitted radiance (CGL emission/radiance, or phong emission)
  glm::vec3 reflectance{1.0f};     ///< mirror, glass: specular reflectance
  glm::vec3 transmittance{1.0f};   ///< glass: transmittance
  float ior = 1.5f;                ///< glass: index of refraction
  float roughness = 0.0f;          ///< glass/microfacet roughness (alpha)
  glm::vec3 eta{1.0f};             ///< microfacet conductor: real part of the IOR, per channel
  glm::vec3 k{0.0f};               ///< microfacet conductor: imaginary part (absorption)

  bool emissive() const { return emission.x > 0 || emission.y > 0 || emission.z > 0; }
};

}  // namespace pt
