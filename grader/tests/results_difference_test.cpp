// The measure of what a student chose in a results file (results_difference.h) counts what it
// must: every character two results differ in, field by field, and nothing they share.
#include "grader/tests/results_difference.h"

#include <gtest/gtest.h>

namespace pt::grader::testing {
namespace {

TEST(GraderResultsDifference, CountsTheCharactersOutsideWhatTwoTextsShare) {
  EXPECT_EQ(differing_characters(std::string("t is 1.234, not 2"), std::string("t is 1.234, not 2")), 0u);
  EXPECT_EQ(differing_characters(std::string("t is 1.234"), std::string("t is 5.678")), 4u);
  EXPECT_EQ(differing_characters(std::string(""), std::string("abc")), 3u);
  EXPECT_EQ(differing_characters(std::string("exited with status 3"),
                                 std::string("exited with status 203")), 2u);
}

TEST(GraderResultsDifference, CountsFieldByFieldAndWholeWhereOneSideHasNone) {
  const nlohmann::json a = {{"score", 0}, {"tests", {{{"output", "got 1.5"}}}}, {"execution_time", 12}};
  nlohmann::json b = a;
  EXPECT_EQ(differing_characters(a, b), 0u);
  b["tests"][0]["output"] = "got 2.5";
  b["execution_time"] = 13;
  EXPECT_EQ(differing_characters(a, b), 2u);
  b["extra"] = "abc";  // 5 for the key, 5 for "abc" as JSON writes it
  EXPECT_EQ(differing_characters(a, b), 12u);
  b["tests"].push_back({{"x", 1}});
  EXPECT_EQ(differing_characters(a, b), 12u + nlohmann::json({{"x", 1}}).dump().size());
}

}  // namespace
}  // namespace pt::grader::testing
