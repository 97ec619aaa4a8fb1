// Cheater (attacks part1.step4.sphere): takes the complete solution's sphere test from the
// solution copy the isolated build links against, at compile time, where a bundle keeps it.
#include "parts/1-raygen/sphere_intersect.h"

#if __has_include("../../../../pt/private/solution/parts/1-raygen/sphere_intersect.cpp")
#include "../../../../pt/private/solution/parts/1-raygen/sphere_intersect.cpp"
#else
namespace pt {
bool intersect_sphere(const Ray&, const Sphere&, float*) { return false; }
}  // namespace pt
#endif
