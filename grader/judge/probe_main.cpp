// The main of a probe: a part's test program linked with the student's part, run by the grader
// as the student's user. It decides nothing: the record it writes to the descriptor PT_RECORD_FD
// names is what the student's functions gave the test, and the judge (judge_main.cpp) decides.
// GoogleTest's own verdicts here are only for a person reading the output.
#include <cstdlib>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "framework/testing/probe_mode.h"
#include "grader/judge/record.h"

namespace {

/// Writes the record out after every test, so a crash in a later one loses nothing before it.
class FlushAfterEachTest : public testing::EmptyTestEventListener {
  void OnTestEnd(const testing::TestInfo&) override { pt::judge::flush_record(); }
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  // The tests may leave their expectations to the judge, which computes them itself.
  pt::test::set_probe();
  // One thread: the judge replays the calls in the order they were made, so the probe makes them
  // in the one order the test's code gives (a parallel loop on one thread runs in order).
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  if (const char* fd = std::getenv("PT_RECORD_FD")) {
    pt::judge::start_recording(std::atoi(fd));
    unsetenv("PT_RECORD_FD");
  }
  testing::UnitTest::GetInstance()->listeners().Append(new FlushAfterEachTest);
  int status = RUN_ALL_TESTS();
  pt::judge::flush_record();
  return status;
}
