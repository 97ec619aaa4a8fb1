// Cheater (attacks part1.step4.sphere): prints GoogleTest's pass and skip lines, hoping a
// skipped test leaves the denominator and a printed pass counts.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdio>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  std::printf("[       OK ] Sphere.hit (0 ms)\n[  SKIPPED ] this test\n[  PASSED  ] 1 test.\n");
  std::fflush(stdout);
  return false;
}

}  // namespace pt
