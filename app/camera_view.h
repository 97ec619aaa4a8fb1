// A camera given by where it stands, what it looks at and which way is up (the --camera option,
// and the viewer's "use this view"), read from and written as one line of text.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "framework/scene/camera.h"

namespace pt {

/// A look-at camera: eye, target, up and the horizontal field of view in degrees.
struct CameraView {
  glm::vec3 eye{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float hfov_degrees = 49.13f;
};

/// Reads "px,py,pz,tx,ty,tz,ux,uy,uz,fov": ten finite numbers separated by commas. Throws
/// std::invalid_argument naming what is wrong: a count other than ten, a field that is not a
/// number, eye equal to target, an up direction that is zero or along the view, a field of view
/// outside (0, 180) degrees.
CameraView parse_camera_view(const std::string& text);

/// The same ten numbers, written so that parse_camera_view reads back the very same floats.
std::string format_camera_view(const CameraView& view);

/// The look-at view of a camera (the target one unit in front of it).
CameraView camera_view_of(const Camera& camera);

/// Places `camera` at the view: camera_to_world looks from eye to target with up as near +Y as
/// it can be, and the horizontal field of view is the view's. The lens and planes are kept.
void apply_camera_view(const CameraView& view, Camera* camera);

}  // namespace pt
