// The sandbox the student's code runs in: as root, a user of its own per process that cannot
// read the grader's files nor write outside its scratch folder, and leaves nothing behind (no
// file, no IPC object), with namespaces and where they are refused; slots taken alone; and a
// render's file is read only if the render wrote it itself.
#include "grader/sandbox.h"

#include <fcntl.h>
#include <mqueue.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"
#include "grader/student_traces.h"

namespace pt::grader {
namespace {

/// Run as a student's process (this test program again, PT_LEAVE_TRACES set): tries to leave
/// something a later process could open, everywhere it can, and prints how much it made.
struct LeaveTraces {
  LeaveTraces() {
    if (!std::getenv("PT_LEAVE_TRACES")) return;
    int made = 0;
    for (const std::string& folder : world_writable_places().folders) {
      std::string path = folder + "/pt-trace-" + std::to_string(getuid());
      int fd = open(path.c_str(), O_CREAT | O_WRONLY | O_EXCL, 0666);
      if (fd >= 0 && write(fd, "solution", 8) == 8) ++made;
      if (fd >= 0) close(fd);
      if (mkdir((path + "-folder").c_str(), 0777) == 0) ++made;
    }
    const key_t key = key_t(0x50540000 + getuid() % 0x10000);
    if (shmget(key, 4096, IPC_CREAT | 0666) >= 0) ++made;
    if (semget(key, 1, IPC_CREAT | 0666) >= 0) ++made;
    if (msgget(key, IPC_CREAT | 0666) >= 0) ++made;
    if (mq_open("/pt-trace", O_CREAT | O_RDWR, 0666, nullptr) != mqd_t(-1)) ++made;
    if (socket(AF_INET, SOCK_STREAM, 0) >= 0) ++made;
    std::printf("made %d\n", made);
    std::fflush(stdout);
    _exit(0);
  }
} leave_traces;

/// This test program's own path, to run it again as a student's process.
std::string self() { return std::filesystem::read_symlink("/proc/self/exe").string(); }

/// A uid slot to start looking from: slots are taken alone, whichever is given.
int own_slot() { return int(::getpid() % kSlots); }

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

/// Runs the trace-leaving process in a sandbox (namespaces on or refused), then checks that
/// nothing of its uid is left anywhere on the machine. Returns how much it could make.
int made_and_left_nothing(bool namespaces) {
  setenv("PT_SANDBOX_NAMESPACES", namespaces ? "on" : "off", 1);
  test::TempFolder dir("pt-sandbox-traces");
  Sandbox sandbox = Sandbox::standard((dir.path() / "scratch").string(), own_slot());
  EXPECT_TRUE(sandbox.protects());
  EXPECT_EQ(sandbox.namespaces, namespaces);
  std::string scratch = sandbox.make_scratch("traces");
  long uid = sandbox.uid_of(scratch);
  ChildOptions o = sandbox.options(scratch, 30.0);
  o.environment.push_back("PT_LEAVE_TRACES=1");
  ChildResult r = run_child({self()}, o);
  EXPECT_TRUE(r.ok()) << r.describe() << "\n" << r.output;
  sandbox.finish(scratch);
  EXPECT_EQ(sandbox.leftovers(), "");
  std::vector<std::string> left = traces_of_uids(uid, uid);
  std::string listed;
  for (const std::string& l : left) listed += l + "\n";
  EXPECT_TRUE(left.empty()) << listed;
  int made = -1;
  std::sscanf(r.output.c_str(), "made %d", &made);
  return made;
}

TEST(GraderSandbox, WithNamespacesAProcessLeavesNothingBehind) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root to switch users";
  if (!kernel_gives_namespaces()) GTEST_SKIP() << "the kernel refuses namespaces here";
  // It made files in its own empty tmpfs folders and IPC objects in its own IPC namespace
  // (nothing of a socket: it has no network), and they went with them.
  EXPECT_GT(made_and_left_nothing(true), 0);
}

TEST(GraderSandbox, WhereNamespacesAreRefusedAProcessCanMakeNothingOutsideItsScratch) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root to switch users";
  // No shared folder writable, no IPC object, no socket: it makes nothing at all.
  EXPECT_EQ(made_and_left_nothing(false), 0);
}

TEST(GraderSandbox, WhatTheCleanupMissesIsFoundAndRemoved) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root to switch users";
  test::TempFolder dir("pt-sandbox-sweep");
  Sandbox sandbox = Sandbox::standard((dir.path() / "scratch").string(), own_slot());
  std::string scratch = sandbox.make_scratch("sweep");
  long uid = sandbox.uid_of(scratch);
  // As if the confinement had failed: a shared folder's file and a SysV segment of that uid.
  ASSERT_FALSE(world_writable_places().folders.empty());
  std::string file = world_writable_places().folders.front() + "/pt-sweep-" + std::to_string(uid);
  std::ofstream(file) << "x";
  ASSERT_EQ(chown(file.c_str(), uid_t(uid), gid_t(uid)), 0);
  int id = shmget(IPC_PRIVATE, 4096, IPC_CREAT | 0600);
  ASSERT_GE(id, 0);
  shmid_ds ds;
  ASSERT_EQ(shmctl(id, IPC_STAT, &ds), 0);
  ds.shm_perm.uid = uid_t(uid);
  ASSERT_EQ(shmctl(id, IPC_SET, &ds), 0);
  EXPECT_FALSE(traces_of_uids(uid, uid).empty());
  sandbox.finish(scratch);
  EXPECT_EQ(sandbox.leftovers(), "");
  EXPECT_FALSE(std::filesystem::exists(file));
  for (const IpcObject& o : sysv_objects()) EXPECT_NE(o.id, id) << o.kind;
}

TEST(GraderSandbox, EachProcessHasAUidOfItsOwnAndSlotsAreTakenAlone) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root to switch users";
  test::TempFolder dir("pt-sandbox-slots");
  const int slot = own_slot();
  long first_uid = -1;
  {
    Sandbox a = Sandbox::standard((dir.path() / "a").string(), slot);
    Sandbox b = Sandbox::standard((dir.path() / "b").string(), slot);
    EXPECT_NE(a.uid, b.uid) << "two graders share a slot";
    EXPECT_GE(a.uid, kFirstStudentUid);
    EXPECT_LT(b.uid, kFirstStudentUid + kSlots * kUidsPerSlot);
    std::string one = a.make_scratch("one"), two = a.lane(1).make_scratch("two");
    EXPECT_NE(a.uid_of(one), a.uid_of(two));
    EXPECT_GE(a.uid_of(two), a.uid);
    EXPECT_LT(a.uid_of(two), a.uid + kUidsPerSlot);
    a.finish(one);
    a.finish(two);
    first_uid = a.uid;
  }
  // A sandbox that is gone frees its slot.
  Sandbox again = Sandbox::standard((dir.path() / "c").string(), int((first_uid - kFirstStudentUid) / kUidsPerSlot));
  EXPECT_EQ(again.uid, first_uid);
}

}  // namespace
}  // namespace pt::grader
