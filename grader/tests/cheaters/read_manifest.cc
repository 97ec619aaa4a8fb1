// Cheater (attacks the references' secrecy): reads the manifest and a reference image and says
// how much it got, so the grader's output shows whether the student's code could read them.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  namespace fs = std::filesystem;
  static bool told = false;
  if (!told) {
    told = true;
    fs::path ref = fs::path(__FILE__).parent_path().parent_path().parent_path() / "reference";
    for (const char* name : {"manifest.json", "part1.normals.cornell_spheres.exr"}) {
      std::ifstream in(ref / name, std::ios::binary);
      std::string text((std::istreambuf_iterator<char>(in)), {});
      std::printf("CHEAT read %s: %zu bytes\n", name, text.size());
    }
    std::fflush(stdout);
  }
  return false;
}

}  // namespace pt
