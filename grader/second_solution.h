// The second correct solution (grader/second_solution/): the complete solution written another
// way (other random-number order, other ray-sphere and ray-triangle tests), made in a scratch
// tree, so that correct code of another shape can be graded and measured for false failures.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace pt::grader {

/// The patches that turn the complete solution into the second one, in the order they apply.
std::vector<std::string> second_solution_patches(const std::string& source_dir);

/// Makes (or brings up to date) the second solution's scratch tree at `root`: the source's
/// tracked files, every patch applied, a configured build tree. Returns the tree's folder.
/// Throws std::runtime_error naming the patch or the step that failed.
std::string make_second_solution(const std::string& source_dir, const std::string& root,
                                 std::ostream& log);

/// Builds `targets` in a configured tree's build folder with -j `jobs`; throws with the
/// build's last lines on failure.
void build_targets(const std::string& build_dir, const std::vector<std::string>& targets, int jobs);

}  // namespace pt::grader
