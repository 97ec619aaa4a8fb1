// Not needed for the assignment.
// Light sources as the scene file states them, in world space.
#pragma once

#include <string>

#include <glm/vec3.hpp>

namespace pt {

enum class LightKind { point, directional, spot, ambient, area };

const char* to_string(LightKind kind);

/// One light. Which fields matter depends on the kind:
/// - point: position, radiance = intensity (W/sr), attenuation constant/linear/quadratic.
/// - spot: as point, plus direction and the cone (falloff_degrees full angle, falloff_exponent).
/// - directional: direction the light travels, radiance = irradiance on a surface facing it.
/// - ambient: radiance arriving from every direction (a uniform environment).
/// - area: a parallelogram centred at position with full edge vectors edge_u and edge_v,
///   radiance emitted towards the side `direction` points to (Blender lamps shine down their
///   local −Z).
struct Light {
  std::string name;  ///< the file's name for it (for messages)
  LightKind kind = LightKind::point;
  glm::vec3 radiance{1.0f};
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};
  glm::vec3 edge_u{1.0f, 0.0f, 0.0f};
  glm::vec3 edge_v{0.0f, 1.0f, 0.0f};
  float constant_attenuation = 1.0f;
  float linear_attenuation = 0.0f;
  float quadratic_attenuation = 0.0f;
  float falloff_degrees = 180.0f;
  float falloff_exponent = 0.0f;

  /// True for lights that one sample describes exactly (point, spot, directional).
  bool is_delta() const {
    return kind == LightKind::point || kind == LightKind::spot || kind == LightKind::directional;
  }
};

}  // namespace pt
