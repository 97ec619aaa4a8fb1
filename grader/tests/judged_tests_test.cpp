// A test's verdict comes from its judge, which holds no student code: Part 1's real probe and
// judge pass the complete solution's test; a probe that exits 0 without answering, one that prints
// GoogleTest's pass lines, one that writes a forged or cut-short record, one that crashes after
// answering, and one that answers one call wrongly all fail, each with a message that says why.
#include "grader/judged_tests.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"

namespace pt::grader {
namespace {

#ifdef GRADER_SECRET_DIR
const std::string kSecret = GRADER_SECRET_DIR;

int own_slot() { return 2000 + int(::getpid() % 30000); }

/// The camera test of Part 1, with its real judge and `probe` in its probe's place.
JudgedTest camera_test(const std::string& probe) {
  JudgedTest t;
  t.part = 1;
  t.step = 1;
  t.gtest = "camera_ray.corners_match_the_field_of_view";
  t.name = "part1.step1." + t.gtest;
  t.probe = probe;
  t.judge = kSecret + "/judge_part1_step1_camera_ray_test";
  return t;
}

JudgedOutcome run(const JudgedTest& t, const test::TempFolder& dir) {
  Sandbox sandbox = Sandbox::standard((dir.path() / "scratch").string(), own_slot());
  return run_judged_tests({t}, sandbox, 60.0, (dir.path() / "records").string()).at(0);
}

/// A probe that is a shell script: what a student's code could make the probe do instead.
std::string script(const test::TempFolder& dir, const std::string& name, const std::string& body) {
  std::filesystem::path p = dir.path() / name;
  std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
  std::filesystem::permissions(p, std::filesystem::perms(0755));
  return p.string();
}

TEST(GraderJudgedTests, TheJudgesListTheirTests) {
  std::vector<JudgedTest> tests = list_judged_tests(1, std::filesystem::path(kSecret).parent_path().string(),
                                                    std::filesystem::path(kSecret).parent_path().string());
  ASSERT_FALSE(tests.empty());
  bool found = false;
  for (const JudgedTest& t : tests) {
    EXPECT_EQ(t.part, 1);
    EXPECT_GE(t.step, 1);
    found = found || t.gtest == camera_test("").gtest;
  }
  EXPECT_TRUE(found) << "the camera test is not among Part 1's judged tests";
}

TEST(GraderJudgedTests, TheSolutionsProbePassesItsJudge) {
  test::TempFolder dir("pt-judged");
  JudgedOutcome o = run(camera_test(kSecret + "/probe_part1_step1_camera_ray_test"), dir);
  EXPECT_TRUE(o.pass) << o.message << "\n" << o.student_output;
}

// The longest tests start first when their times are known; each outcome stays with its test.
TEST(GraderJudgedTests, OutcomesKeepTheirTestsWhateverOrderTheyRunIn) {
  test::TempFolder dir("pt-judged");
  const JudgedTest good = camera_test(kSecret + "/probe_part1_step1_camera_ray_test");
  const JudgedTest silent = camera_test(script(dir, "silent", "exit 0"));
  Sandbox sandbox = Sandbox::standard((dir.path() / "scratch").string(), own_slot());
  for (const std::vector<double>& expected :
       {std::vector<double>{}, std::vector<double>{0.1, 5.0, 0.2}, std::vector<double>{9, 1, 3}}) {
    const std::vector<JudgedOutcome> o = run_judged_tests(
        {good, silent, good}, sandbox, 60.0, (dir.path() / "records").string(), expected);
    ASSERT_EQ(o.size(), 3u);
    EXPECT_TRUE(o[0].pass) << o[0].message;
    EXPECT_FALSE(o[1].pass);
    EXPECT_TRUE(o[2].pass) << o[2].message;
  }
}

TEST(GraderJudgedTests, AProbeThatAnswersNothingFails) {
  test::TempFolder dir("pt-judged");
  JudgedOutcome o = run(camera_test(script(dir, "silent", "exit 0")), dir);
  EXPECT_FALSE(o.pass);
  EXPECT_NE(o.message.find("stopped before it returned"), std::string::npos) << o.message;
}

TEST(GraderJudgedTests, PrintedPassLinesCountForNothing) {
  test::TempFolder dir("pt-judged");
  JudgedOutcome o = run(camera_test(script(dir, "printer",
      "echo '[       OK ] camera_ray.corners_match_the_field_of_view (0 ms)'\n"
      "echo '[  PASSED  ] 1 test.'\nexit 0")), dir);
  EXPECT_FALSE(o.pass) << o.message;
}

TEST(GraderJudgedTests, AForgedRecordFails) {
  test::TempFolder dir("pt-judged");
  // A call event of another function, then bytes that are no event.
  JudgedOutcome o = run(camera_test(script(dir, "forger",
      "printf 'C\\146\\000\\000\\000\\000\\000\\000garbage' >&$PT_RECORD_FD\nexit 0")), dir);
  EXPECT_FALSE(o.pass);
  EXPECT_NE(o.message.find("record"), std::string::npos) << o.message;
}

TEST(GraderJudgedTests, AnswersBeforeACrashDoNotCount) {
  test::TempFolder dir("pt-judged");
  std::string real = kSecret + "/probe_part1_step1_camera_ray_test";
  JudgedOutcome o = run(camera_test(script(dir, "crasher",
      "\"" + real + "\" \"$@\" >/dev/null\nkill -SEGV $$")), dir);
  EXPECT_FALSE(o.pass);
  EXPECT_NE(o.message.find("your code"), std::string::npos) << o.message;
}

TEST(GraderJudgedTests, OneWrongAnswerFailsTheTest) {
  test::TempFolder dir("pt-judged");
  // The real probe's record with one byte of its last answer changed on the way to the grader.
  std::string real = kSecret + "/probe_part1_step1_camera_ray_test";
  std::string body =
      "tmp=$(mktemp)\n"
      "PT_RECORD_FD=9 \"" + real + "\" \"$@\" 9>\"$tmp\" >/dev/null\n"
      "size=$(stat -c %s \"$tmp\")\n"
      "printf '\\177' | dd of=\"$tmp\" bs=1 seek=$((size - 2)) conv=notrunc 2>/dev/null\n"
      "cat \"$tmp\" >&$PT_RECORD_FD\nrm -f \"$tmp\"\nexit 0";
  JudgedOutcome o = run(camera_test(script(dir, "changer", body)), dir);
  EXPECT_FALSE(o.pass) << "a record with a changed answer passed";
  EXPECT_NE(o.message.find("camera_ray_test.cpp"), std::string::npos)
      << "the judge's own failure, with its file and line, is the message: " << o.message;
}

// Skipping is the judge's word alone: a probe that prints GoogleTest's skip lines is a failure.
TEST(GraderJudgedTests, APrintedSkipIsNoSkip) {
  test::TempFolder dir("pt-judged");
  JudgedOutcome o = run(camera_test(script(dir, "skipper",
      "echo 'x.cpp:1: Skipped'\necho 'no scene'\n"
      "echo '[  SKIPPED ] camera_ray.corners_match_the_field_of_view (0 ms)'\nexit 0")), dir);
  EXPECT_FALSE(o.pass);
  EXPECT_FALSE(o.skipped) << o.message;
}

TEST(GraderJudgedTests, TheSkipReasonIsWhatTheTestSaid) {
  EXPECT_EQ(gtest_skip_reason("[ RUN      ] t.a\n"
                              "/p/parts/2-bvh/tests/step3_traversal_test.cpp:201: Skipped\n"
                              "cannot open x.dae: put the course's scenes at ../shared/scenes/cs184\n"
                              "\n"
                              "[  SKIPPED ] t.a (0 ms)\n"),
            "cannot open x.dae: put the course's scenes at ../shared/scenes/cs184");
  EXPECT_EQ(gtest_skip_reason("[ RUN      ] t.a\n[       OK ] t.a (0 ms)\n"), "");
}

// A test its judge skips (a course scene it needs is not there) is a skip with the judge's
// reason, not a failure: the judge's report says so, whatever the probe did.
TEST(GraderJudgedTests, ATestTheJudgeSkipsIsASkipWithItsReason) {
  test::TempFolder dir("pt-judged");
  const std::filesystem::path judge = dir.path() / "judge";
  std::ofstream(judge)
      << "#!/bin/sh\n"
         "for a in \"$@\"; do case \"$a\" in --gtest_output=json:*) out=${a#--gtest_output=json:};; "
         "esac; done\n"
         "echo '[ RUN      ] traversal.course_bunny'\n"
         "echo 'step3_traversal_test.cpp:201: Skipped'\n"
         "echo \"cannot open bunny.dae: put the course's scenes at ../shared/scenes/cs184\"\n"
         "echo '[  SKIPPED ] traversal.course_bunny (0 ms)'\n"
         "printf '%s' '{\"testsuites\": [{\"name\": \"traversal\", \"testsuite\": [{\"name\": "
         "\"course_bunny\", \"status\": \"RUN\", \"result\": \"SKIPPED\"}]}]}' > \"$out\"\n";
  std::filesystem::permissions(judge, std::filesystem::perms(0755));
  JudgedTest t;
  t.part = 2;
  t.step = 3;
  t.gtest = "traversal.course_bunny";
  t.name = "part2.step3." + t.gtest;
  t.probe = script(dir, "probe", "exit 0");
  t.judge = judge.string();
  Sandbox sandbox;
  sandbox.scratch_root = (dir.path() / "scratch").string();
  std::filesystem::create_directories(sandbox.scratch_root);
  const JudgedOutcome o = run_judged_tests({t}, sandbox, 60.0, (dir.path() / "records").string()).at(0);
  EXPECT_FALSE(o.pass);
  EXPECT_TRUE(o.skipped) << o.message;
  EXPECT_EQ(o.message, "cannot open bunny.dae: put the course's scenes at ../shared/scenes/cs184");
  // The same judge reporting the test run and failed is a failure, not a skip.
  std::ofstream(judge, std::ios::app)
      << "printf '%s' '{\"testsuites\": [{\"name\": \"traversal\", \"testsuite\": [{\"name\": "
         "\"course_bunny\", \"status\": \"RUN\", \"result\": \"COMPLETED\", \"failures\": "
         "[{\"failure\": \"x.cpp:1\\\\nExpected equality\"}]}]}]}' > \"$out\"\n";
  const JudgedOutcome f = run_judged_tests({t}, sandbox, 60.0, (dir.path() / "records").string()).at(0);
  EXPECT_FALSE(f.pass);
  EXPECT_FALSE(f.skipped) << f.message;
  EXPECT_NE(f.message.find("Expected equality"), std::string::npos) << f.message;
}
#endif

}  // namespace
}  // namespace pt::grader
