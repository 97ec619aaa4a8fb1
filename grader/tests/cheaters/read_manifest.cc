// Cheater (attacks the references' secrecy; replaces parts/1-raygen/triangle_intersect.cpp):
// reads the manifest and a reference image and says how much it got, so the grader's output
// shows whether the student's code could read them.
#include "parts/1-raygen/triangle_intersect.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
  namespace fs = std::filesystem;
  static bool told = false;
  if (!told) {
    told = true;
    fs::path ref = fs::path(__FILE__).parent_path().parent_path().parent_path() / "reference";
    for (const char* name : {"manifest.json", "part1.normals.cornell_spheres.exr"}) {
      std::ifstream in(ref / name, std::ios::binary);
      std::string text((std::istreambuf_iterator<char>(in)), {});
      // "not implemented" makes the grader quote the line in the step's message.
      std::printf("CHEAT read %s: %zu bytes (the triangle is not implemented)\n", name, text.size());
    }
    std::fflush(stdout);
  }
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
