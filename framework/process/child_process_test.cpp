// A child that crashes, hangs or floods its output is reported as such, and the grader goes on.
#include "framework/process/child_process.h"

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

TEST(GraderChildProcess, ExitStatusAndOutputAreCaptured) {
  ChildResult r = run_child({"sh", "-c", "echo to-out; echo to-err >&2; exit 3"}, 10.0);
  EXPECT_TRUE(r.started);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.output.find("to-out"), std::string::npos);
  EXPECT_NE(r.output.find("to-err"), std::string::npos);
  EXPECT_EQ(r.describe(), "exited with status 3");
  EXPECT_TRUE(run_child({"true"}, 10.0).ok());
}

TEST(GraderChildProcess, ACrashIsNamed) {
  ChildResult r = run_child({"sh", "-c", "kill -SEGV $$"}, 10.0);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.signal, 11);
  EXPECT_NE(r.describe().find("SIGSEGV"), std::string::npos) << r.describe();
}

TEST(GraderChildProcess, AHangIsStoppedAtItsLimitWithItsChildren) {
  // The shell starts a sleep of its own: the whole group must go, or the test would wait.
  ChildResult r = run_child({"sh", "-c", "sleep 60; echo never"}, 0.5);
  EXPECT_TRUE(r.timed_out);
  EXPECT_FALSE(r.ok());
  EXPECT_LT(r.seconds, 5.0);
  EXPECT_NE(r.describe().find("time limit"), std::string::npos);
}

TEST(GraderChildProcess, FloodedOutputIsCut) {
  ChildResult r = run_child({"sh", "-c", "head -c 3000000 /dev/zero | tr '\\0' x"}, 20.0, {}, 1000);
  EXPECT_TRUE(r.ok()) << r.describe();
  EXPECT_LT(r.output.size(), 1100u);
  EXPECT_NE(r.output.find("output cut"), std::string::npos);
}

TEST(GraderChildProcess, AMissingProgramIsAFailureNotACrash) {
  ChildResult r = run_child({"pt-no-such-program-xyz"}, 5.0);
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.started && r.exit_code == 0);
}

TEST(GraderChildProcess, WorkingDirectoryIsUsed) {
  ChildResult r = run_child({"pwd"}, 5.0, "/");
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.output, "/\n");
}

}  // namespace
}  // namespace pt::grader
