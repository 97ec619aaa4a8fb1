// A scratch copy of the project that instructor commands may change and build (a mutant applied,
// the second solution's patches), so the instructor's own tree is never touched.
#pragma once

#include <string>
#include <vector>

namespace pt::grader {

/// A copy of the files git tracks in a source tree, kept in its own folder with a build tree
/// inside it (`root/build`, laid out like the original so the compiler cache's relative paths
/// match and an unchanged file is a cache hit). Syncing copies only files whose bytes differ, so
/// the build tree stays incremental: after a patch is undone only the patched files rebuild.
class ScratchTree {
 public:
  /// A scratch tree of `source_dir` at `root` (made on first sync).
  ScratchTree(std::string source_dir, std::string root);

  /// Makes the copy equal to the source (every tracked file, byte for byte; files the copy has
  /// beyond them stay). Returns how many files were written. Throws std::runtime_error naming
  /// the folder when the source is not a git checkout or a file cannot be copied.
  int sync();

  /// Applies a patch (git's unified diff, paths from the project root) to the copy. Throws
  /// std::runtime_error with git's message, naming the patch, when it does not apply.
  void apply(const std::string& patch_file);

  /// Puts back the source's version of every file the last applies changed.
  void restore();

  /// Configures `root/build` (Release, Ninja, the compiler cache), once; `cmake_args` are added
  /// the first time. Throws std::runtime_error with CMake's output on failure.
  void configure(const std::vector<std::string>& cmake_args = {});

  const std::string& root() const { return root_; }
  std::string build_dir() const { return root_ + "/build"; }
  const std::string& source_dir() const { return source_; }

 private:
  std::string source_, root_;
  std::vector<std::string> touched_;  ///< files changed by apply() since the last restore()
};

/// The files a unified diff changes (its `+++ b/PATH` lines), relative to the project root.
std::vector<std::string> patched_files(const std::string& patch_text);

}  // namespace pt::grader
