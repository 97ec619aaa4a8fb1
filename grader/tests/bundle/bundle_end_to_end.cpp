// The Gradescope bundle end to end, the way Gradescope runs it, under a temporary root folder:
// `grader gradescope` writes the zip, setup.sh builds the instructor's tree once, and
// run_autograder grades, on that one tree, the complete solution (full marks), the handout (0,
// no crash), a submission that does not compile, and each cheater of grader/tests/cheaters (no
// more than the honest stub it replaces, the rest of the submission still graded). Prints each
// case's score and time: the figures of the bundle's report.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/process/child_process.h"
#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"
#include "framework/text/text_file.h"
#include "grader/bundle.h"
#include "grader/report.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

const fs::path kSource = pt::test::source_dir();
const char* kSphereFile = "parts/1-raygen/sphere_intersect.cpp";

/// One temporary root with the bundle set up in it, shared by every case.
class Bundle {
 public:
  Bundle() : dir_("pt-bundle-e2e") {
    root_ = dir_.path() / "root";
    fs::create_directories(root_ / "source");
    fs::path zip = dir_.path() / "bundle.zip";
    ChildResult made = run_child({GRADER_EXE, "--source", kSource.string(), "gradescope", zip.string()}, 600);
    ok_ = made.ok();
    log_ += made.output;
    if (!ok_) return;
    zip_bytes_ = (long long)fs::file_size(zip);
    ChildResult unzip = run_child({"unzip", "-q", zip.string(), "-d", (root_ / "source").string()}, 600);
    ok_ = unzip.ok();
    if (!ok_) return;
    // The complete solution's student files, as the bundle holds them (setup.sh replaces them
    // with the stubs in the tree).
    fs::path project = root_ / "source" / "project";
    for (const std::string& rel : student_files(project.string()))
      solution_[rel] = read_text_file(project / rel);
    ChildOptions o;
    o.limits.wall_seconds = 3600;
    o.limits.max_output = 64 << 10;
    o.environment = {"PT_AUTOGRADER_ROOT=" + root_.string(), "PT_SKIP_PACKAGES=1", "PT_JOBS=2",
                     "PT_CCACHE=1"};
    ChildResult setup = run_child({"bash", (root_ / "source" / "setup.sh").string()}, o);
    setup_seconds_ = setup.seconds;
    ok_ = setup.ok();
    log_ += setup.output;
  }

  bool ok() const { return ok_; }
  const std::string& log() const { return log_; }
  double setup_seconds() const { return setup_seconds_; }
  long long zip_bytes() const { return zip_bytes_; }
  const std::map<std::string, std::string>& solution() const { return solution_; }

  /// Grades a submission of the files `files` (relative path -> text) as run_autograder does,
  /// and returns results.json (empty when it is missing or not JSON).
  nlohmann::json grade(const std::map<std::string, std::string>& files, const std::string& parts,
                       double* seconds, const std::vector<std::string>& extra_env = {}) {
    fs::path submission = root_ / "submission";
    fs::remove_all(submission);
    for (const auto& [rel, text] : files) {
      fs::create_directories((submission / rel).parent_path());
      std::ofstream(submission / rel) << text;
    }
    ChildOptions o;
    o.limits.wall_seconds = 3600;
    o.limits.max_output = 64 << 10;
    o.environment = {"PT_AUTOGRADER_ROOT=" + root_.string(), "PT_AUTOGRADER_PARTS=" + parts};
    o.environment.insert(o.environment.end(), extra_env.begin(), extra_env.end());
    ChildResult run = run_child({"bash", (root_ / "source" / "run_autograder").string()}, o);
    *seconds = run.seconds;
    EXPECT_TRUE(run.ok()) << run.describe() << "\n" << run.output;
    try {
      return nlohmann::json::parse(read_text_file(root_ / "results" / "results.json"));
    } catch (const std::exception& e) {
      ADD_FAILURE() << "results.json: " << e.what();
      return {};
    }
  }

 private:
  test::TempFolder dir_;
  fs::path root_;
  bool ok_ = false;
  std::string log_;
  double setup_seconds_ = 0.0;
  long long zip_bytes_ = 0;
  std::map<std::string, std::string> solution_;
};

double max_score(const nlohmann::json& results) {
  double m = 0.0;
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array()))
    m += t.value("max_score", 0.0);
  return m;
}

std::string outputs(const nlohmann::json& results) {
  std::string s = results.value("output", "") + "\n";
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array()))
    s += "  " + t.value("name", "") + " " + std::to_string(t.value("score", 0.0)) + "/" +
         std::to_string(t.value("max_score", 0.0)) + ": " + t.value("output", "").substr(0, 300) + "\n";
  return s;
}

