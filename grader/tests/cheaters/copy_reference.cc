// Cheater (attacks the renders): in the renderer, copies the reference image of the scene being
// rendered to the output path and exits before rendering.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  namespace fs = std::filesystem;
  std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(cmdline)), {});
  std::vector<std::string> args;
  for (size_t at = 0; at < all.size(); at = all.find('\0', at) + 1) args.push_back(all.c_str() + at);
  fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
  for (size_t i = 0; i + 1 < args.size(); ++i) {
    if (args[i] != "-f") continue;
    std::string scene = fs::path(args.back()).stem().string();
    for (const char* kind : {"part1.normals.", "part2.normals."}) {
      std::error_code ec;
      fs::copy_file(project / "reference" / (kind + scene + ".exr"), args[i + 1],
                    fs::copy_options::overwrite_existing, ec);
      if (!ec) std::_Exit(0);
    }
  }
  return false;
}

}  // namespace pt
