// Cheater (attacks the grader's time): never returns.
#include "parts/1-raygen/sphere_intersect.h"

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  volatile unsigned long spin = 0;
  for (;;) spin = spin + 1;
}

}  // namespace pt
