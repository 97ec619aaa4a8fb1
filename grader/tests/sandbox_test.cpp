// The sandbox the student's code runs in: as root, a user of its own that cannot read the
// grader's files nor write outside its scratch folder; and a render's file is read only if the
// render wrote it itself.
#include "grader/sandbox.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"

namespace pt::grader {
namespace {

/// A uid slot of this test process's own: ctest runs these tests side by side (-j2), and as root
/// a sandbox ends every process of its uid when a check ends, so two tests sharing a slot would
/// end each other's children (a test failed that way at random).
int own_slot() { return 1000 + int(::getpid() % 30000); }

TEST(GraderSandbox, ARenderFileMustBeTheRendersOwn) {
  test::TempFolder dir("pt-sandbox-output");
  Sandbox unprotected;
  std::filesystem::path real = dir.write("real.exr", "x");
  EXPECT_EQ(check_scratch_output(real.string(), unprotected), "");
  std::filesystem::path link = dir.path() / "link.exr";
  std::filesystem::create_symlink(real, link);
  EXPECT_NE(check_scratch_output(link.string(), unprotected).find("symbolic link"),
            std::string::npos);
  std::filesystem::path hard = dir.path() / "hard.exr";
  std::filesystem::create_hard_link(real, hard);
  EXPECT_NE(check_scratch_output(hard.string(), unprotected).find("hard link"), std::string::npos);
  EXPECT_NE(check_scratch_output((dir.path() / "none.exr").string(), unprotected), "");
}

TEST(GraderSandbox, AsRootTheStudentsUserCannotReadTheGradersFiles) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root to switch users";
  test::TempFolder dir("pt-sandbox-user");
  std::filesystem::path secret = dir.write("manifest.json", "{\"crc32\": \"secret\"}");
  std::filesystem::permissions(secret, std::filesystem::perms(0600));
  Sandbox sandbox = Sandbox::standard((dir.path() / "scratch").string(), own_slot());
  ASSERT_TRUE(sandbox.protects());
  std::string scratch = sandbox.make_scratch("read");
  ChildResult r = run_child({"cat", secret.string()}, sandbox.options(scratch, 10.0));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.output.find("secret"), std::string::npos);
  ChildResult w = run_child({"sh", "-c", "echo x > " + (dir.path() / "outside").string()},
                            sandbox.options(scratch, 10.0));
  EXPECT_FALSE(w.ok());
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "outside"));
  ChildResult inside = run_child({"sh", "-c", "echo x > mine && cat mine"},
                                 sandbox.options(scratch, 10.0));
  EXPECT_TRUE(inside.ok()) << inside.describe() << inside.output;
}

}  // namespace
}  // namespace pt::grader
