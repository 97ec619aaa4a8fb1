// Not needed for the assignment.
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

/// The view the course's renderer gives when it renders `width` × `height` to a file: it looks at
/// the centre of `bounds` along the file camera's direction from 1.5 × the length of the bounds'
/// diagonal, and, having set its camera up for an 800 × 600 window, resizing to width × height
/// keeps the size of that window's pixels, so the tangent of the half field of view scales by
/// width/800 across (height/600 down; × 0.6 at the course's usual 480 × 360). Empty bounds
/// keep the camera where it is; the orientation is always kept. Throws std::range_error when the
/// placed camera's position would not be finite in float.
void place_course_camera(const Bounds3& bounds, int width, int height, Camera* camera);

}  // namespace pt
