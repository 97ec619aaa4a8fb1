// The fuzz target's seed corpus and every reproducer it (or a person) found, run through the
// loader as ordinary tests, so a fixed crash stays fixed in every build, the sanitizer one too:
// each file loads into a scene that keeps its promises or fails with a SceneError naming it.
#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"
#include "fuzz/fuzz_limits.h"
#include "fuzz/scene_invariants.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> files_in(const std::string& folder) {
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(std::string(PT_FUZZ_DIR) + "/" + folder))
    if (e.is_regular_file() && e.path().filename().string()[0] != '.') files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

/// Loads `path` as the fuzz target does (its limits): a scene that keeps every promise, or a
/// SceneError that names the file.
void expect_loads_or_refuses(const std::string& path, bool* loaded) {
  *loaded = false;
  try {
    const Scene s = load_collada(path, [](const std::string&) {}, fuzz::kFuzzLimits);
    EXPECT_EQ(fuzz::scene_invariant_violation(s), "");
    *loaded = true;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
}

TEST(FrameworkFuzzCorpus, EverySeedLoadsIntoASceneThatKeepsItsPromises) {
  const std::vector<std::string> seeds = files_in("seeds");
  ASSERT_GE(seeds.size(), 5u);
  for (const std::string& path : seeds) {
    SCOPED_TRACE(path);
    bool loaded = false;
    expect_loads_or_refuses(path, &loaded);
    EXPECT_TRUE(loaded) << "a seed is meant to be a valid scene";
  }
}

TEST(FrameworkFuzzCorpus, EveryReproducerLoadsOrIsRefusedInBoundedMemory) {
  const std::vector<std::string> found = files_in("reproducers");
  ASSERT_FALSE(found.empty());
  for (const std::string& path : found) {
    SCOPED_TRACE(path);
    bool loaded = false;
    expect_loads_or_refuses(path, &loaded);
  }
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  EXPECT_LT(long(u.ru_maxrss) * 1024, 1L << 30) << "a reproducer took a gigabyte";
}

}  // namespace
}  // namespace pt
