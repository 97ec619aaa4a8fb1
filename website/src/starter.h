// `website init`: a starting write-up with a section per part and the renders each part asks
// for, made from the project's own scenes and the course's where they are present.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pt::web {

/// What `website init` needs to know.
struct StarterOptions {
  std::filesystem::path dir;                      ///< where writeup.md goes
  std::vector<std::filesystem::path> scene_dirs;  ///< where the scenes it names are looked for
  std::filesystem::path convergence_table;        ///< Part 5's table (CSV/JSON), if there is one
  bool force = false;                             ///< replace an existing writeup.md
};

/// The Markdown of the starting write-up; scenes not found in `scene_dirs` are left out with a
/// note saying so, so that what it names can always be rendered.
std::string starter_markdown(const StarterOptions& options);

/// Writes dir/writeup.md (and copies the convergence table beside it). Throws
/// std::runtime_error rather than overwrite a student's write-up without --force.
std::filesystem::path write_starter(const StarterOptions& options);

}  // namespace pt::web
