// What the grader refuses or warns about in a tree: re-made references in a handout, and
// grading binaries older than their sources.
#pragma once

#include <string>
#include <vector>

namespace pt::grader {

/// Whether `source_dir` holds the complete solution: some file under parts/ still has a
/// `// BEGIN SOLUTION` block. A handout has none (the handout tool cut them all).
bool has_solution(const std::string& source_dir);

/// The source files (.cpp, .h under parts/, pipeline/, framework/, app/ of `source_dir`,
/// relative to it) modified after the oldest of `binaries`; a binary that does not exist
/// counts as infinitely old. Empty when every binary is newer than every source.
std::vector<std::string> sources_newer_than(const std::string& source_dir,
                                            const std::vector<std::string>& binaries);

/// The binaries `grader --part N` runs from `build_dir`: the renderer and part N's test
/// executables (named partN_*).
std::vector<std::string> part_binaries(const std::string& build_dir, const std::string& pathtracer,
                                       int part);

/// The warning for --no-build, or "" when nothing is stale: names up to five files.
std::string stale_warning(const std::vector<std::string>& stale);

}  // namespace pt::grader
