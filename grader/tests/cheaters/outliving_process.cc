// Cheater (attacks every check): forks a process that leaves the process group and session
// (setsid) and, for two minutes, keeps rewriting the JUnit and results files with full marks,
// after the check that started it has ended.
#include "parts/1-raygen/sphere_intersect.h"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

namespace pt {

bool intersect_sphere(const Ray&, const Sphere&, float*) {
  namespace fs = std::filesystem;
  static bool started = false;
  if (!started && !std::getenv("CHEAT_DAEMON")) {
    started = true;
    setenv("CHEAT_DAEMON", "1", 1);
    if (fork() == 0) {
      setsid();
      if (fork() != 0) _exit(0);
      // A daemon holds no descriptor of the test's: nobody waits for its output to end.
      int null = open("/dev/null", O_RDWR);
      for (int fd = 0; fd < 1024; ++fd)
        if (fd != null) close(fd);
      dup2(null, 0), dup2(null, 1), dup2(null, 2);
      fs::path project = fs::path(__FILE__).parent_path().parent_path().parent_path();
      auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
      while (std::chrono::steady_clock::now() < until) {
        for (fs::path f : {project / "build" / "grader-out" / "part1-tests.xml",
                           project / "grader-out" / "part1-tests.xml"}) {
          if (fs::exists(f.parent_path()))
            std::ofstream(f) << "<testsuite tests=\"1\" failures=\"0\"><testcase name=\"all\"/></testsuite>\n";
        }
        for (fs::path f : {project.parent_path().parent_path() / "results" / "results.json",
                           project / "results.json"}) {
          if (fs::exists(f)) std::ofstream(f) << "{\"score\": 100, \"tests\": []}\n";
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
      _exit(0);
    }
  }
  return false;
}

}  // namespace pt
