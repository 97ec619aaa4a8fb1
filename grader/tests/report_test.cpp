// The score table and the Gradescope results: totals, failure messages, the documented shape.
#include "grader/report.h"

#include <sstream>

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

std::vector<CheckResult> sample_results() {
  CheckResult build{"part3.build", 3, 0, 0, true, false, "built", 1.0};
  CheckResult tests{"part3.tests", 3, 7.5, 10, false, false, "3 of 4 tests passed\n    failed: X", 2.0};
  CheckResult render{"part3.direct.cornell_spheres", 3, 0, 5, false, false,
                     "block (3,5) is 12% too dark", 0.5};
  CheckResult skipped{"part3.direct.course_bunny", 3, 0, 0, false, true, "skipped: not there", 0};
  return {build, tests, render, skipped};
}

TEST(GraderReport, GradescopeJsonHasTheDocumentedShape) {
  nlohmann::json j = gradescope_results(sample_results(), 12.5);
  EXPECT_EQ(validate_gradescope(j), "") << j.dump(2);
  EXPECT_DOUBLE_EQ(j["score"].get<double>(), 7.5);
  EXPECT_DOUBLE_EQ(j["execution_time"].get<double>(), 12.5);
  ASSERT_EQ(j["tests"].size(), 4u);
  const nlohmann::json& t = j["tests"][2];
  for (const char* key : {"name", "score", "max_score", "output"}) EXPECT_TRUE(t.contains(key)) << key;
  EXPECT_EQ(t["name"], "part3.direct.cornell_spheres");
  EXPECT_NE(t["output"].get<std::string>().find("12% too dark"), std::string::npos);
  // Round trip through text, as Gradescope reads the file.
  EXPECT_EQ(validate_gradescope(nlohmann::json::parse(j.dump())), "");
}

TEST(GraderReport, ValidatorRejectsWhatGradescopeWouldNot) {
  nlohmann::json good = gradescope_results(sample_results(), 1.0);
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
  EXPECT_NE(validate_gradescope(nlohmann::json::array()), "");
}

TEST(GraderReport, ScoreTableShowsPointsFailuresAndTotal) {
  std::ostringstream out;
  print_score_table(out, sample_results());
  std::string s = out.str();
  EXPECT_NE(s.find("Part 3"), std::string::npos) << s;
  EXPECT_NE(s.find("7.5/10"), std::string::npos) << s;
  EXPECT_NE(s.find("FAIL"), std::string::npos) << s;
  EXPECT_NE(s.find("block (3,5) is 12% too dark"), std::string::npos) << s;
  EXPECT_NE(s.find("skipped"), std::string::npos) << s;
  EXPECT_NE(s.find("Total: 7.5/15"), std::string::npos) << s;
  EXPECT_FALSE(all_passed(sample_results()));
  std::vector<CheckResult> good = {sample_results()[0], sample_results()[3]};
  EXPECT_TRUE(all_passed(good));
}

}  // namespace
}  // namespace pt::grader
