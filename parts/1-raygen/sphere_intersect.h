// Part 1, step 4 (sphere): where a ray meets a sphere, with a quadratic that does not cancel.
#pragma once

#include "framework/math/ray.h"
#include "framework/scene/scene.h"

namespace pt {

/// Step 4 (sphere).
/// The nearest t with ray.tmin < t < ray.tmax where `ray` meets the sphere's surface, if any,
/// in *t. Both roots count (a ray that starts inside hits the far side). The quadratic is solved
/// without catastrophic cancellation, so a far sphere or a near-tangent ray still gets an
/// accurate t.
bool intersect_sphere(const Ray& ray, const Sphere& sphere, float* t);

}  // namespace pt
