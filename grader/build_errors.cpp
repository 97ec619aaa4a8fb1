#include "grader/build_errors.h"

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

/// The grader's word for what an error line says: the first kind whose phrase it holds. The
/// phrases are the compiler's and the linker's own; only the kind reaches the results.
std::string kind_of(const std::string& said) {
  static const std::vector<std::pair<const char*, const char*>> kinds = {
      {"Permission denied", "an #include of a file it may not read (Permission denied)"},
      {"No such file or directory", "an #include of a file that is not there"},
      {"#error", "an #error directive"},
      {"static assertion failed", "a static_assert that fails"},
      {"undefined reference", "a function declared and called but never defined (the link)"},
      {"multiple definition", "a function defined twice (the link)"},
      {"was not declared", "a name that is not declared"},
      {"does not name a type", "a name that is not declared"},
      {"has not been declared", "a name that is not declared"},
      {"has no member", "no member of that name"},
      {"no matching", "no function matches the call"},
      {"redefinition", "a second definition"},
      {"conver", "a value of the wrong type"},
      {"expected", "a syntax error (the compiler expected something else)"},
  };
  for (const auto& [phrase, kind] : kinds)
    if (said.find(phrase) != std::string::npos) return kind;
  return "an error";
}

/// The project's name of `path` (absolute, or relative to the project), when it is a file of the
/// project; else "a file" (a #line directive can name any file, and a name is text of its own).
std::string project_file(const std::string& path, const fs::path& project) {
  std::error_code ec;
  fs::path p = fs::path(path).is_absolute() ? fs::path(path) : project / path;
  p = fs::weakly_canonical(p, ec);
  const fs::path root = fs::weakly_canonical(project, ec);
  const fs::path rel = p.lexically_relative(root);
  if (ec || rel.empty() || *rel.begin() == ".." || !fs::is_regular_file(p, ec)) return "a file";
  return rel.generic_string();
}

}  // namespace

std::string build_errors(const std::string& output, const std::string& project) {
  // "FILE:LINE:COLUMN: error: WHAT" and "fatal error:" from the compiler; the linker's
  // "undefined reference" and "multiple definition" lines, and a program's own "PROGRAM: fatal
  // error:", have no line of their own.
  static const std::regex located("^(.+?):([0-9]+):([0-9]+): (fatal )?error: (.*)$");
  std::vector<std::string> shown;
  int errors = 0;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    std::string where, said;
    if (std::regex_match(line, m, located)) {
      const long l = std::atol(m[2].str().substr(0, 9).c_str());
      const long c = std::atol(m[3].str().substr(0, 9).c_str());
      where = project_file(m[1].str(), project);
      where += m[2].length() <= 9 && l <= kBuildLineShown ? ":" + std::to_string(l) : ":(a line)";
      if (m[3].length() <= 9 && c <= kBuildColumnShown) where += ":" + std::to_string(c);
      said = m[5].str();
    } else if (line.find("undefined reference") != std::string::npos ||
               line.find("multiple definition") != std::string::npos) {
      where = "the link";
      said = line;
    } else if ((line.find(": error: ") != std::string::npos ||
                line.find(": fatal error: ") != std::string::npos) &&
               line.find("ld returned") == std::string::npos) {
      // An error of no line ("cc1plus: fatal error: FILE: Permission denied" for an #include
      // found by __has_include but not readable).
      where = "the compiler";
      said = line;
    } else {
      continue;
    }
    ++errors;
    if (int(shown.size()) < kBuildErrorsShown) shown.push_back(where + ": " + kind_of(said));
  }
  std::string s;
  for (const std::string& e : shown) s += "    " + e + "\n";
  if (errors == 0)
    s += "    (no error line the grader knows: the build stopped for another reason)\n";
  else if (errors > int(shown.size()))
    s += "    " + (errors > 99 ? std::string("more than 99") : std::to_string(errors)) +
         " errors in all\n";
  s += "    (build it yourself to read the compiler's own words: the results never quote them)\n";
  return s;
}

}  // namespace pt::grader
