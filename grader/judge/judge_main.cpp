// The main of a judge: a part's test program in which the part's functions read the probe's
// record instead of running (replay_partN.cpp). It holds no student code and runs as the
// grader's user; its GoogleTest verdict is the check's verdict. PT_REPLAY_FILE names the record.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "grader/judge/record.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const char* path = std::getenv("PT_REPLAY_FILE");
  if (!path && GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();  // listing needs no record
  if (!path) {
    std::cerr << "judge: PT_REPLAY_FILE names no record\n";
    return 2;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << "judge: cannot read the record " << path << "\n";
    return 2;
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  pt::judge::load_record(bytes.str());
  int status = RUN_ALL_TESTS();
  if (!pt::judge::record_consumed()) {
    std::cout << "JUDGE: the record holds calls the test did not make\n";
    return 3;
  }
  return status;
}