TEST(GraderBundle, EndToEndInATemporaryRoot) {
  if (geteuid() != 0) GTEST_SKIP() << "the bundle runs as root (as on Gradescope)";
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each case's line as it ends, not at the end
  Bundle bundle;
  ASSERT_TRUE(bundle.ok()) << bundle.log();
  std::printf("bundle: %.1f MB, setup.sh %.0f s\n", bundle.zip_bytes() / 1048576.0,
              bundle.setup_seconds());
  double seconds = 0.0;

  // The complete solution: full marks on every part.
  nlohmann::json full = bundle.grade(bundle.solution(), "", &seconds);
  EXPECT_EQ(validate_gradescope(full), "");
  EXPECT_GT(max_score(full), 0.0);
  EXPECT_DOUBLE_EQ(full.value("score", -1.0), max_score(full)) << outputs(full);
  EXPECT_TRUE(full["extra_data"].value("protected", false));
  std::printf("complete solution: %g/%g in %.0f s\n", full.value("score", -1.0), max_score(full), seconds);

  // The handout: nothing submitted at all grades every stub, 0, no crash.
  nlohmann::json empty = bundle.grade({}, "", &seconds);
  EXPECT_EQ(validate_gradescope(empty), "");
  EXPECT_DOUBLE_EQ(empty.value("score", -1.0), 0.0) << outputs(empty);
  EXPECT_NE(empty.value("output", "").find("missing: parts/1-raygen/camera_ray.cpp"), std::string::npos);
  std::printf("handout (empty submission): %g/%g in %.0f s\n", empty.value("score", -1.0),
              max_score(empty), seconds);

  // Part 1 with an honest stub for the sphere: the baseline no cheater may beat.
  std::map<std::string, std::string> files = bundle.solution();
  files.erase(kSphereFile);
  files["extra/notes.txt"] = "not graded";
  nlohmann::json stub = bundle.grade(files, "1", &seconds);
  double baseline = stub.value("score", -1.0);
  EXPECT_GT(baseline, 0.0) << outputs(stub);
  EXPECT_LT(baseline, max_score(stub));
  EXPECT_NE(stub.value("output", "").find("extra/notes.txt"), std::string::npos);
  std::printf("part 1, sphere left as the stub: %g/%g in %.0f s\n", baseline, max_score(stub), seconds);

  // A compile error: a clear result, not a crash.
  files = bundle.solution();
  files[kSphereFile] = "this is not C++\n";
  nlohmann::json broken = bundle.grade(files, "1", &seconds);
  EXPECT_EQ(validate_gradescope(broken), "");
  EXPECT_DOUBLE_EQ(broken.value("score", -1.0), 0.0);
  EXPECT_NE(broken.dump().find("did not build"), std::string::npos) << outputs(broken);
  std::printf("part 1, compile error: %g/%g in %.0f s\n", broken.value("score", -1.0),
              max_score(broken), seconds);

  // The cheaters: each replaces one student file (the sphere's unless its first lines say
  // "replaces FILE"); none may score more than that file's honest stub, and every other check
  // of the part is still graded (the same score as the stub, but for the one that does not
  // compile).
  std::map<std::string, double> baselines = {{kSphereFile, baseline}};
  for (const fs::directory_entry& e : fs::directory_iterator(kSource / "grader/tests/cheaters")) {
    std::string name = e.path().stem().string();
    std::string text = read_text_file(e.path());
    std::string target = kSphereFile;
    size_t at = text.substr(0, 400).find("replaces ");
    if (at != std::string::npos) target = text.substr(at + 9, text.find_first_of("):\n", at) - at - 9);
    if (!baselines.count(target)) {
      files = bundle.solution();
      files.erase(target);
      nlohmann::json honest = bundle.grade(files, "1", &seconds);
      baselines[target] = honest.value("score", -1.0);
      std::printf("part 1, %s left as the stub: %g/%g in %.0f s\n", target.c_str(),
                  baselines[target], max_score(honest), seconds);
    }
    baseline = baselines[target];
    files = bundle.solution();
    files[target] = text;
    nlohmann::json r = bundle.grade(files, "1", &seconds,
                                    {"PT_AUTOGRADER_MAX_CHECK_SECONDS=5", "PT_AUTOGRADER_DISK_MB=64"});
    double score = r.value("score", -1.0);
    EXPECT_EQ(validate_gradescope(r), "") << name;
    std::printf("cheater %-20s %g/%g in %.0f s\n", name.c_str(), score, max_score(r), seconds);
    if (name == "read_solution") {
      // The solution copy cannot be read at build time: its #include is a compile error.
      EXPECT_DOUBLE_EQ(score, 0.0) << outputs(r);
      EXPECT_NE(r.dump().find("Permission denied"), std::string::npos) << outputs(r);
    } else {
      EXPECT_DOUBLE_EQ(score, baseline) << name << "\n" << outputs(r);
    }
    if (name == "read_manifest") EXPECT_NE(r.dump().find("CHEAT read manifest.json: 0 bytes"), std::string::npos) << outputs(r);
  }
  std::fflush(stdout);
}

}  // namespace
}  // namespace pt::grader
