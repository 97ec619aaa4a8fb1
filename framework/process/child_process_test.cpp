// A child that crashes, hangs or floods its output is reported as such, and the tool that ran it
// (the grader, the write-up's renders) goes on.
#include "framework/process/child_process.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

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

}  // namespace
}  // namespace pt
