// Cheater (attacks the machine): allocates and touches memory until something gives.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstring>
#include <vector>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  std::vector<char*> hoard;
  for (;;) {
    char* block = new char[size_t(256) << 20];
    std::memset(block, 1, size_t(256) << 20);
    hoard.push_back(block);
  }
}

}  // namespace pt
