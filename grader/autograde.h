// What the Gradescope bundle's scripts run: `grader autograde-setup` once when the image is built
// (after setup.sh built the instructor's tree), `grader autograde` once per submission. Both take
// the root folder (/autograder on Gradescope), so the same bundle runs under any folder.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grader/sandbox.h"

namespace pt::grader {

/// Where everything is under the root folder.
struct AutogradeLayout {
  std::filesystem::path root;        ///< /autograder
  std::filesystem::path project;     ///< root/source/project: the instructor's tree
  std::filesystem::path submission;  ///< root/submission: the student's upload
  std::filesystem::path results;     ///< root/results/results.json
  /// root/source/project/build: the build of the instructor's tree, where a developer's is, so
  /// a compiler cache keyed on relative paths serves it (CI)
  std::filesystem::path build;
  std::filesystem::path private_dir; ///< root/pt/private: what grading trusts (0711, files 0600)
  std::filesystem::path scratch;     ///< root/pt/scratch: the student processes' scratch folders

  static AutogradeLayout under(const std::string& root);
  std::filesystem::path solution() const { return private_dir / "solution"; }
  std::filesystem::path stubs() const { return private_dir / "stubs"; }
  std::filesystem::path grader() const { return private_dir / "grader"; }
  std::filesystem::path student_list() const { return private_dir / "student_files.txt"; }
};

/// After the instructor's tree is configured and its grader built: writes the student-file list,
/// the stubs and a copy of `grader_exe` to the private folder, puts the stubs in place of the
/// solution in the tree, builds what grading runs (the judges, the complete solution's renderer
/// and every object the probes link) with `jobs` jobs, and sets the permissions that keep the
/// references, the manifest, the solution, the judges and the results from the student's user.
/// Throws std::runtime_error on a failure.
void autograde_setup(const std::string& root, const std::string& grader_exe, int jobs);

/// How one run of `grader autograde` differs from Gradescope's: tighter limits for a test run
/// of the bundle (CI's cheater cases), and where `grader batch` puts a submission's run. Every
/// zero or empty field keeps the standard.
struct AutogradeTuning {
  double max_check_seconds = 0.0;  ///< caps every test's and render's wall time
  /// Quote any "not implemented" line of the student's output, not only the handout's stub
  /// lines: CI's cheater runs, whose attacks say on such a line what they got. Never Gradescope.
  bool quote_student_lines = false;
  size_t disk_bytes = 0;           ///< the disk a check may fill
  int jobs = 0;                    ///< tests run at once (0: one per core)
  int build_jobs = 2;              ///< the student's build's jobs
  int slot = 0;                    ///< the first of the uids the run uses is 60000 + slot
  std::string submission;          ///< instead of root/submission
  std::string results;             ///< instead of root/results/results.json
  /// A copy of the set-up tree to grade in instead of root/source/project: mounted over it in a
  /// mount namespace of this process's own, so that the build tree's absolute paths still hold
  /// and runs side by side never share a build (grader batch).
  std::string tree;
};

/// Mounts `tree` over `project` in a new mount namespace of this process (and its children):
/// needs root (CAP_SYS_ADMIN). Returns "" on success, else why not.
std::string mount_tree_over(const std::string& tree, const std::string& project);

/// Grades root/submission into root/results/results.json: the intake, the student's build as
/// the sandbox's user, then every part in `parts` (all when empty). Always writes the results
/// (a submission that is missing files or does not compile gets a result that says so).
/// Returns 0 when results were written.
int autograde(const std::string& root, const std::vector<int>& parts,
              const AutogradeTuning& tuning = {});

/// The build tree as a part's compile has it: everything but the secret folder the user `uid`'s
/// (-1: owners kept), folders 0755, files 0644. close_build_after_compile puts it back: root's
/// (when `given`), folders and programs 0711, files 0600, shared libraries 0755.
void open_build_for_compile(const AutogradeLayout& L, long uid);
void close_build_after_compile(const AutogradeLayout& L, bool given);

/// The proof autograde-setup ends with: takes fingerprints of the solution's objects (the
/// secret folder's pt_solution_part*_obj) and walks, as a student's user, every file of the root,
/// of the shared writable places and of the set-up user's home, once as grading leaves the tree
/// and once as a part's compile has it. Returns one line of what it walked; throws naming the
/// files when any that user can open carries a fingerprint.
std::string check_no_solution_readable(const AutogradeLayout& L);

/// Gives every file under `dir` (itself included, links not followed) to `uid`:`gid`.
void give_tree(const std::filesystem::path& dir, long uid, long gid);

}  // namespace pt::grader
