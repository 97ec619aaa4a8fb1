// The score table and the Gradescope results by step: points shared among a step's checks, the
// first failing check and its message, the documented shape.
#include "grader/report.h"

#include <sstream>

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

CheckResult check(const std::string& name, const std::string& kind, bool pass, bool skipped,
                  const std::string& output) {
  CheckResult c;
  c.name = name;
  c.kind = kind;
  c.pass = pass;
  c.skipped = skipped;
  c.output = output;
  c.seconds = 0.5;
  return c;
}

StepSpec spec(int step, const std::string& name, double points) {
  StepSpec s;
  s.part = 3;
  s.step = step;
  s.name = name;
  s.points = points;
  return s;
}

/// Part 3 with a passing step 1 (one check skipped) and a step 4 failing one check in four.
std::vector<PartResult> sample_results() {
  PartResult p;
  p.part = 3;
  p.rests_on = "Part 3's renders trace rays with your Part 1 and Part 2: Part 1 passed (12:04), "
               "Part 2 not graded yet (grader --part 2).";
  p.steps.push_back(score_step(spec(1, "diffuse_bsdf", 3),
                               {check("part3.step1.diffuse_bsdf.a", "test", true, false, ""),
                                check("part3.step1.render.course_x", "render", false, true,
                                      "skipped: the course scene is not there")}));
  p.steps.push_back(score_step(
      spec(4, "importance", 8),
      {check("part3.step4.importance.a", "test", true, false, ""),
       check("part3.step4.importance.b", "test", true, false, ""),
       check("part3.step4.render.cornell_spheres", "render", false, false,
             "block (3,5) is 12% too dark\n    estimate_direct_importance: not implemented"),
       check("part3.step4.render.cornell_gap", "render", true, false, "")}));
  return {p};
}

TEST(GraderReport, AStepSharesItsPointsAmongItsCountedChecks) {
  std::vector<PartResult> r = sample_results();
  const StepResult& bsdf = r[0].steps[0];
  EXPECT_DOUBLE_EQ(bsdf.score, 3.0);  // the skipped check does not count
  EXPECT_TRUE(bsdf.passed());
  const StepResult& importance = r[0].steps[1];
  EXPECT_DOUBLE_EQ(importance.score, 6.0);
  EXPECT_FALSE(importance.passed());
  EXPECT_EQ(importance.message.rfind("part3.step4.render.cornell_spheres: block (3,5) is 12% too dark", 0), 0u)
      << importance.message;
  EXPECT_NE(importance.message.find("1 of 4 checks failed"), std::string::npos) << importance.message;
  EXPECT_NE(importance.message.find("not implemented"), std::string::npos) << importance.message;
  // Nothing counted: no points, and it says why.
  StepResult none = score_step(spec(2, "zero_bounce", 3), {});
  EXPECT_DOUBLE_EQ(none.score, 0.0);
  EXPECT_FALSE(none.passed());
  EXPECT_NE(none.message.find("no check"), std::string::npos);
}

// Locally a part's renders run the student's own earlier parts; Gradescope runs the course's. The
// table says which figure Gradescope gives, or the range it lies in and why.
TEST(GraderReport, TheTableSaysWhatGradescopeGives) {
  std::vector<PartResult> r = sample_results();
  std::ostringstream same;
  print_score_table(same, r);
  EXPECT_NE(same.str().find("so it gives this total"), std::string::npos) << same.str();
  r[0].open_checks = 1;
  r[0].open_points = 2.0;
  r[0].failing_parts_run = {2};
  std::ostringstream range;
  print_score_table(range, r);
  EXPECT_NE(range.str().find("between 9/11 and 11/11 (1 failing check here ran your Part 2, "
                             "which fails)"),
            std::string::npos)
      << range.str();
  EXPECT_NE(range.str().find("its total is between 9/11 and 11/11"), std::string::npos)
      << range.str();
  r[0].graded_alone = true;
  r[0].open_checks = 0;
  r[0].open_points = 0.0;
  std::ostringstream alone;
  print_score_table(alone, r);
  EXPECT_NE(alone.str().find("Graded as Gradescope grades it"), std::string::npos) << alone.str();
}

