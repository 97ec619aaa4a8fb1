// Cheater (attacks the renders; replaces parts/1-raygen/triangle_intersect.cpp): in the renderer,
// copies the reference image of the scene being rendered to the output path and exits before
// rendering; everywhere else the triangle is not implemented.
#include "parts/1-raygen/triangle_intersect.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
  namespace fs = std::filesystem;
  std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(cmdline)), {});
  std::vector<std::string> args;
  for (size_t at = 0; at < all.size(); at = all.find('\0', at) + 1) args.push_back(all.c_str() + at);
  fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
  for (size_t i = 0; i + 1 < args.size(); ++i) {
    if (args[i] != "-f") continue;
    std::string scene = fs::path(args.back()).stem().string();
    std::error_code ec;
    fs::copy_file(project / "reference" / ("part1.normals." + scene + ".exr"), args[i + 1],
                  fs::copy_options::overwrite_existing, ec);
    if (!ec) std::_Exit(0);
  }
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
