// A child that crashes, hangs or floods its output is reported as such, and the tool that ran it
// (the grader, the write-up's renders) goes on.
#include "grader/process/child_process.h"

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "framework/testing/temp_folder.h"

namespace pt {
namespace {

/// Whether this build runs children under the Linux keeper (PT_LINUX_SANDBOX): what only the
/// keeper does (following what left the group, a user of its own) is checked only then.
constexpr bool kLinuxKeeper = PT_LINUX_SANDBOX != 0;
constexpr const char* kNoKeeper = "built without the Linux keeper (PT_LINUX_SANDBOX off)";

TEST(FrameworkChildProcess, ExitStatusAndOutputAreCaptured) {
  ChildResult r = run_child({"sh", "-c", "echo to-out; echo to-err >&2; exit 3"}, 10.0);
  EXPECT_TRUE(r.started);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.output.find("to-out"), std::string::npos);
  EXPECT_NE(r.output.find("to-err"), std::string::npos);
  EXPECT_EQ(r.describe(), "exited with status 3");
  EXPECT_TRUE(run_child({"true"}, 10.0).ok());
}

TEST(FrameworkChildProcess, ACrashIsNamed) {
  ChildResult r = run_child({"sh", "-c", "kill -SEGV $$"}, 10.0);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.signal, 11);
  EXPECT_NE(r.describe().find("SIGSEGV"), std::string::npos) << r.describe();
}

TEST(FrameworkChildProcess, AHangIsStoppedAtItsLimitWithItsChildren) {
  // The shell starts a sleep of its own: the whole group must go, or the test would wait.
  ChildResult r = run_child({"sh", "-c", "sleep 60; echo never"}, 0.5);
  EXPECT_TRUE(r.timed_out);
  EXPECT_FALSE(r.ok());
  EXPECT_LT(r.seconds, 5.0);
  EXPECT_NE(r.describe().find("time limit"), std::string::npos);
}

TEST(FrameworkChildProcess, FloodedOutputIsCut) {
  ChildResult r = run_child({"sh", "-c", "head -c 3000000 /dev/zero | tr '\\0' x"}, 20.0, {}, 1000);
  EXPECT_TRUE(r.ok()) << r.describe();
  EXPECT_LT(r.output.size(), 1100u);
  EXPECT_NE(r.output.find("output cut"), std::string::npos);
}

TEST(FrameworkChildProcess, SeparateStreamsKeepStdoutForData) {
  ChildResult r = run_child({"sh", "-c", "echo data; echo why >&2; echo more"}, 10.0, {}, 1 << 20,
                            ChildStreams::separate);
  EXPECT_TRUE(r.ok()) << r.describe();
  EXPECT_EQ(r.output, "data\nmore\n");
  EXPECT_EQ(r.errors, "why\n");
  // A hang is stopped whichever way the streams go (the write-up's renders had no limit).
  ChildResult hang = run_child({"sh", "-c", "echo started; sleep 60"}, 0.5, {}, 1 << 20,
                               ChildStreams::separate);
  EXPECT_TRUE(hang.timed_out);
  EXPECT_EQ(hang.output, "started\n");
}

TEST(FrameworkChildProcess, TailLinesKeepsTheLastNonEmptyLines) {
  EXPECT_EQ(tail_lines("a\n\nb\nc\n\n", 2), "b\nc");
  EXPECT_EQ(tail_lines("only", 5), "only");
  EXPECT_EQ(tail_lines("", 3), "");
}

TEST(FrameworkChildProcess, AMissingProgramIsAFailureNotACrash) {
  ChildResult r = run_child({"pt-no-such-program-xyz"}, 5.0);
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.started && r.exit_code == 0);
  EXPECT_NE(r.errors.find("pt-no-such-program-xyz"), std::string::npos) << r.errors;
}

TEST(FrameworkChildProcess, WorkingDirectoryIsUsed) {
  ChildResult r = run_child({"pwd"}, 5.0, "/");
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.output, "/\n");
}

ChildOptions limited(double wall) {
  ChildOptions o;
  o.limits.wall_seconds = wall;
  return o;
}

bool process_exists(pid_t pid) { return kill(pid, 0) == 0 || errno != ESRCH; }

pid_t read_pid(const std::filesystem::path& file) {
  std::ifstream in(file);
  long pid = 0;
  in >> pid;
  return pid_t(pid);
}

