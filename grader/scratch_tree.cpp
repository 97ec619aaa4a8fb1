#include "grader/scratch_tree.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "grader/process/child_process.h"
#include "framework/text/text_file.h"
#include "grader/handout.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

/// Writes `text` to `to` unless it already holds exactly those bytes (so its time stamp, and
/// the build tree's idea of what is up to date, stay). Returns whether it wrote.
bool write_if_changed(const fs::path& to, const std::string& text, fs::perms perms) {
  std::error_code ec;
  if (fs::is_regular_file(to, ec) && fs::file_size(to, ec) == text.size() &&
      read_text_file(to) == text)
    return false;
  fs::create_directories(to.parent_path());
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(to.string() + ": cannot be written");
  fs::permissions(to, perms);
  return true;
}

}  // namespace

ScratchTree::ScratchTree(std::string source_dir, std::string root)
    : source_(fs::absolute(source_dir).lexically_normal().string()),
      root_(fs::absolute(root).lexically_normal().string()) {
  if (!source_.empty() && source_.back() == '/') source_.pop_back();
  if (!root_.empty() && root_.back() == '/') root_.pop_back();
}

int ScratchTree::sync() {
  fs::create_directories(root_);
  // A repository of its own, so `git apply` inside it never looks for an enclosing one.
  if (!fs::exists(fs::path(root_) / ".git")) {
    ChildResult init = run_child({"git", "init", "-q", root_}, 60.0);
    if (!init.ok()) throw std::runtime_error(root_ + ": git init " + init.describe() + "\n" + init.output);
  }
  // Course scenes are found beside the project (../shared): the copy sees the same ones.
  fs::path shared = fs::path(source_).parent_path() / "shared";
  fs::path link = fs::path(root_).parent_path() / "shared";
  std::error_code ec;
  if (fs::exists(shared) && !fs::exists(fs::symlink_status(link, ec)))
    fs::create_directory_symlink(fs::canonical(shared), link, ec);
  int written = 0;
  for (const std::string& rel : tracked_files(source_)) {
    fs::path from = fs::path(source_) / rel;
    if (!fs::is_regular_file(from)) continue;  // deleted in the work tree, or a submodule
    if (write_if_changed(fs::path(root_) / rel, read_text_file(from), fs::status(from).permissions()))
      ++written;
  }
  touched_.clear();
  return written;
}

void ScratchTree::apply(const std::string& patch_file) {
  std::string text = read_text_file(patch_file);
  std::vector<std::string> files = patched_files(text);
  if (files.empty()) throw std::runtime_error(patch_file + ": no file is patched (no +++ b/ line)");
  ChildResult c = run_child({"git", "-C", root_, "apply", "--whitespace=nowarn",
                             fs::absolute(patch_file).string()}, 60.0);
  if (!c.ok())
    throw std::runtime_error(patch_file + ": does not apply to the tree (git apply " +
                             c.describe() + "):\n" + c.output);
  touched_.insert(touched_.end(), files.begin(), files.end());
}

void ScratchTree::restore() {
  for (const std::string& rel : touched_) {
    fs::path from = fs::path(source_) / rel, to = fs::path(root_) / rel;
    if (fs::is_regular_file(from))
      write_if_changed(to, read_text_file(from), fs::status(from).permissions());
    else
      fs::remove(to);
  }
  touched_.clear();
}

void ScratchTree::configure(const std::vector<std::string>& cmake_args) {
  if (fs::exists(fs::path(build_dir()) / "CMakeCache.txt")) return;
  std::vector<std::string> argv = {"cmake", "-S", root_, "-B", build_dir(), "-G", "Ninja",
                                   "-DCMAKE_BUILD_TYPE=Release",
                                   "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"};
  argv.insert(argv.end(), cmake_args.begin(), cmake_args.end());
  ChildResult c = run_child(argv, 600.0);
  if (!c.ok())
    throw std::runtime_error(build_dir() + ": cmake " + c.describe() + "\n" + tail_lines(c.output, 20));
}

std::vector<std::string> patched_files(const std::string& patch_text) {
  std::vector<std::string> files;
  std::istringstream in(patch_text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("+++ b/", 0) == 0) files.push_back(line.substr(6));
  }
  return files;
}

}  // namespace pt::grader
