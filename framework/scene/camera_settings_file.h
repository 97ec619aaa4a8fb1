// Not needed for the assignment.
// The course renderer's camera settings file (its -c FILE): a saved view, read into a Camera.
#pragma once

#include <string>

#include "framework/scene/camera.h"

namespace pt {

/// Reads the camera settings file the course's renderer writes when its viewer saves a view:
/// whitespace-separated numbers, in this order,
///   hFov vFov aspect near far          (degrees; the aspect is hFov's over vFov's)
///   position (3)   target (3)          (world space)
///   phi theta r minR maxR              (the viewer's orbit; not needed to render)
///   c2w (9, row by row)                (columns: the camera's right, up and backward axes)
///   screenW screenH screenDist         (the window; not needed to render)
///   focalDistance lensRadius           (absent in files from before the lens was added)
/// Returns `base` with its placement, field of view, clipping planes and, when present, its lens
/// replaced by the file's. Throws SceneError naming the file and the first number that is
/// missing, is not a number, or makes no camera (a field of view outside (0, 180), an axis of
/// zero length).
Camera read_camera_settings(const std::string& path, const Camera& base);

}  // namespace pt