TEST(FrameworkChildProcess, ADescendantThatLeftTheGroupIsEndedWithTheChild) {
  if (!kLinuxKeeper) GTEST_SKIP() << kNoKeeper;
  // setsid puts the grandchild in a session and group of its own, out of reach of a group kill;
  // it would write a file after the check, but the keeper (a subreaper) ends it.
  test::TempFolder dir("pt-child-setsid");
  std::filesystem::path pid_file = dir.path() / "pid", late = dir.path() / "late";
  std::string script = "setsid sh -c 'echo $$ > " + pid_file.string() + "; sleep 1; echo x > " +
                       late.string() + "' & sleep 0.3; exit 0";
  ChildResult r = run_child({"sh", "-c", script}, limited(20.0));
  EXPECT_TRUE(r.ok()) << r.describe();
  EXPECT_GE(r.descendants_killed, 1);
  pid_t escaped = read_pid(pid_file);
  ASSERT_GT(escaped, 0);
  EXPECT_FALSE(process_exists(escaped)) << "pid " << escaped << " outlived its check";
  std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  EXPECT_FALSE(std::filesystem::exists(late)) << "a leftover process wrote after the check";
}

TEST(FrameworkChildProcess, ADoubleForkedDaemonIsEndedToo) {
  if (!kLinuxKeeper) GTEST_SKIP() << kNoKeeper;
  test::TempFolder dir("pt-child-daemon");
  std::filesystem::path late = dir.path() / "late";
  std::string script = "( ( sleep 1; echo x > " + late.string() + " ) & ) ; exit 0";
  ChildResult r = run_child({"sh", "-c", script}, limited(20.0));
  EXPECT_TRUE(r.ok()) << r.describe();
  std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  EXPECT_FALSE(std::filesystem::exists(late));
}

TEST(FrameworkChildProcess, CpuTimeIsLimited) {
  ChildOptions o = limited(30.0);
  o.limits.cpu_seconds = 1.0;
  ChildResult r = run_child({"sh", "-c", "while :; do :; done"}, o);
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.timed_out) << "the CPU limit, not the wall limit, must end it";
  EXPECT_TRUE(r.signal == SIGXCPU || r.signal == SIGKILL) << r.describe();
  EXPECT_LT(r.seconds, 15.0);
}

// A SIGKILL that no limit sent (here the child's own; another grader's or the OOM killer's look
// the same) is told apart from the limits' ends: a grader reruns such a check, never scores it.
TEST(FrameworkChildProcess, AKillFromOutsideIsToldApartFromTheLimits) {
  if (!kLinuxKeeper) GTEST_SKIP() << kNoKeeper;
  ChildOptions o = limited(30.0);
  o.limits.cpu_seconds = 20.0;
  ChildResult outside = run_child({"sh", "-c", "kill -9 $$"}, o);
  EXPECT_EQ(outside.signal, SIGKILL) << outside.describe();
  EXPECT_TRUE(outside.killed_from_outside);
  o.limits.cpu_seconds = 1.0;
  ChildResult cpu = run_child({"sh", "-c", "trap '' XCPU; while :; do :; done"}, o);
  EXPECT_FALSE(cpu.ok());
  EXPECT_FALSE(cpu.killed_from_outside) << cpu.describe();
  ChildResult wall = run_child({"sleep", "30"}, limited(0.5));
  EXPECT_TRUE(wall.timed_out);
  EXPECT_FALSE(wall.killed_from_outside);
  ChildResult fine = run_child({"true"}, limited(10.0));
  EXPECT_FALSE(fine.killed_from_outside);
}

TEST(FrameworkChildProcess, AMemoryBombFailsAtTheAddressSpaceLimit) {
  ChildOptions o = limited(60.0);
  o.limits.address_space = size_t(256) << 20;
  // The string doubles until an allocation fails.
  ChildResult r = run_child({"awk", "BEGIN { s = \"x\"; while (1) s = s s }"}, o);
  EXPECT_FALSE(r.ok()) << r.describe();
  EXPECT_FALSE(r.timed_out);
}

TEST(FrameworkChildProcess, FileSizeIsLimited) {
  test::TempFolder dir("pt-child-fsize");
  std::filesystem::path big = dir.path() / "big";
  ChildOptions o = limited(30.0);
  o.limits.file_size = 1 << 20;
  ChildResult r = run_child({"sh", "-c", "head -c 10000000 /dev/zero > " + big.string()}, o);
  EXPECT_FALSE(r.ok()) << r.describe();
  EXPECT_LE(std::filesystem::file_size(big), size_t(1) << 20);
}

