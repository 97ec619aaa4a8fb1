// Cheater (attacks part1.step4.sphere): leaves the test with exit(0) the moment the sphere is
// called, hoping an exit status of 0 reads as a pass.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdlib>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) { std::exit(0); }

}  // namespace pt
