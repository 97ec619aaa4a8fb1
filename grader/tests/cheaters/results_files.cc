// Cheater (attacks every check): writes a JUnit file where every test passed and a Gradescope
// results.json with full marks wherever a grader might read them.
#include "parts/1-raygen/sphere_intersect.h"

#include <filesystem>
#include <fstream>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  namespace fs = std::filesystem;
  fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
  for (fs::path dir : {fs::current_path() / "grader-out", project / "grader-out",
                       project / "build" / "grader-out"}) {
    std::ofstream(dir / "part1-tests.xml")
        << "<testsuite tests=\"1\" failures=\"0\"><testcase name=\"all\" status=\"run\"/></testsuite>\n";
  }
  for (fs::path file : {project.parent_path().parent_path() / "results" / "results.json",
                        fs::current_path() / "results.json"}) {
    std::ofstream(file) << "{\"score\": 100, \"tests\": []}\n";
  }
  return false;
}

}  // namespace pt
