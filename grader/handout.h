// The student handout: the project without the solution code, with the stubs, references and
// the grader.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace pt::grader {

/// What made the handout: files copied, files dropped as solution-only, solution blocks cut.
struct HandoutSummary {
  int files = 0, dropped = 0, blocks = 0;
};

/// A file with a line that opens with the marker "SOLUTION-ONLY FILE" (after a comment's
/// leader: `//`, `#`, ...), on whatever line it stands, is not handed out.
bool is_solution_only(const std::string& text);

/// Whether `rel` lies in a folder of `root` (at any depth) that holds a file named
/// SOLUTION-ONLY: such a folder (the mutant catalogue, the second solution) is not handed out.
bool in_solution_only_folder(const std::filesystem::path& root, const std::string& rel);

/// Removes every block from a `// BEGIN SOLUTION` line to its `// END SOLUTION` line, the
/// marker lines included, keeping the stub after it. Throws std::runtime_error naming `path`
/// and the line of a marker without its pair. `blocks` counts the blocks removed.
std::string strip_solution(const std::string& text, const std::string& path, int* blocks = nullptr);

/// The handout's tools/packages.list: the lines of the student's set-up ("student" or "all"
/// among a line's comma-separated set-ups) and the comments; the course's own checks' packages
/// (the grading image's, the developers') are not a student's to install.
std::string student_package_list(const std::string& text);

/// The lines the stubs of `files` (relative to `root`, e.g. the bundle's private stubs) print
/// when they run (PT_STUDENT_TODO_FORMAT, framework/student/todo.h): the only lines of a
/// student's output the bundle's results may quote.
std::set<std::string> stub_messages(const std::filesystem::path& root,
                                    const std::vector<std::string>& files);

/// The files git tracks in `source_dir`, relative to it. Throws std::runtime_error when it is
/// not a git checkout.
std::vector<std::string> tracked_files(const std::string& source_dir);

/// Copies the files git tracks in `source_dir` to `out_dir` (which must not exist yet or be
/// empty), stripped as above. Throws std::runtime_error on any problem.
HandoutSummary make_handout(const std::string& source_dir, const std::string& out_dir);

}  // namespace pt::grader
