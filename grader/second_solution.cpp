#include "grader/second_solution.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "grader/process/child_process.h"
#include "grader/scratch_tree.h"

namespace fs = std::filesystem;

namespace pt::grader {

std::vector<std::string> second_solution_patches(const std::string& source_dir) {
  fs::path dir = fs::path(source_dir) / "grader" / "second_solution";
  std::vector<std::string> patches;
  if (fs::is_directory(dir))
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".patch") patches.push_back(e.path().string());
  std::sort(patches.begin(), patches.end());
  if (patches.empty())
    throw std::runtime_error(dir.string() + ": no patches (the second solution is the "
                             "instructor's; a handout has none)");
  return patches;
}

std::string make_second_solution(const std::string& source_dir, const std::string& root,
                                 std::ostream& log) {
  ScratchTree tree(source_dir, root);
  int written = tree.sync();
  for (const std::string& p : second_solution_patches(source_dir)) tree.apply(p);
  tree.configure({"-DPT_SOLUTION_DIR=" + tree.source_dir()});
  log << "second solution: " << tree.root() << " (" << written << " files synced, patches applied)\n";
  return tree.root();
}

void build_targets(const std::string& build_dir, const std::vector<std::string>& targets, int jobs) {
  std::vector<std::string> argv = {"cmake", "--build", build_dir, "-j", std::to_string(jobs), "--target"};
  argv.insert(argv.end(), targets.begin(), targets.end());
  ChildResult c = run_child(argv, 3600.0);
  if (!c.ok())
    throw std::runtime_error(build_dir + ": the build " + c.describe() + "\n" + tail_lines(c.output, 20));
}

}  // namespace pt::grader
