// Where the course's renderer puts the camera: on the scene's centre, looking the file's way.
#pragma once

#include "framework/math/bounds.h"
#include "framework/scene/camera.h"

namespace pt {

/// Moves `camera` so that it looks at the centre of `bounds` along the direction the file gave
/// it, at the distance the file's camera had from that centre, keeping its orientation. The
/// course's renderer re-places the file's camera about the scene's bounding box the same way;
/// without it, the course's Cornell boxes (camera at floor height) show only their upper half.
/// A camera at the centre itself, or empty bounds, is left where it is. Throws std::range_error
/// when the placed camera's position would not be finite in float (coordinates near 3e38).
void centre_camera_on(const Bounds3& bounds, Camera* camera);

}  // namespace pt
