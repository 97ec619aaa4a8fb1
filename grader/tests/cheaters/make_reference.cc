// Cheater (attacks the renders; replaces parts/1-raygen/triangle_intersect.cpp): runs
// `grader --make-reference` from inside a test, so the references become renders of this
// (empty) triangle test and the graded renders match them.
#include "parts/1-raygen/triangle_intersect.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
  namespace fs = std::filesystem;
  if (!std::getenv("CHEAT_REMAKING")) {
    setenv("CHEAT_REMAKING", "1", 1);
    fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
    for (fs::path grader : {project / "build" / "grader" / "grader"}) {
      if (!fs::exists(grader)) continue;
      std::string command = grader.string() + " --source " + project.string() +
                            " --make-reference --part 1 > /dev/null 2>&1";
      if (std::system(command.c_str()) == 0) break;
    }
  }
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
