// The handout's own README: the student's page (docs/handout/README.md) at the handout's root.
#pragma once

#include <string>

namespace pt::grader {

/// Where the student's README lives in the instructor's tree.
inline constexpr const char* kStudentReadme = "docs/handout/README.md";

/// `markdown`, a page at `from` (a path relative to the project's root), with every relative
/// link target rewritten so that it resolves from `to` instead: `../../parts/x.cpp` in
/// docs/handout/README.md becomes `parts/x.cpp` at the root. Absolute URLs, anchors and links
/// inside code spans and fenced blocks are left as they are.
std::string rebase_links(const std::string& markdown, const std::string& from,
                         const std::string& to);

/// Writes the student's README (`source_dir`/docs/handout/README.md, links rebased) as
/// `out_dir`/README.md, in place of the instructor's. Throws std::runtime_error when the
/// student's README is missing.
void write_student_readme(const std::string& source_dir, const std::string& out_dir);

}  // namespace pt::grader
