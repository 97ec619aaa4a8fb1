#include "grader/handout_guard.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace fs = std::filesystem;

namespace pt::grader {

bool has_solution(const std::string& source_dir) {
  const fs::path parts = fs::path(source_dir) / "parts";
  std::error_code ec;
  for (fs::recursive_directory_iterator it(parts, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    if (!it->is_regular_file() || (p.extension() != ".cpp" && p.extension() != ".h")) continue;
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);) {
      const size_t a = line.find_first_not_of(" \t");
      if (a != std::string::npos && line.compare(a, 17, "// BEGIN SOLUTION") == 0) return true;
    }
  }
  return false;
}

std::vector<std::string> sources_newer_than(const std::string& source_dir,
                                            const std::vector<std::string>& binaries) {
  std::error_code ec;
  fs::file_time_type oldest = fs::file_time_type::max();
  for (const std::string& b : binaries) {
    const fs::file_time_type t = fs::last_write_time(b, ec);
    oldest = ec ? fs::file_time_type::min() : std::min(oldest, t);
  }
  std::vector<std::string> stale;
  for (const char* layer : {"parts", "pipeline", "framework", "app"}) {
    const fs::path dir = fs::path(source_dir) / layer;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      const fs::path& p = it->path();
      if (!it->is_regular_file() || (p.extension() != ".cpp" && p.extension() != ".h")) continue;
      std::error_code tec;
      const fs::file_time_type t = fs::last_write_time(p, tec);
      if (!tec && t > oldest)
        stale.push_back(p.lexically_relative(source_dir).generic_string());
    }
  }
  return stale;
}

std::vector<std::string> part_binaries(const std::string& build_dir, const std::string& pathtracer,
                                       int part) {
  std::vector<std::string> out{pathtracer};
  const std::string prefix = "part" + std::to_string(part) + "_";
  std::error_code ec;
  for (fs::directory_iterator it(fs::path(build_dir) / "parts", ec), end; !ec && it != end;
       it.increment(ec))
    if (it->is_regular_file() && it->path().filename().string().rfind(prefix, 0) == 0 &&
        it->path().extension().empty())
      out.push_back(it->path().string());
  return out;
}

std::string stale_warning(const std::vector<std::string>& stale) {
  if (stale.empty()) return "";
  std::string s = "grader: warning: --no-build, but " + std::to_string(stale.size()) +
                  " source file(s) changed after the binaries were built, so you would be "
                  "grading old code (drop --no-build to rebuild):";
  for (size_t i = 0; i < stale.size() && i < 5; ++i) s += "\n    " + stale[i];
  if (stale.size() > 5) s += "\n    ... and " + std::to_string(stale.size() - 5) + " more";
  return s + "\n";
}

}  // namespace pt::grader
