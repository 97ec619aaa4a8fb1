// The Gradescope autograder bundle: the zip an instructor uploads (setup.sh, run_autograder and
// the instructor's tree), and what run_autograder does with a submission's files.
#pragma once

#include <string>
#include <vector>

namespace pt::grader {

/// The files that hold student functions: every file under parts/ outside tests/ with a
/// `// BEGIN SOLUTION` marker, relative to the project, sorted. The project's own markers are
/// the list, so it is never typed twice.
std::vector<std::string> student_files(const std::string& source_dir);

/// What was taken from a submission.
struct SubmissionIntake {
  std::vector<std::string> taken;    ///< student files found and copied
  std::vector<std::string> missing;  ///< not in the submission: graded as the handout's stub
  /// "file: why" (a link, a file too big, two candidates), the file by the project's name: the
  /// submission's own paths are the student's text and never reach the results
  std::vector<std::string> refused;
  std::vector<std::string> ignored;  ///< other files in the submission, not graded (counted only)
  /// What a student reads at the top of the results: what was graded, what was missing.
  std::string summary() const;
};

/// Copies each of `files` from `submission_dir` into `project_dir`: the file at its path in
/// the project (parts/3-direct/direct_lighting.cpp), or anywhere in the submission under that
/// path (a whole repository uploaded), or a file of the same name when exactly one has it (a
/// flat upload). A file the submission lacks, or that is refused (a symbolic link, over 1 MB,
/// not a regular file), gets the stub from `stub_dir` instead. Never throws for what a
/// submission holds; throws std::runtime_error when the grader cannot write the project.
SubmissionIntake take_submission(const std::vector<std::string>& files,
                                 const std::string& submission_dir,
                                 const std::string& project_dir, const std::string& stub_dir);

/// What a bundle holds.
struct BundleSummary {
  int project_files = 0;
  int shared_files = 0;  ///< course scenes and ray sets included
  long long bytes = 0;   ///< of the zip
};

/// Writes OUT_ZIP: setup.sh and run_autograder (from grader/bundle/ of the project), the files
/// git tracks in `source_dir` (but website/) under project/, and what the tests read beside it
/// (`source_dir`/../shared/scenes/cs184 and ../shared/rays) under shared/. Throws
/// std::runtime_error on a failure, and first when either shared folder is missing (a bundle
/// without them would skip checks on Gradescope).
BundleSummary make_gradescope_bundle(const std::string& source_dir, const std::string& out_zip);

}  // namespace pt::grader
