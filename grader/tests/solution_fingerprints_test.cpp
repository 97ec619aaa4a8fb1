// The solution's fingerprints: found in what copies or links the solution's code (a program that
// links Part 1, an object's bytes hidden in noise), never in the given code's objects, and, walked
// as another user, in exactly the files that user can open (in a folder it cannot list too).
#include "grader/solution_fingerprints.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"
#include "grader/sandbox.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

const fs::path kBuild = pt::test::binary_dir();

/// The objects of the build's target `target` (its CMakeFiles/TARGET.dir below `dir`).
std::vector<fs::path> objects_of(const fs::path& dir, const std::string& target) {
  std::vector<fs::path> found;
  const fs::path at = dir / "CMakeFiles" / (target + ".dir");
  std::error_code ec;
  for (fs::recursive_directory_iterator it(at, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".o") found.push_back(it->path());
  return found;
}

class SolutionFingerprints : public ::testing::Test {
 protected:
  void SetUp() override {
    part1_ = objects_of(kBuild / "parts", "pt_part1_obj");
    given_ = objects_of(kBuild / "framework", "pt_framework_obj");
    if (part1_.size() < 4 || given_.empty())
      GTEST_SKIP() << "this build has no Part 1 or framework objects to take prints of";
    prints_ = fingerprints_of(part1_, given_);
  }
  std::vector<fs::path> part1_, given_;
  Fingerprints prints_;
};

TEST_F(SolutionFingerprints, PartOneHasPrintsAndTheGivenCodeNone) {
  EXPECT_EQ(prints_.objects, part1_.size());
  EXPECT_GT(prints_.code_bytes, 1000u);
  EXPECT_GT(prints_.by_hash.size(), 20u) << "too few windows to tell Part 1's code by";
  // The given code's own objects: none of them carries a print (they were taken out).
  WalkCount n;
  std::vector<fs::path> roots(given_.begin(), given_.end());
  EXPECT_TRUE(files_carrying(prints_, roots, &n).empty());
  EXPECT_EQ(n.files, given_.size());
}

TEST_F(SolutionFingerprints, AProgramThatLinksPartOneCarriesThem) {
  // A step test links Part 1's objects as they are (tests link without whole-program
  // optimisation), relocated: the windows without a relocated byte are there as compiled.
  const fs::path program = kBuild / "parts" / "part1_step3_triangle_test";
  if (!fs::exists(program)) GTEST_SKIP() << program << " is not built";
  const std::vector<Carrier> found = files_carrying(prints_, {program});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].path, program.string());
}

TEST_F(SolutionFingerprints, CodeHiddenInNoiseIsFoundWhereItIs) {
  test::TempFolder dir("pt-fingerprints");
  // Some bytes of one object's code, 12345 bytes into random noise, in a folder below the root.
  const auto& [hash, entry] = *prints_.by_hash.begin();
  (void)hash;
  std::mt19937 rng(7);
  std::string noise(1 << 16, '\0');
  for (char& c : noise) c = char(rng());
  std::string carrier = noise;
  carrier.replace(12345, kFingerprintBytes,
                  std::string(entry.bytes.begin(), entry.bytes.end()));
  fs::create_directories(dir.path() / "a" / "b");
  std::ofstream(dir.path() / "a" / "b" / "cache-entry", std::ios::binary) << carrier;
  std::ofstream(dir.path() / "a" / "noise", std::ios::binary) << noise;
  // One byte changed: no longer the solution's.
  carrier[12345 + 5] = char(carrier[12345 + 5] ^ 1);
  std::ofstream(dir.path() / "a" / "near-miss", std::ios::binary) << carrier;
  WalkCount n;
  const std::vector<Carrier> found = files_carrying(prints_, {dir.path()}, &n);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].path, (dir.path() / "a" / "b" / "cache-entry").string());
  EXPECT_EQ(found[0].offset, 12345u);
  EXPECT_EQ(found[0].fingerprint, entry.source);
  EXPECT_EQ(n.files, 3u);
}

TEST_F(SolutionFingerprints, AnotherUserFindsOnlyWhatItCanOpen) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root, to walk as another user";
  test::TempFolder dir("pt-fingerprints-as");
  fs::permissions(dir.path(), fs::perms(0755));
  const auto& entry = prints_.by_hash.begin()->second;
  const std::string code(entry.bytes.begin(), entry.bytes.end());
  std::ofstream(dir.path() / "open", std::ios::binary) << "x" + code;
  std::ofstream(dir.path() / "closed", std::ios::binary) << "y" + code;
  fs::permissions(dir.path() / "open", fs::perms(0644));
  fs::permissions(dir.path() / "closed", fs::perms(0600));
  // A folder the user may enter but not list: its readable file can still be opened by name.
  fs::create_directories(dir.path() / "unlisted");
  std::ofstream(dir.path() / "unlisted" / "by-name", std::ios::binary) << "zz" + code;
  fs::permissions(dir.path() / "unlisted" / "by-name", fs::perms(0644));
  fs::permissions(dir.path() / "unlisted", fs::perms(0711));
  WalkCount n;
  const long uid = kFirstStudentUid + kUidsPerSlot * (kSlots - 1);  // a slot's last uid
  std::vector<Carrier> found = files_carrying_as(uid, prints_, {dir.path()}, &n);
  ASSERT_EQ(found.size(), 2u);
  std::sort(found.begin(), found.end(), [](const Carrier& a, const Carrier& b) { return a.path < b.path; });
  EXPECT_EQ(found[0].path, (dir.path() / "open").string());
  EXPECT_EQ(found[0].offset, 1u);
  EXPECT_EQ(found[1].path, (dir.path() / "unlisted" / "by-name").string());
  EXPECT_EQ(found[1].offset, 2u);
  EXPECT_EQ(n.unreadable, 1u);
  // As root, all three.
  EXPECT_EQ(files_carrying(prints_, {dir.path()}).size(), 3u);
}

TEST(SolutionFingerprintsInput, AFileThatIsNoObjectIsNamed) {
  test::TempFolder dir("pt-fingerprints-bad");
  std::ofstream(dir.path() / "notes.o") << "not an object";
  try {
    fingerprints_of({dir.path() / "notes.o"}, {});
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("notes.o: not an ELF64 relocatable object"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace pt::grader
