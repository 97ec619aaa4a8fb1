// The score table and the Gradescope results by step: points shared among a step's checks, the
// first failing check and its message, the documented shape.
#include "grader/report.h"

#include <sstream>

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

CheckResult check(const std::string& name, const std::string& kind, bool pass, bool skipped,
                  const std::string& output, const std::string& todo = "") {
  CheckResult c;
  c.todo = todo;
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
             "block (3,5) is 12% too dark", "    estimate_direct_importance: not implemented"),
       check("part3.step4.render.cornell_gap", "render", true, false, "")}));
  return {p};
}

/// What GoogleTest's EXPECT_EQ says, values on indented lines, then what the test added.
const char* kEqualityFailure =
    "parts/2-bvh/tests/step2_split_test.cpp:172\n"
    "Expected equality of these values:\n"
    "  got.plane\n"
    "    Which is: 0.375\n"
    "  want.plane\n"
    "    Which is: 0.5\n"
    "trial 3";

// A failing check's message reaches the student whole, values included, in the step's message
// (the table) and in results.json, its "not implemented" lines apart and once.
TEST(GraderReport, AFailingCheckShowsWhatItExpectedAndWhatCameBack) {
  StepSpec st = spec(2, "split", 6);
  Rule rule;
  rule.id = "sah_cost";
  rule.text = "the split of least SAH cost";
  rule.checks = {"part3.step2.split.a"};
  st.rules = {rule};
  PartResult p;
  p.part = 3;
  p.steps.push_back(score_step(
      st, {check("part3.step2.split.a", "test", false, false, kEqualityFailure,
                 "    parts/2-bvh/bvh_split.cpp:12: part 2 not implemented: best_sah_split"),
           check("part3.step2.split.b", "test", true, false, "")}));
  const std::string& message = p.steps[0].message;
  for (const char* part : {"got.plane", "Which is: 0.375", "want.plane", "Which is: 0.5", "trial 3",
                           "#sah_cost", "part 2 not implemented: best_sah_split"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " is not in\n" << message;
  // The rule comes after the values, not between them.
  EXPECT_LT(message.find("Which is: 0.5"), message.find("#sah_cost")) << message;
  EXPECT_EQ(message.find("not implemented"), message.rfind("not implemented")) << message;
  std::ostringstream table;
  print_score_table(table, {p});
  EXPECT_NE(table.str().find("Which is: 0.375"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("Which is: 0.5"), std::string::npos) << table.str();
  const nlohmann::json j = gradescope_results({p}, RunInfo{});
  const std::string step_output = j["tests"][0]["output"].get<std::string>();
  const std::string check_output = j["tests"][0]["extra_data"]["checks"][0]["output"].get<std::string>();
  for (const std::string& out : {step_output, check_output}) {
    EXPECT_NE(out.find("Which is: 0.375"), std::string::npos) << out;
    EXPECT_NE(out.find("Which is: 0.5"), std::string::npos) << out;
    EXPECT_NE(out.find("not implemented: best_sah_split"), std::string::npos) << out;
  }
  // Bounded: a message of any length stays within its cap in results.json.
  PartResult flood = p;
  flood.steps[0].checks[0].output = std::string(kEqualityFailure) + std::string(100000, 'x');
  flood.steps[0].message = std::string(100000, 'y');
  const nlohmann::json capped = gradescope_results({flood}, RunInfo{});
  EXPECT_LE(capped["tests"][0]["output"].get<std::string>().size(), 2100u);
  const std::string cut = capped["tests"][0]["extra_data"]["checks"][0]["output"].get<std::string>();
  EXPECT_LE(cut.size(), 1300u);
  EXPECT_NE(cut.find("Which is: 0.5"), std::string::npos) << cut;
}

// A check that cannot run (a course scene that is not there) is a skip: not counted, not a
// failure; its step says why and what to do, and the total says what it leaves ungraded.
TEST(GraderReport, ASkippedCheckIsNamedAndCostsNothing) {
  const std::string why =
      "skipped, not counted: cannot open ../shared/scenes/cs184/sky/CBbunny.dae: put the "
      "course's scenes at ../shared/scenes/cs184 (beside the project)";
  PartResult p;
  p.part = 2;
  p.steps.push_back(score_step(spec(3, "traversal", 8),
                               {check("part2.step3.traversal.a", "test", true, false, ""),
                                check("part2.step3.traversal.b", "test", true, false, ""),
                                check("part2.step3.traversal.c", "test", true, false, ""),
                                check("part2.step3.traversal.course_bunny", "test", false, true, why)}));
  const StepResult& st = p.steps[0];
  EXPECT_DOUBLE_EQ(st.score, 8.0);
  EXPECT_TRUE(st.passed());
  EXPECT_EQ(st.skipped(), 1);
  EXPECT_DOUBLE_EQ(st.skipped_points(), 2.0);
  EXPECT_DOUBLE_EQ(p.skipped_points(), 2.0);
  EXPECT_NE(st.message.find("1 of 4 checks skipped"), std::string::npos) << st.message;
  EXPECT_NE(st.message.find("put the course's scenes at ../shared/scenes/cs184"), std::string::npos)
      << st.message;
  EXPECT_EQ(st.message.find("fail"), std::string::npos) << st.message;
  std::ostringstream table;
  print_score_table(table, {p});
  EXPECT_NE(table.str().find("Total: 8/8"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("put the course's scenes at ../shared/scenes/cs184"), std::string::npos)
      << table.str();
  EXPECT_NE(table.str().find("1 check could not run here"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("2 points ungraded"), std::string::npos) << table.str();
  const nlohmann::json j = gradescope_results({p}, RunInfo{});
  EXPECT_EQ(j["tests"][0]["status"], "passed");
  EXPECT_EQ(j["extra_data"]["skipped_checks"], 1);
  EXPECT_NE(j["output"].get<std::string>().find("2 points ungraded"), std::string::npos) << j.dump(1);
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
  // Whole seconds: the run's time is the student's choice as much as the grader's.
  EXPECT_DOUBLE_EQ(j["execution_time"].get<double>(), 13.0);
  for (const nlohmann::json& t : j["tests"])
    for (const nlohmann::json& c : t["extra_data"]["checks"]) EXPECT_FALSE(c.contains("seconds"));
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
