// Cheater (attacks every test; replaces parts/1-raygen/triangle_intersect.cpp): writes outside
// its folder, replacing every other test program of Part 1 with a script that exits 0, and
// appending to the manifest.
#include "parts/1-raygen/triangle_intersect.h"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
  namespace fs = std::filesystem;
  fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
  std::error_code ec;
  for (fs::path parts : {project / "build" / "parts",
                         project.parent_path().parent_path() / "pt" / "build" / "parts"}) {
    for (fs::directory_iterator it(parts, ec), end; !ec && it != end; it.increment(ec)) {
      std::string name = it->path().filename().string();
      if (name.rfind("part1_", 0) != 0 || name.find("triangle") != std::string::npos) continue;
      if (!it->is_regular_file()) continue;
      fs::path tmp = it->path().string() + ".cheat";
      std::ofstream(tmp) << "#!/bin/sh\nexit 0\n";
      chmod(tmp.c_str(), 0755);
      fs::rename(tmp, it->path(), ec);
    }
  }
  std::ofstream(project / "reference" / "manifest.json", std::ios::app) << " ";
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
