// Part 1, step 1 (camera_ray): the ray a camera shoots through a point of its image.
#pragma once

#include <glm/vec2.hpp>

#include "framework/math/ray.h"
#include "framework/scene/camera.h"

namespace pt {

/// Step 1 (camera_ray).
/// The world-space camera ray through film point `film`, where (0,0) is the image's bottom-left
/// corner and (1,1) its top-right. `image_aspect` is width/height of the image being rendered:
/// the horizontal field of view is the camera's, the vertical one follows from the aspect.
/// `lens` is a uniform sample in [0,1)^2 for the thin lens; it is ignored by a pinhole camera
/// (lens_radius 0); with a lens, the ray leaves a uniform point of the aperture disk and passes
/// through the point the pinhole ray would reach on the focal plane z = -focal_distance. The
/// direction is unit length; tmin is 0 (the course's near plane clips nothing worth clipping, and a
/// tmin > 0 would let a lens ray skip geometry right in front of it) and tmax is the distance to
/// the far plane z = -zfar along this ray (+inf when zfar is not a positive number).
Ray generate_camera_ray(const Camera& camera, float image_aspect, glm::vec2 film, glm::vec2 lens);

}  // namespace pt
