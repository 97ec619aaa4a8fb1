// The scene's pinhole (or thin-lens) camera, as the file describes it.
#pragma once

#include <glm/mat4x4.hpp>

namespace pt {

/// A camera in the COLLADA convention: it looks down its local −Z axis with +Y up and +X to the
/// right; camera_to_world places it in the scene. The horizontal field of view is the file's
/// xfov and stays fixed; the vertical one follows the aspect of the image being rendered (as the
/// course's renderer does), so -r with another aspect widens or narrows the view vertically.
struct Camera {
  glm::mat4 camera_to_world{1.0f};
  float hfov_degrees = 49.13f;  ///< horizontal field of view (COLLADA xfov)
  float aspect = 4.0f / 3.0f;   ///< width/height the file was made for (default resolution)
  float znear = 0.1f;
  float zfar = 100.0f;
  float lens_radius = 0.0f;     ///< thin-lens aperture radius (-b); 0 is a pinhole
  float focal_distance = 1.0f;  ///< distance of the plane in focus (-d)
};

}  // namespace pt
