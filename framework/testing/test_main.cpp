// Not needed for the assignment.
// The main of every test executable a developer runs (ctest): GoogleTest's own. The grader does
// not read these programs' verdicts: it runs each part's tests as probes and decides them by
// their judges (grader/judge/).
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
