#include "grader/handout_readme.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "framework/text/markdown_links.h"
#include "framework/text/text_file.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

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
  return rewrite_markdown_links(markdown, [&](const std::string& target) {
    return is_relative_link(target) ? rebase_one(target, from_dir, to_dir) : target;
  });
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
