// Cheater (attacks the renders): runs `grader --make-reference` from inside a test, so the
// references become renders of this (empty) sphere and the graded renders match them.
#include "parts/1-raygen/sphere_intersect.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  namespace fs = std::filesystem;
  if (!std::getenv("CHEAT_REMAKING")) {
    setenv("CHEAT_REMAKING", "1", 1);
    fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
    for (fs::path grader : {project / "build" / "grader" / "grader",
                            project.parent_path().parent_path() / "pt" / "build" / "grader" / "grader"}) {
      if (!fs::exists(grader)) continue;
      std::string command = grader.string() + " --source " + project.string() +
                            " --make-reference --part 1 > /dev/null 2>&1";
      if (std::system(command.c_str()) == 0) break;
    }
  }
  return false;
}

}  // namespace pt
