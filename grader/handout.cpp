#include "grader/handout.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "grader/process/child_process.h"
#include "framework/student/todo.h"
#include "framework/text/text_file.h"
#include "grader/handout_readme.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

std::string trimmed(const std::string& line) {
  size_t a = line.find_first_not_of(" \t\r");
  size_t b = line.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : line.substr(a, b - a + 1);
}

}  // namespace

bool in_solution_only_folder(const fs::path& root, const std::string& rel) {
  for (fs::path dir = fs::path(rel).parent_path(); !dir.empty(); dir = dir.parent_path())
    if (fs::exists(root / dir / "SOLUTION-ONLY")) return true;
  return false;
}

bool is_solution_only(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    // The marker opens a comment (or, in a patch, the line): a line that only mentions it (a
    // string, a sentence of prose) is no marker.
    size_t at = line.find_first_not_of(" \t/#*;-");
    if (at != std::string::npos && line.compare(at, 18, "SOLUTION-ONLY FILE") == 0) return true;
  }
  return false;
}

std::set<std::string> stub_messages(const fs::path& root, const std::vector<std::string>& files) {
  static const std::regex todo(R"re(PT_STUDENT_TODO\(\s*"([^"]*)"\s*,\s*"([^"]*)"\s*\))re");
  std::set<std::string> messages;
  for (const std::string& rel : files) {
    std::istringstream in(read_text_file(root / rel));
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      std::smatch m;
      if (!std::regex_search(line, m, todo)) continue;
      char text[512];
      std::snprintf(text, sizeof text, PT_STUDENT_TODO_FORMAT, m[1].str().c_str(),
                    m[2].str().c_str(), rel.c_str(), number);
      messages.insert(text);
    }
  }
  return messages;
}

std::string strip_solution(const std::string& text, const std::string& path, int* blocks) {
  std::istringstream in(text);
  std::string out, line;
  int number = 0, begin_line = 0, count = 0;
  bool inside = false;
  while (std::getline(in, line)) {
    ++number;
    std::string t = trimmed(line);
    if (t == "// BEGIN SOLUTION") {
      if (inside)
        throw std::runtime_error(path + ":" + std::to_string(number) +
                                 ": BEGIN SOLUTION inside the block opened at line " +
                                 std::to_string(begin_line));
      inside = true;
      begin_line = number;
      continue;
    }
    if (t == "// END SOLUTION") {
      if (!inside)
        throw std::runtime_error(path + ":" + std::to_string(number) +
                                 ": END SOLUTION without a BEGIN SOLUTION before it");
      inside = false;
      ++count;
      continue;
    }
    if (!inside) out += line + "\n";
  }
  if (inside)
    throw std::runtime_error(path + ":" + std::to_string(begin_line) +
                             ": BEGIN SOLUTION is never closed by END SOLUTION");
  if (blocks) *blocks += count;
  // A file that did not end in a newline keeps it that way.
  if (!text.empty() && text.back() != '\n' && !out.empty()) out.pop_back();
  return out;
}

std::vector<std::string> tracked_files(const std::string& source_dir) {
  ChildResult files = run_child({"git", "-C", fs::absolute(source_dir).string(), "ls-files", "-z"},
                                60.0, {}, 64 << 20);
  if (!files.ok())
    throw std::runtime_error(source_dir + ": git ls-files " + files.describe() +
                             " (the handout, the bundle and the scratch trees are copied from a git checkout)\n" +
                             files.output);
  std::vector<std::string> list;
  std::string_view all = files.output;
  for (size_t start = 0; start < all.size();) {
    size_t end = all.find('\0', start);
    if (end == std::string_view::npos) end = all.size();
    if (end > start) list.emplace_back(all.substr(start, end - start));
    start = end + 1;
  }
  return list;
}

std::string student_package_list(const std::string& text) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string name, setups;
    words >> name >> setups;
    bool keep = name.empty() || name[0] == '#';
    for (std::istringstream list(setups); !keep && std::getline(list, name, ',');)
      keep = name == "student" || name == "all";
    if (keep) out += line + "\n";
  }
  return out;
}

HandoutSummary make_handout(const std::string& source_dir, const std::string& out_dir) {
  fs::path src = fs::absolute(source_dir), dst = fs::absolute(out_dir);
  if (fs::exists(dst) && !fs::is_empty(dst))
    throw std::runtime_error(out_dir + ": exists and is not empty; the handout needs a new folder");
  HandoutSummary summary;
  for (const std::string& rel : tracked_files(source_dir)) {
    fs::path from = src / rel;
    if (!fs::is_regular_file(from)) continue;  // deleted in the work tree, or a submodule
    if (rel == "README.md") continue;  // the instructor's: the student's is written below
    if (in_solution_only_folder(src, rel)) {
      ++summary.dropped;
      continue;
    }
    std::string text = read_text_file(from);
    std::string ext = from.extension().string();
    bool source = ext == ".cpp" || ext == ".h" || ext == ".hpp" || ext == ".cc";
    if (is_solution_only(text)) {
      ++summary.dropped;
      continue;
    }
    if (source) text = strip_solution(text, rel, &summary.blocks);
    if (rel == "tools/packages.list") text = student_package_list(text);
    fs::path to = dst / rel;
    fs::create_directories(to.parent_path());
    std::ofstream out(to, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(to.string() + ": cannot be written");
    fs::permissions(to, fs::status(from).permissions());
    ++summary.files;
  }
  write_student_readme(src.string(), dst.string());
  ++summary.files;
  return summary;
}

}  // namespace pt::grader
