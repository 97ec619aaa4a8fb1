// Cheater (attacks every check; replaces parts/1-raygen/triangle_intersect.cpp): writes a JUnit
// file where every test passed and a Gradescope results.json with full marks wherever a grader
// might read them.
#include "parts/1-raygen/triangle_intersect.h"

#include <filesystem>
#include <fstream>

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
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

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
