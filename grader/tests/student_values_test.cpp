// The student's values in the grader's words: every number a judge, a comparison or a process's
// ending wrote is marked, printed again in at most kValueChars characters, and shown only while
// the results' budget lasts; a byte dump, a quoted character and a forged marker show nothing.
#include "grader/student_values.h"

#include <string>

#include <gtest/gtest.h>

namespace pt::grader {
namespace {

// What GoogleTest writes for an EXPECT_NEAR that fails on two of the student's doubles.
const std::string kNear =
    "parts/1-raygen/tests/step4_sphere_test.cpp:87: Failure\n"
    "The difference between t and expected is 0.12345678901234566, which exceeds 1e-4, where\n"
    "t evaluates to -1.2345678901234567e-300,\nexpected evaluates to 4.5, and\n"
    "1e-4 evaluates to 0.0001.";

std::string all_shown(const std::string& text) { return release_values(text, nullptr); }

TEST(GraderStudentValues, EveryNumberIsMarkedAndBoundedButTheTestsOwnLine) {
  const std::string marked = mark_values(kNear);
  EXPECT_EQ(marked_values(marked), 6);  // 1e-4 twice (the test's own words), and 4 values
  const std::string shown = all_shown(marked);
  EXPECT_NE(shown.find("step4_sphere_test.cpp:87: Failure"), std::string::npos) << shown;
  EXPECT_NE(shown.find("is 0.1235, which"), std::string::npos) << shown;
  EXPECT_NE(shown.find("t evaluates to -1.235e-300,"), std::string::npos) << shown;
  EXPECT_NE(shown.find("expected evaluates to 4.5, and"), std::string::npos) << shown;
  EXPECT_EQ(shown.find("12345678901"), std::string::npos) << shown;
}

TEST(GraderStudentValues, AValueIsAtMostItsCharacters) {
  for (const char* v : {"-1.2345678901234567e-300", "123456789012345678901234567890", "-999999",
                        "0xffffffffffffffff", "-0.000012345678901234", "3.4028234663852886e+38"}) {
    const std::string shown = all_shown(mark_values(v));
    EXPECT_LE(shown.size(), size_t(kValueChars)) << v << " -> " << shown;
  }
  EXPECT_EQ(all_shown(mark_values("-999999")), "-999999");  // an integer below 10^6, exactly
}

TEST(GraderStudentValues, DigitsInsideWordsAreTheGradersOwn) {
  const std::string text = "part1.step3.render.cornell_spheres, parts/1-raygen, bvh2, x86_64, 3D";
  EXPECT_EQ(marked_values(mark_values(text)), 0);
  EXPECT_EQ(all_shown(mark_values(text)), text);
}

TEST(GraderStudentValues, BytesAndCharactersGoogleTestQuotesAreMasked) {
  const std::string text = "Which is: 12-byte object <3F-80 00 00 41-42 43 44 45-46 47 48>\n"
                           "Which is: 'Q' (81, 0x51)";
  const std::string shown = all_shown(mark_values(text));
  EXPECT_EQ(shown.find("3F-80"), std::string::npos) << shown;
  EXPECT_EQ(shown.find("'Q'"), std::string::npos) << shown;
  EXPECT_NE(shown.find("12-byte object"), std::string::npos) << shown;
}

TEST(GraderStudentValues, AMarkerInTheTextComingInIsNoMarker) {
  // A judge that printed the student's bytes could print the marker characters themselves.
  const std::string forged = std::string("x \x1f") + "secret text" + "\x1e y";
  const std::string marked = mark_values(forged);
  EXPECT_EQ(marked_values(marked), 0);
  EXPECT_EQ(all_shown(marked), "x secret text y");
}

TEST(GraderStudentValues, TheBudgetShowsTheFirstValuesAndHidesTheRest) {
  const std::string marked = mark_values("1 2 3 4 5 6 7 8");
  int left = 100;
  EXPECT_EQ(release_values(marked, &left), "1 2 3 4 5 6 \xe2\x80\xa6 \xe2\x80\xa6");  // 6 a text
  EXPECT_EQ(left, 100 - kValuesPerStep);
  left = 2;
  EXPECT_EQ(release_values(marked, &left, 8), "1 2 \xe2\x80\xa6 \xe2\x80\xa6 \xe2\x80\xa6 \xe2\x80\xa6 \xe2\x80\xa6 \xe2\x80\xa6");
  EXPECT_EQ(left, 0);
  int none = 0;
  EXPECT_EQ(marked_values(release_values(marked, &none)), 0);
}

}  // namespace
}  // namespace pt::grader
