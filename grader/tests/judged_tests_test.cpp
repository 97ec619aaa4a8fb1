// A test's verdict comes from its judge, which holds no student code: Part 1's real probe and
// judge pass the complete solution's test; a probe that exits 0 without answering, one that prints
// GoogleTest's pass lines, one that writes a forged or cut-short record, one that crashes after
// answering, and one that answers one call wrongly all fail, each with a message that says why.
#include "grader/judged_tests.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"

namespace pt::grader {
namespace {

#ifdef GRADER_SECRET_DIR
const std::string kSecret = GRADER_SECRET_DIR;

int own_slot() { return 2000 + int(::getpid() % 30000); }

/// Test `gtest` of part `part`'s step `step` (NAME), with its real judge and `probe` in its
/// probe's place.
JudgedTest judged(int part, int step, const std::string& name, const std::string& gtest,
                  const std::string& probe) {
  JudgedTest t;
  t.part = part;
  t.step = step;
  t.gtest = gtest;
  t.name = "part" + std::to_string(part) + ".step" + std::to_string(step) + "." + gtest;
  t.probe = probe;
  t.judge = kSecret + "/judge_part" + std::to_string(part) + "_step" + std::to_string(step) + "_" +
            name + "_test";
  return t;
}

/// The camera test of Part 1.
JudgedTest camera_test(const std::string& probe) {
  return judged(1, 1, "camera_ray", "camera_ray.corners_match_the_field_of_view", probe);
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

/// Part 3's test that a light sample of no radiance costs no shadow ray.
JudgedTest black_light_test(const std::string& probe) {
  return judged(3, 4, "importance", "importance.a_light_sample_of_no_radiance_traces_no_shadow_ray",
                probe);
}

// The rays an estimator traces are the judge's count: each is a callback the judge traces again.
// The complete solution's probe passes; the same record with the call's counter moves forged
// (one shadow ray fewer, as a student's code that puts the test's counter back would claim)
// fails, and so does one whose rays were answered by another scene.
TEST(GraderJudgedTests, TheRaysAnEstimatorTracesAreTheJudgesCount) {
  test::TempFolder dir("pt-judged");
  const std::string real = kSecret + "/probe_part3_step4_importance_test";
  ASSERT_TRUE(std::filesystem::exists(real)) << real;
  JudgedOutcome o = run(black_light_test(real), dir);
  ASSERT_TRUE(o.pass) << o.message << "\n" << o.student_output;
  // The real record, taken as the grader takes it.
  const std::filesystem::path record = dir.path() / "record";
  ASSERT_EQ(std::system(("PT_RECORD_FD=9 '" + real + "' --gtest_filter=" + black_light_test("").gtest +
                         " 9>'" + record.string() + "' >/dev/null 2>&1").c_str()),
            0);
  std::string bytes;
  {
    std::ifstream in(record, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // Events: kind (1 byte), function (2), which (1), size (4), payload. A return's payload opens
  // with the number of counters and their moves outside the call's callbacks.
  auto forged = [&](auto&& change) {
    std::string b = bytes;
    int changed = 0;
    for (size_t at = 0; at + 8 <= b.size();) {
      uint32_t size;
      std::memcpy(&size, b.data() + at + 4, 4);
      if (changed == 0 && change(b, at, size)) ++changed;
      at += 8 + size;
    }
    EXPECT_EQ(changed, 1) << "the record holds no event to change";
    const std::filesystem::path p = dir.path() / ("forged-" + std::to_string(b.size()));
    std::ofstream(p, std::ios::binary) << b;
    std::filesystem::permissions(p, std::filesystem::perms(0644));
    std::filesystem::permissions(dir.path(), std::filesystem::perms(0755));
    return script(dir, "forger", "cat '" + p.string() + "' >&$PT_RECORD_FD\nexit 0");
  };
  const std::string uncounted = forged([](std::string& b, size_t at, uint32_t size) {
    if (b[at] != 'R' || size < 4 + 8) return false;
    uint32_t n;
    std::memcpy(&n, b.data() + at + 8, 4);
    if (n == 0) return false;
    const int64_t fewer = -1;  // the last counter registered: the query's any-hit rays
    std::memcpy(&b[at + 8 + 4 + 8 * (n - 1)], &fewer, 8);
    return true;
  });
  o = run(black_light_test(uncounted), dir);
  EXPECT_FALSE(o.pass) << "a record that counts a shadow ray fewer passed";
  EXPECT_NE(o.message.find("changed a counter of the test's itself"), std::string::npos) << o.message;
  const std::string lying = forged([](std::string& b, size_t at, uint32_t) {
    if (b[at] != 'A') return false;  // a ray's answer: "blocked" turned round
    b[at + 8] = char(b[at + 8] ^ 1);
    return true;
  });
  o = run(black_light_test(lying), dir);
  EXPECT_FALSE(o.pass) << "a record whose ray was answered otherwise passed";
  EXPECT_NE(o.message.find("callback answered what the test's callback does not answer"),
            std::string::npos) << o.message;
}

// A record is hostile input to the judge: 200 copies of a real one, each with bits flipped, cut
// short, bytes inserted or a size field made huge, each ends the judge with a verdict (pass, fail,
// or "the record holds calls the test did not make"), never a crash or a hang. A copy may pass: a
// changed ray the judge traces again, or a value within the test's tolerance, is another claim
// the test accepts.
TEST(GraderJudgedTests, AJudgeGivesAVerdictOnAnyRecord) {
  test::TempFolder dir("pt-judged-fuzz");
  const std::string probe = kSecret + "/probe_part3_step4_importance_test";
  const std::string judge = kSecret + "/judge_part3_step4_importance_test";
  const std::string filter = "--gtest_filter=" + black_light_test("").gtest;
  const std::filesystem::path record = dir.path() / "record";
  ASSERT_EQ(std::system(("PT_RECORD_FD=9 '" + probe + "' " + filter + " 9>'" + record.string() +
                         "' >/dev/null 2>&1").c_str()),
            0);
  std::string bytes;
  {
    std::ifstream in(record, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes.size(), 40u);
  std::mt19937 rng(11);
  auto below = [&](size_t n) { return size_t(rng() % n); };
  int verdicts[4] = {0, 0, 0, 0};  // pass, fail, calls not made, other
  for (int i = 0; i < 200; ++i) {
    std::string b = bytes;
    switch (i % 4) {
      case 0:
        for (int k = 0; k < 1 + int(below(4)); ++k) b[below(b.size())] ^= char(1 << below(8));
        break;
      case 1: b.resize(below(b.size())); break;
      case 2: b.insert(below(b.size()), std::string(1 + below(16), char(rng()))); break;
      case 3: {
        const uint32_t huge = 0xfffffff0u;
        std::memcpy(&b[below(b.size() - 8) + 4], &huge, 4);
        break;
      }
    }
    const std::filesystem::path m = dir.path() / "mutated";
    std::ofstream(m, std::ios::binary | std::ios::trunc) << b;
    ChildOptions o;
    o.limits.wall_seconds = 20;
    o.environment = {"PT_REPLAY_FILE=" + m.string()};
    const ChildResult r = run_child({judge, filter}, o);
    ASSERT_TRUE(r.started && !r.timed_out && r.signal == 0)
        << "mutation " << i << ": " << r.describe() << "\n" << r.output;
    const int k = r.exit_code == 0 ? 0 : r.exit_code == 1 ? 1 : r.exit_code == 3 ? 2 : 3;
    ++verdicts[k];
    EXPECT_NE(k, 3) << "mutation " << i << ": " << r.describe() << "\n" << r.output;
  }
  std::printf("200 mutated records: %d pass, %d fail, %d hold calls not made\n", verdicts[0],
              verdicts[1], verdicts[2]);
  EXPECT_GT(verdicts[1] + verdicts[2], 100);
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
