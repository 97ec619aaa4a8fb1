#include "grader/handout_readme.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "framework/text/text_file.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

bool is_relative_target(const std::string& target) {
  if (target.empty() || target[0] == '#' || target[0] == '/') return false;
  const size_t colon = target.find(':'), slash = target.find('/');
  return colon == std::string::npos || (slash != std::string::npos && slash < colon);
}

std::string rebase_one(const std::string& target, const fs::path& from_dir, const fs::path& to_dir) {
  const size_t hash = target.find('#');
  const std::string file = target.substr(0, hash), anchor = hash == std::string::npos ? "" : target.substr(hash);
  const fs::path resolved = (from_dir / file).lexically_normal();
  std::string out = resolved.lexically_relative(to_dir).generic_string();
  if (out.empty()) out = ".";
  return out + anchor;
}

}  // namespace

std::string rebase_links(const std::string& markdown, const std::string& from, const std::string& to) {
  const fs::path from_dir = fs::path(from).parent_path(), to_dir = fs::path(to).parent_path();
  std::string out;
  bool fenced = false;
  size_t pos = 0;
  while (pos < markdown.size()) {
    size_t end = markdown.find('\n', pos);
    if (end == std::string::npos) end = markdown.size();
    std::string line = markdown.substr(pos, end - pos);
    const size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) fenced = !fenced;
    if (!fenced) {
      std::string rebuilt;
      bool code = false;
      for (size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '`') code = !code;
        if (!code && line[i] == ']' && i + 1 < line.size() && line[i + 1] == '(') {
          const size_t close = line.find(')', i + 2);
          if (close != std::string::npos) {
            const std::string target = line.substr(i + 2, close - i - 2);
            rebuilt += "](" + (is_relative_target(target) ? rebase_one(target, from_dir, to_dir) : target) + ")";
            i = close;
            continue;
          }
        }
        rebuilt += line[i];
      }
      line = rebuilt;
    }
    out += line;
    if (end < markdown.size()) out += '\n';
    pos = end + 1;
  }
  return out;
}

void write_student_readme(const std::string& source_dir, const std::string& out_dir) {
  const fs::path from = fs::path(source_dir) / kStudentReadme;
  if (!fs::is_regular_file(from))
    throw std::runtime_error(from.string() + ": the student's README is missing");
  const std::string text = rebase_links(read_text_file(from), kStudentReadme, "README.md");
  const fs::path to = fs::path(out_dir) / "README.md";
  std::ofstream out(to, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(to.string() + ": cannot be written");
}

}  // namespace pt::grader