TEST(FrameworkChildProcess, FillingTheDiskIsStopped) {
  test::TempFolder dir("pt-child-disk");
  ChildOptions o = limited(30.0);
  o.limits.disk_bytes = 16 << 20;
  o.limits.disk_watch = {dir.path().string()};
  std::string script = "head -c 100000000 /dev/zero > " + (dir.path() / "fill").string() +
                       "; sleep 20";
  ChildResult r = run_child({"sh", "-c", script}, o);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.disk_exceeded) << r.describe();
  EXPECT_LT(r.seconds, 15.0);
}

TEST(FrameworkChildProcess, EnvironmentIsAdded) {
  ChildOptions o = limited(10.0);
  o.environment = {"PT_CHILD_TEST=hello", "HOME=/nonexistent-home"};
  ChildResult r = run_child({"sh", "-c", "echo $PT_CHILD_TEST $HOME"}, o);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.output, "hello /nonexistent-home\n");
}

TEST(FrameworkChildProcess, AKilledKeeperIsAnUnknownStatusAndAFailure) {
  if (!kLinuxKeeper) GTEST_SKIP() << kNoKeeper;
  // Only a child of our own user can do this (its parent is the keeper): no wait status comes
  // back, and that must never read as success.
  ChildResult r = run_child({"sh", "-c", "kill -9 $PPID; exit 0"}, limited(10.0));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.unknown_status) << r.describe();
}

TEST(FrameworkChildProcess, TheTreeEndsWhenTheCallerDies) {
  if (!kLinuxKeeper) GTEST_SKIP() << kNoKeeper;
  // A caller killed in the middle (a grader stopped by its own harness) takes its children's
  // trees with it: the keeper sees its parent go and ends the tree.
  test::TempFolder dir("pt-child-caller");
  std::filesystem::path pid_file = dir.path() / "pid";
  pid_t caller = fork();
  if (caller == 0) {
    run_child({"sh", "-c", "echo $$ > " + pid_file.string() + "; sleep 60"}, limited(120.0));
    _exit(0);
  }
  for (int i = 0; i < 200 && read_pid(pid_file) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  pid_t child = read_pid(pid_file);
  ASSERT_GT(child, 0);
  kill(caller, SIGKILL);
  waitpid(caller, nullptr, 0);
  bool gone = false;
  for (int i = 0; i < 300 && !gone; ++i) {
    gone = !process_exists(child);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(gone) << "the child " << child << " outlived its caller";
}

TEST(FrameworkChildProcess, AnotherUserAndItsProcessLimit) {
  if (!kLinuxKeeper) GTEST_SKIP() << kNoKeeper;
  if (geteuid() != 0) GTEST_SKIP() << "switching users needs root";
  const long nobody = 65534;
  ChildOptions o = limited(30.0);
  o.uid = nobody;
  o.gid = nobody;
  ChildResult id = run_child({"id", "-u"}, o);
  ASSERT_TRUE(id.ok()) << id.describe() << id.output;
  EXPECT_EQ(id.output, "65534\n");
  test::TempFolder dir("pt-child-user");
  std::filesystem::path secret = dir.path() / "secret";
  std::ofstream(secret) << "the answer";
  std::filesystem::permissions(secret, std::filesystem::perms::owner_read |
                                           std::filesystem::perms::owner_write);
  ChildResult read = run_child({"cat", secret.string()}, o);
  EXPECT_FALSE(read.ok());
  EXPECT_EQ(read.output.find("the answer"), std::string::npos);
  // A fork bomb stops at the process limit and is ended whole.
  o.limits.processes = 16;
  ChildResult bomb = run_child({"sh", "-c", "for i in $(seq 100); do sleep 20 & done; wait"}, o);
  EXPECT_FALSE(bomb.timed_out);
  EXPECT_LT(bomb.seconds, 25.0);
}

TEST(FrameworkChildProcess, SwitchingUserWithoutRootIsRefused) {
  if (geteuid() == 0) GTEST_SKIP() << "root may switch";
  ChildOptions o = limited(10.0);
  o.uid = 65534;
  ChildResult r = run_child({"true"}, o);
  EXPECT_FALSE(r.started);
  EXPECT_FALSE(r.ok());
}

TEST(FrameworkChildProcess, WithoutTheKeeperAnotherUserIsRefused) {
  if (kLinuxKeeper) GTEST_SKIP() << "the Linux keeper may switch users";
  ChildOptions o = limited(10.0);
  o.uid = 65534;
  o.gid = 65534;
  ChildResult r = run_child({"true"}, o);
  EXPECT_FALSE(r.started);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errors.find("PT_LINUX_SANDBOX"), std::string::npos) << r.errors;
}

}  // namespace
}  // namespace pt