TEST(GraderReport, GradescopeJsonHasOneTestPerStep) {
  RunInfo info;
  info.seconds = 12.5;
  info.seed_offset = 3;
  nlohmann::json j = gradescope_results(sample_results(), info);
  EXPECT_EQ(validate_gradescope(j), "") << j.dump(2);
  EXPECT_DOUBLE_EQ(j["score"].get<double>(), 9.0);
  EXPECT_DOUBLE_EQ(j["execution_time"].get<double>(), 12.5);
  ASSERT_EQ(j["tests"].size(), 2u);
  const nlohmann::json& t = j["tests"][1];
  EXPECT_EQ(t["name"], "part3.step4.importance");
  EXPECT_EQ(t["number"], "3.4");
  EXPECT_EQ(t["status"], "failed");
  EXPECT_DOUBLE_EQ(t["max_score"].get<double>(), 8.0);
  EXPECT_NE(t["output"].get<std::string>().find("12% too dark"), std::string::npos);
  ASSERT_EQ(t["extra_data"]["checks"].size(), 4u);
  EXPECT_EQ(t["extra_data"]["checks"][2]["status"], "failed");
  EXPECT_EQ(t["extra_data"]["step_name"], "importance");
  EXPECT_EQ(j["tests"][0]["extra_data"]["checks"][1]["status"], "skipped");
  EXPECT_EQ(j["extra_data"]["seed_offset"], 3);
  EXPECT_NE(j["output"].get<std::string>().find("Part 1 passed"), std::string::npos);
  // Round trip through text, as Gradescope reads the file.
  EXPECT_EQ(validate_gradescope(nlohmann::json::parse(j.dump())), "");
}

TEST(GraderReport, ValidatorRejectsWhatGradescopeWouldNot) {
  nlohmann::json good = gradescope_results(sample_results(), RunInfo{});
  nlohmann::json j = good;
  j["tests"][0]["score"] = "1";
  EXPECT_NE(validate_gradescope(j), "");
  j = good;
  j["tests"] = nlohmann::json::object();
  EXPECT_NE(validate_gradescope(j), "");
  j = good;
  j["score"] = 99.0;
  EXPECT_NE(validate_gradescope(j).find("sum"), std::string::npos);
  j = good;
  j["tests"][1]["visibility"] = "sometimes";
  EXPECT_NE(validate_gradescope(j), "");
  j = good;
  j["tests"][1]["status"] = "almost";
  EXPECT_NE(validate_gradescope(j), "");
  EXPECT_NE(validate_gradescope(nlohmann::json::array()), "");
}

TEST(GraderReport, ScoreTableShowsStepsPointsAndTheFirstFailure) {
  std::ostringstream out;
  print_score_table(out, sample_results());
  std::string s = out.str();
  EXPECT_NE(s.find("Part 3\nPart 3's renders trace rays with your Part 1 and Part 2"), std::string::npos) << s;
  EXPECT_NE(s.find("part3.step1.diffuse_bsdf"), std::string::npos) << s;
  EXPECT_NE(s.find("6/8"), std::string::npos) << s;
  EXPECT_NE(s.find("FAIL"), std::string::npos) << s;
  EXPECT_NE(s.find("3 of 4 pass"), std::string::npos) << s;
  EXPECT_NE(s.find("part3.step4.render.cornell_spheres: block (3,5) is 12% too dark"), std::string::npos) << s;
  EXPECT_NE(s.find("Total: 9/11"), std::string::npos) << s;
  EXPECT_FALSE(all_passed(sample_results()));
  std::vector<PartResult> good = sample_results();
  good[0].steps.pop_back();
  EXPECT_TRUE(all_passed(good));
  good[0].built = false;
  EXPECT_FALSE(all_passed(good));
}

}  // namespace
}  // namespace pt::grader
