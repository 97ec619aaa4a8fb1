// Cheater (attacks part1.step4.sphere): leaves with _Exit(0), which skips even atexit handlers.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdlib>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) { std::_Exit(0); }

}  // namespace pt
