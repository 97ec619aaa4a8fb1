// The main of every test executable: GoogleTest's, plus a sealed report for the grader. When the
// grader starts a test it passes two descriptors: one it will read the report from, and one that
// holds a nonce it drew and keeps. The listener below writes one line per finished test to the
// report descriptor, each carrying the nonce, and a last line when the program ends normally.
// The grader counts a test as passed only from such a line with its nonce, together with a clean
// exit, so exit(0) or _Exit(0) inside a test, a printed "[       OK ]" or "[  SKIPPED ]" line, or
// a JUnit or results file the test wrote, never reads as a pass (docs/grading.md, "Outcomes
// student code cannot forge").
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

namespace {

/// Writes all of `text` to `fd`, or gives up silently (the grader then sees no line: a failure).
void write_all(int fd, const std::string& text) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    ssize_t n = write(fd, p, left);
    if (n <= 0) return;
    p += n;
    left -= size_t(n);
  }
}

/// Reports each test's outcome, with the nonce, to the grader's descriptor.
class SealedReporter : public testing::EmptyTestEventListener {
 public:
  SealedReporter(int fd, std::string nonce) : fd_(fd), nonce_(std::move(nonce)) {}

  void OnTestEnd(const testing::TestInfo& info) override {
    const testing::TestResult* r = info.result();
    const char* status = r->Skipped() ? "skipped" : r->Passed() ? "passed" : "failed";
    write_all(fd_, "PTREPORT " + nonce_ + " test " + info.test_suite_name() + "." + info.name() +
                       " " + status + "\n");
    ++finished_;
  }
  void OnTestProgramEnd(const testing::UnitTest&) override {
    write_all(fd_, "PTREPORT " + nonce_ + " end " + std::to_string(finished_) + "\n");
  }

 private:
  int fd_;
  std::string nonce_;
  int finished_ = 0;
};

/// The nonce from the descriptor named by PT_NONCE_FD (read once, then closed), or "".
std::string take_nonce() {
  const char* fd_text = std::getenv("PT_NONCE_FD");
  if (!fd_text) return "";
  int fd = std::atoi(fd_text);
  std::string nonce;
  char buf[128];
  for (ssize_t n; (n = read(fd, buf, sizeof buf)) > 0;) nonce.append(buf, size_t(n));
  close(fd);
  unsetenv("PT_NONCE_FD");
  while (!nonce.empty() && (nonce.back() == '\n' || nonce.back() == ' ')) nonce.pop_back();
  return nonce;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  if (const char* report = std::getenv("PT_REPORT_FD")) {
    int fd = std::atoi(report);
    unsetenv("PT_REPORT_FD");
    std::string nonce = take_nonce();
    if (fd > 2 && !nonce.empty())
      testing::UnitTest::GetInstance()->listeners().Append(new SealedReporter(fd, nonce));
  }
  return RUN_ALL_TESTS();
}
