// The Gradescope bundle end to end, the way Gradescope runs it, under a temporary root folder:
// `grader gradescope` writes the zip, setup.sh builds the instructor's tree once, and every case
// below grades on that one tree: `grader batch` on three small submissions, the complete
// solution (full marks), the handout (0, no crash), a submission that does not compile, and the
// cheaters of grader/tests/cheaters, two at a time where they replace different files (no step
// scores more than with the honest stubs of those files, every step that does not rest on them
// keeps its full marks), and a cheater that smuggles a payload out by every channel it has, graded
// with two payloads (the results differ in at most 512 characters). Each case prints its score
// and time: the figures of the bundle's report.
// Not a test of the suite (it takes most of half an hour): tools/bundle_check runs it.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grader/process/child_process.h"
#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"
#include "framework/text/text_file.h"
#include "grader/autograde.h"
#include "grader/batch.h"
#include "grader/bundle.h"
#include "grader/handout.h"
#include "grader/report.h"
#include "grader/sandbox.h"
#include "grader/student_traces.h"
#include "grader/tests/results_difference.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

const fs::path kSource = pt::test::source_dir();
const std::string kSphere = "parts/1-raygen/sphere_intersect.cpp";
const std::string kTriangle = "parts/1-raygen/triangle_intersect.cpp";
// The cheater runs' cap on every test and render: an endless loop or a memory bomb costs this
// per check that calls it, not the part's own minute. Every honest check of Part 1 takes far less.
const char* kCheckCap = "PT_AUTOGRADER_MAX_CHECK_SECONDS=10";
// The cheaters' runs quote any "not implemented" line (Gradescope quotes only the handout's own
// stub lines), so that what an attack got can be read in the results.
const char* kQuoteAll = "PT_AUTOGRADER_QUOTE_STUDENT_LINES=1";

using Files = std::map<std::string, std::string>;

/// One temporary root with the bundle set up in it, shared by every case.
class Bundle {
 public:
  Bundle() : dir_("pt-bundle-e2e") {
    root_ = dir_.path() / "root";
    fs::create_directories(root_ / "source");
    zip_ = dir_.path() / "bundle.zip";
    ChildResult made = run_child({GRADER_EXE, "--source", kSource.string(), "gradescope", zip_.string()}, 600);
    log_ += made.output;
    if (!made.ok()) return;
    zip_bytes_ = (long long)fs::file_size(zip_);
    ChildResult unzip = run_child({"unzip", "-q", zip_.string(), "-d", (root_ / "source").string()}, 600);
    log_ += unzip.output;
    if (!unzip.ok()) return;
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
    log_ += setup.output;
    ok_ = setup.ok();
  }

  bool ok() const { return ok_; }
  const std::string& log() const { return log_; }
  const fs::path& root() const { return root_; }
  const fs::path& zip() const { return zip_; }
  fs::path scratch() const { return dir_.path(); }
  double setup_seconds() const { return setup_seconds_; }
  long long zip_bytes() const { return zip_bytes_; }
  const Files& solution() const { return solution_; }

  /// Grades a submission of `files` (relative path -> text) as run_autograder does, parts
  /// `parts` ("" for all), and returns results.json (empty when it is missing or not JSON).
  nlohmann::json grade(const Files& files, const std::string& parts, double* seconds,
                       const std::vector<std::string>& extra_env = {}) {
    fs::path submission = root_ / "submission";
    fs::remove_all(submission);
    write_files(submission, files);
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

  static void write_files(const fs::path& dir, const Files& files) {
    fs::create_directories(dir);
    for (const auto& [rel, text] : files) {
      fs::create_directories((dir / rel).parent_path());
      std::ofstream(dir / rel) << text;
    }
  }

 private:
  test::TempFolder dir_;
  fs::path root_, zip_;
  bool ok_ = false;
  std::string log_;
  double setup_seconds_ = 0.0;
  long long zip_bytes_ = 0;
  Files solution_;
};

double max_score(const nlohmann::json& results) {
  double m = 0.0;
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array()))
    m += t.value("max_score", 0.0);
  return m;
}

/// Each step's score by its name.
std::map<std::string, double> step_scores(const nlohmann::json& results) {
  std::map<std::string, double> s;
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array()))
    s[t.value("name", "")] = t.value("score", 0.0);
  return s;
}

std::string outputs(const nlohmann::json& results) {
  std::string s = results.value("output", "") + "\n";
  for (const nlohmann::json& t : results.value("tests", nlohmann::json::array()))
    s += "  " + t.value("name", "") + " " + std::to_string(t.value("score", 0.0)) + "/" +
         std::to_string(t.value("max_score", 0.0)) + ": " + t.value("output", "").substr(0, 300) + "\n";
  return s;
}

/// The student file a cheater replaces: the one its opening comment names after "replaces ",
/// else the sphere's.
std::string replaced_file(const std::string& text) {
  size_t at = text.substr(0, 400).find("replaces ");
  if (at == std::string::npos) return kSphere;
  return text.substr(at + 9, text.find_first_of("):\n", at) - at - 9);
}

class GraderBundle : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each case's line as it ends, not at the end
    if (geteuid() != 0) return;
    bundle_ = new Bundle;
    std::printf("bundle: %.1f MB, setup.sh %.0f s\n", bundle_->zip_bytes() / 1048576.0,
                bundle_->setup_seconds());
  }
  static void TearDownTestSuite() {
    delete bundle_;
    bundle_ = nullptr;
  }
  void SetUp() override {
    if (geteuid() != 0) GTEST_SKIP() << "the bundle runs as root (as on Gradescope)";
    ASSERT_TRUE(bundle_->ok()) << bundle_->log();
  }
  static Bundle* bundle_;
  /// Part 1's step scores with the sphere's and the triangle's stubs (the cheaters' baseline).
  static std::map<std::string, double> part1_stubs_;
};
Bundle* GraderBundle::bundle_ = nullptr;
std::map<std::string, double> GraderBundle::part1_stubs_;

/// What leave_behind.cc's processes say they found of an earlier one's: 0 bytes, every time it is
/// quoted (and it is quoted at least once); where namespaces are refused, nothing could be left
/// either.
void expect_nothing_found(const nlohmann::json& r, bool nothing_left) {
  const std::string all = r.dump();
  std::regex said("CHEAT found ([0-9]+) bytes left behind, left ([0-9]+) copies");
  int lines = 0;
  for (std::sregex_iterator it(all.begin(), all.end(), said), end; it != end; ++it) {
    ++lines;
    EXPECT_EQ((*it)[1].str(), "0") << "a later process found what an earlier one left:\n" << outputs(r);
    if (nothing_left) {
      EXPECT_EQ((*it)[2].str(), "0") << "a process left a copy:\n" << outputs(r);
    }
  }
  EXPECT_GT(lines, 0) << "no process of the attack was quoted:\n" << outputs(r);
}

// What the student's code can reach: no SOLUTION-ONLY folder in the zip at all, and a
// solution-only file that stays (a stress test with a working answer) the grader's alone.
TEST_F(GraderBundle, KeepsTheSolutionOnlyFilesFromTheStudent) {
  ChildResult list = run_child({"unzip", "-Z1", bundle_->zip().string()}, 120, {}, 16 << 20);
  ASSERT_TRUE(list.ok()) << list.output;
  std::set<std::string> zipped;
  std::istringstream in(list.output);
  for (std::string l; std::getline(in, l);) zipped.insert(l);
  int left_out = 0;
  for (const std::string& rel : tracked_files(kSource.string())) {
    if (!in_solution_only_folder(kSource, rel)) continue;
    ++left_out;
    EXPECT_FALSE(zipped.count("project/" + rel)) << rel << " is in the bundle";
  }
  EXPECT_GT(left_out, 0) << "no SOLUTION-ONLY folder in the tree: the check above checked nothing";
  const std::string stress = "parts/1-raygen/tests/step3_triangle_stress_test.cpp";
  ASSERT_TRUE(is_solution_only(read_text_file(kSource / stress)));
  fs::path in_tree = bundle_->root() / "source" / "project" / stress;
  ASSERT_TRUE(fs::exists(in_tree));
  EXPECT_EQ(fs::status(in_tree).permissions() & fs::perms::all, fs::perms(0600));
  // It does not break the student's build: every case below builds Part 1 beside it.
}

// grader batch first, on the tree as setup.sh left it (batch copies that tree for every run):
// a complete Part 1, the handout's, and one that does not compile, two at a time.
TEST_F(GraderBundle, BatchGradesEverySubmissionWithItsOwnResults) {
  fs::path dir = bundle_->scratch() / "batch";
  Files complete, broken = bundle_->solution();
  for (const auto& [rel, text] : bundle_->solution())
    if (rel.rfind("parts/1-raygen/", 0) == 0) complete[rel] = text;
  broken[kSphere] = "this is not C++\n";
  Bundle::write_files(dir / "alice", complete);
  Bundle::write_files(dir / "bob", {});
  Bundle::write_files(dir / "carol", broken);
  fs::path out = bundle_->scratch() / "batch-results";
  ChildOptions o;
  o.limits.wall_seconds = 3600;
  ChildResult c = run_child({GRADER_EXE, "batch", dir.string(), "--root", bundle_->root().string(),
                             "--out", out.string(), "--parts", "1", "--jobs", "2"}, o);
  ASSERT_TRUE(c.ok()) << c.describe() << "\n" << c.output;
  std::printf("batch of 3 submissions (Part 1), 2 at a time: %.0f s\n", c.seconds);
  std::map<std::string, nlohmann::json> r;
  for (const char* name : {"alice", "bob", "carol"}) {
    r[name] = nlohmann::json::parse(read_text_file(out / name / "results.json"));
    EXPECT_EQ(validate_gradescope(r[name]), "") << name;
    EXPECT_NE(c.output.find(std::string(name) + ": "), std::string::npos) << "no score line for " << name << "\n" << c.output;
  }
  EXPECT_GT(max_score(r["alice"]), 0.0);
  EXPECT_DOUBLE_EQ(r["alice"].value("score", -1.0), max_score(r["alice"])) << outputs(r["alice"]);
  EXPECT_TRUE(r["alice"]["extra_data"].value("protected", false));
  EXPECT_DOUBLE_EQ(r["bob"].value("score", -1.0), 0.0) << outputs(r["bob"]);
  EXPECT_DOUBLE_EQ(r["carol"].value("score", -1.0), 0.0) << outputs(r["carol"]);
  EXPECT_NE(r["carol"].dump().find("did not build"), std::string::npos) << outputs(r["carol"]);
  // The CSV: a header and one row per step of each submission, the points those results give.
  std::string csv = read_text_file(out / "scores.csv");
  std::vector<BatchScore> rows;
  for (const char* name : {"alice", "bob", "carol"}) {
    std::vector<BatchScore> s = scores_of(name, r[name]);
    EXPECT_FALSE(s.empty()) << name;
    rows.insert(rows.end(), s.begin(), s.end());
  }
  EXPECT_EQ(csv, scores_csv(rows));
  EXPECT_NE(csv.find("\nalice,1,part1.step1.camera_ray,3,3\n"), std::string::npos) << csv;
}

TEST_F(GraderBundle, CompleteSolutionHasFullMarks) {
  double seconds = 0.0;
  nlohmann::json full = bundle_->grade(bundle_->solution(), "", &seconds);
  EXPECT_EQ(validate_gradescope(full), "");
  EXPECT_GT(max_score(full), 0.0);
  EXPECT_DOUBLE_EQ(full.value("score", -1.0), max_score(full)) << outputs(full);
  EXPECT_TRUE(full["extra_data"].value("protected", false));
  std::printf("complete solution: %g/%g in %.0f s\n", full.value("score", -1.0), max_score(full), seconds);
}

// The handout: nothing submitted at all grades every stub of every part, 0, no crash. Under the
// cheaters' cap: a stub's check that runs to the cap fails, as it would at the part's own limit.
TEST_F(GraderBundle, HandoutScoresZero) {
  double seconds = 0.0;
  nlohmann::json empty = bundle_->grade({}, "", &seconds, {kCheckCap});
  EXPECT_EQ(validate_gradescope(empty), "");
  EXPECT_GT(max_score(empty), 0.0);
  EXPECT_DOUBLE_EQ(empty.value("score", -1.0), 0.0) << outputs(empty);
  EXPECT_NE(empty.value("output", "").find("missing: parts/1-raygen/camera_ray.cpp"), std::string::npos);
  // The stubs' own lines are quoted (they are what stub_messages lists, word for word).
  EXPECT_NE(empty.dump().find("part 1 not implemented: generate_camera_ray at parts/1-raygen/camera_ray.cpp:"),
            std::string::npos) << outputs(empty);
  std::printf("handout (empty submission): %g/%g in %.0f s\n", empty.value("score", -1.0),
              max_score(empty), seconds);
}

TEST_F(GraderBundle, CompileErrorIsAResult) {
  double seconds = 0.0;
  Files files = bundle_->solution();
  files[kSphere] = "this is not C++\n";
  files["extra/notes.txt"] = "not graded";
  nlohmann::json broken = bundle_->grade(files, "1", &seconds);
  EXPECT_EQ(validate_gradescope(broken), "");
  EXPECT_GT(max_score(broken), 0.0);
  EXPECT_DOUBLE_EQ(broken.value("score", -1.0), 0.0);
  EXPECT_NE(broken.dump().find("did not build"), std::string::npos) << outputs(broken);
  // Counted, never named (a name is the student's text).
  EXPECT_NE(broken.value("output", "").find("not graded: 1 other file"), std::string::npos) << outputs(broken);
  std::printf("part 1, compile error: %g/%g in %.0f s\n", broken.value("score", -1.0),
              max_score(broken), seconds);
}

// The cheaters: each replaces one student file of Part 1 (the sphere's unless its first lines say
// "replaces FILE"). A sphere cheater and a triangle cheater go in one submission: their steps
// are apart (the sphere's, the triangle's), and the renders, which rest on both, must score no
// more than with both honest stubs. Every step that the stubs leave at full marks (the camera's
// and the pixel loop's) must keep them: the rest of the submission is still graded.
TEST_F(GraderBundle, CheatersGetNothingForWhatTheyAttack) {
  double seconds = 0.0;
  Files files = bundle_->solution();
  files.erase(kSphere);
  files.erase(kTriangle);
  nlohmann::json stubs = bundle_->grade(files, "1", &seconds, {kCheckCap});
  std::map<std::string, double> baseline = step_scores(stubs);
  ASSERT_FALSE(baseline.empty()) << outputs(stubs);
  part1_stubs_ = baseline;
  std::printf("part 1, sphere and triangle left as the stubs: %g/%g in %.0f s\n",
              stubs.value("score", -1.0), max_score(stubs), seconds);
  std::map<std::string, double> full;
  for (const nlohmann::json& t : stubs.value("tests", nlohmann::json::array()))
    full[t.value("name", "")] = t.value("max_score", 0.0);
  int kept = 0;
  for (const auto& [step, score] : baseline) kept += score == full[step] ? 1 : 0;
  EXPECT_GT(kept, 0) << "no step of Part 1 stands without the sphere and the triangle:\n" << outputs(stubs);

  std::map<std::string, std::vector<std::pair<std::string, std::string>>> by_file;  // file -> (name, text)
  for (const fs::directory_entry& e : fs::directory_iterator(kSource / "grader/tests/cheaters")) {
    if (!e.is_regular_file()) continue;
    std::string text = read_text_file(e.path());
    by_file[replaced_file(text)].push_back({e.path().stem().string(), text});
  }
  for (auto& [file, list] : by_file) std::sort(list.begin(), list.end());
  ASSERT_EQ(by_file.size(), 2u) << "the cheaters replace the sphere or the triangle";
  // read_solution's #include of the solution copy fails to compile: its whole part is 0, so it
  // goes alone (beside it no other cheater's verdict could be read).
  std::vector<std::vector<std::pair<std::string, std::string>>> groups;
  auto& spheres = by_file[kSphere];
  auto& triangles = by_file[kTriangle];
  // link_time_code's object is refused before the link: its part is 0 too, and it goes alone.
  for (const char* alone : {"read_solution", "link_time_code"})
    for (auto it = spheres.begin(); it != spheres.end(); ++it)
      if (it->first == alone) {
        groups.push_back({*it});
        spheres.erase(it);
        break;
      }
  for (size_t i = 0; i < std::max(spheres.size(), triangles.size()); ++i) {
    groups.emplace_back();
    if (i < spheres.size()) groups.back().push_back(spheres[i]);
    if (i < triangles.size()) groups.back().push_back(triangles[i]);
  }
  const std::vector<std::string> tight = {kCheckCap, "PT_AUTOGRADER_DISK_MB=64", kQuoteAll};
  for (const auto& group : groups) {
    // Both files are replaced, by a cheater or else by the honest stub (the file left out), so
    // that the one run of both stubs is every group's baseline.
    files = bundle_->solution();
    files.erase(kSphere);
    files.erase(kTriangle);
    std::string names;
    for (const auto& [name, text] : group) {
      files[replaced_file(text)] = text;
      names += (names.empty() ? "" : " + ") + name;
    }
    nlohmann::json r = bundle_->grade(files, "1", &seconds, tight);
    double score = r.value("score", -1.0);
    EXPECT_EQ(validate_gradescope(r), "") << names;
    std::printf("cheaters %-40s %g/%g in %.0f s\n", names.c_str(), score, max_score(r), seconds);
    std::string all = r.dump();
    if (group.size() == 1 && group[0].first == "read_solution") {
      // The solution copy cannot be read at build time: its #include is a compile error.
      EXPECT_DOUBLE_EQ(score, 0.0) << outputs(r);
      EXPECT_NE(all.find("did not build"), std::string::npos) << outputs(r);
      EXPECT_NE(all.find("Permission denied"), std::string::npos) << outputs(r);
      continue;
    }
    if (group.size() == 1 && group[0].first == "link_time_code") {
      // Refused before the grader's link: no compiler ever runs on it with the grader's rights.
      EXPECT_DOUBLE_EQ(score, 0.0) << outputs(r);
      EXPECT_NE(all.find("holds link-time code or is no machine code"), std::string::npos) << outputs(r);
      continue;
    }
    std::map<std::string, double> steps = step_scores(r);
    EXPECT_EQ(steps.size(), baseline.size()) << names << "\n" << outputs(r);
    for (const auto& [step, base] : baseline) {
      ASSERT_TRUE(steps.count(step)) << names << ": no result for " << step;
      EXPECT_LE(steps[step], base + 1e-9) << names << " scored more than the stubs on " << step << "\n" << outputs(r);
      if (base == full[step]) {
        EXPECT_DOUBLE_EQ(steps[step], full[step]) << names << " cost " << step << " its points\n" << outputs(r);
      }
    }
    for (const auto& [name, text] : group)
      if (name == "leave_behind") expect_nothing_found(r, false);
    for (const auto& [name, text] : group) {
      if (name != "read_manifest") continue;
      for (const char* what : {"manifest.json: 0 bytes", "part1.normals.cornell_spheres.exr: 0 bytes"}) {
        // It prints what it could read: 0 bytes, nothing.
        EXPECT_NE(all.find(std::string("CHEAT read ") + what), std::string::npos) << what << "\n" << outputs(r);
      }
    }
  }
}

/// The attack of leave_behind.cc in Part 1's triangle and in Part 2's ray-box file (the rest of
/// those parts the stubs), for Parts 1 and 2 in one submission.
Files leave_behind_submission(const Files& solution, const fs::path& stubs) {
  const std::string cheater = read_text_file(kSource / "grader/tests/cheaters/leave_behind.cc");
  const std::string prelude = cheater.substr(0, cheater.find("// The stubs of the file it replaces."));
  Files files;
  for (const auto& [rel, text] : solution)
    if (rel.rfind("parts/2-", 0) != 0) files[rel] = text;
  files.erase(kSphere);
  files[kTriangle] = cheater;
  const std::string ray_box = "parts/2-bvh/ray_box.cpp";
  files[ray_box] = prelude + read_text_file(stubs / ray_box);
  return files;
}

/// Each step of Parts 1 and 2 scores no more than the stubs: Part 1's baseline, Part 2's 0.
void expect_stubs_scores(const nlohmann::json& r, const std::map<std::string, double>& part1) {
  for (const auto& [step, score] : step_scores(r)) {
    if (step.rfind("part1.", 0) == 0) {
      ASSERT_TRUE(part1.count(step)) << step;
      EXPECT_LE(score, part1.at(step) + 1e-9) << step << "\n" << outputs(r);
    } else {
      EXPECT_EQ(score, 0.0) << step << "\n" << outputs(r);
    }
  }
}

// What a process leaves reaches no later one: every process of Parts 1 and 2 (probes, renders,
// each part's isolated renderer, which holds the other parts' solution) looks for what the ones
// before it left and leaves a copy of its code; none finds anything, and the score is the stubs',
// with namespaces and with them refused, in one submission and across two in `grader batch`.
TEST_F(GraderBundle, WhatAProcessLeavesReachesNoLaterOne) {
  if (part1_stubs_.empty()) GTEST_SKIP() << "needs the cheaters' baseline (run the whole suite)";
  const fs::path stubs = bundle_->root() / "pt" / "private" / "stubs";
  const Files files = leave_behind_submission(bundle_->solution(), stubs);
  for (const char* mode : {"on", "off"}) {
    double seconds = 0.0;
    nlohmann::json r = bundle_->grade(files, "1,2", &seconds,
                                      {kCheckCap, kQuoteAll, std::string("PT_SANDBOX_NAMESPACES=") + mode});
    std::printf("left behind, namespaces %s: %g/%g in %.0f s\n", mode, r.value("score", -1.0),
                max_score(r), seconds);
    EXPECT_EQ(r["extra_data"].value("namespaces", std::string("on") == mode), std::string("on") == mode)
        << outputs(r);
    expect_stubs_scores(r, part1_stubs_);
    expect_nothing_found(r, std::string("off") == mode);
  }
  // Two submissions side by side, the second graded while and after the first.
  fs::path dir = bundle_->scratch() / "left-behind";
  Bundle::write_files(dir / "first", files);
  Bundle::write_files(dir / "second", files);
  fs::path out = bundle_->scratch() / "left-behind-results";
  ChildOptions o;
  o.limits.wall_seconds = 3600;
  o.environment = {"PT_SANDBOX_NAMESPACES=off"};
  ChildResult c = run_child({GRADER_EXE, "batch", dir.string(), "--root", bundle_->root().string(),
                             "--out", out.string(), "--parts", "1,2", "--jobs", "2",
                             "--max-check-seconds", "10", "--quote-student-lines"}, o);
  ASSERT_TRUE(c.ok()) << c.describe() << "\n" << c.output;
  std::printf("left behind, grader batch of 2 (namespaces refused): %.0f s\n", c.seconds);
  for (const char* name : {"first", "second"}) {
    nlohmann::json r = nlohmann::json::parse(read_text_file(out / name / "results.json"));
    expect_stubs_scores(r, part1_stubs_);
    expect_nothing_found(r, true);
  }
}

/// Every file under `dir` as the grader sees it (the test runs as root): the targets an attacker
/// who read the bundle's scripts would aim at.
std::vector<fs::path> files_under(const fs::path& dir) {
  std::vector<fs::path> all;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) all.push_back(it->path());
  std::sort(all.begin(), all.end());
  return all;
}

std::string c_string(const std::string& s) {
  std::string r = "\"";
  for (char ch : s) {
    if (ch == '\n') r += "\\n";
    else if (ch == '"' || ch == '\\') r += std::string("\\") + ch;
    else r += ch;
  }
  return r + "\"";
}

/// What an attacker who read the bundle's scripts would aim at in the set-up tree: the programs
/// (the complete solution's renderer, the judges, any probe or isolated renderer, the ordinary
/// test programs) and the files that hold the solution or the verdicts.
struct Targets {
  std::vector<fs::path> programs, secrets;
};

Targets targets_of(const fs::path& root) {
  const fs::path project = root / "source" / "project";
  std::vector<fs::path> programs, secrets;
  for (const fs::path& f : files_under(project / "build" / "secret")) {
    std::string n = f.filename().string();
    if (n.rfind("judge_part", 0) == 0 || n.rfind("probe_part", 0) == 0 ||
        n.rfind("pathtracer_", 0) == 0)
      programs.push_back(f);
    if (f.extension() == ".o" || f.extension() == ".a" || n.rfind("judge_part", 0) == 0 ||
        n == "pathtracer_solution")
      secrets.push_back(f);
  }
  for (const char* p : {"build/app/pathtracer", "build/app/bench"}) programs.push_back(project / p);
  for (const fs::path& f : files_under(project / "build" / "parts"))
    if (f.filename().string().find("_test") != std::string::npos && (fs::status(f).permissions() & fs::perms::owner_exec) != fs::perms::none)
      programs.push_back(f);
  // The private folder but the stubs, which are the handout's and no secret.
  for (const fs::path& f : files_under(root / "pt" / "private"))
    if (f.string().find("/private/stubs/") == std::string::npos) secrets.push_back(f);
  for (const fs::path& f : files_under(project / "reference")) secrets.push_back(f);
  return {programs, secrets};
}

/// A static constructor that, before the test's or the renderer's main, tries every way a
/// student's code could take a grade or the solution at run time: run another program of the
/// tree in its place with its own arguments and descriptors; read the solution, the references,
/// the judges; write a forged record to the probe's descriptor. Whatever it got it prints on a
/// "not implemented" line (the one kind of line the grader quotes). (At compile time the same
/// files are out of the compiler's reach: the test checks that the student's user can open none.)
std::string attack_prelude(const fs::path& root) {
  const Targets t = targets_of(root);
  const std::vector<fs::path>& programs = t.programs;
  const std::vector<fs::path>& secrets = t.secrets;
  std::string s = "#include <cerrno>\n#include <cstdio>\n#include <cstdlib>\n#include <cstring>\n"
                  "#include <fstream>\n#include <iterator>\n#include <string>\n#include <unistd.h>\n"
                  "#include <vector>\nnamespace {\n";
  s += "const char* const kPrograms[] = {\n";
  for (const fs::path& f : programs) s += "  " + c_string(f.string()) + ",\n";
  s += "  nullptr};\nconst char* const kSecrets[] = {\n";
  for (const fs::path& f : secrets) s += "  " + c_string(f.string()) + ",\n";
  s += "  nullptr};\n";
  s += R"(struct Attack {
  Attack() {
    if (std::getenv("PT_CHEAT_DONE")) return;
    setenv("PT_CHEAT_DONE", "1", 1);
    long read = 0;
    for (const char* const* p = kSecrets; *p; ++p) {
      std::ifstream in(*p, std::ios::binary);
      read += long(std::string((std::istreambuf_iterator<char>(in)), {}).size());
    }
    if (const char* fd = std::getenv("PT_RECORD_FD")) {
      const char junk[] = "C\x65\x00\x00\x00\x00\x00\x00R\x65\x00\x00\x04\x00\x00\x00\x00\x00\x00\x00";
      ssize_t w = write(std::atoi(fd), junk, sizeof junk);
      (void)w;
    }
    std::printf("CHEAT read %ld bytes (not implemented)\n", read);
    std::fflush(stdout);
    char self[4096] = {0};
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    (void)n;
    std::string cmdline;
    {
      std::ifstream in("/proc/self/cmdline", std::ios::binary);
      cmdline.assign((std::istreambuf_iterator<char>(in)), {});
    }
    std::vector<char*> argv;
    for (size_t at = 0; at < cmdline.size(); at += std::strlen(cmdline.c_str() + at) + 1)
      argv.push_back(&cmdline[at]);
    argv.push_back(nullptr);
    for (const char* const* p = kPrograms; *p; ++p) {
      if (std::strcmp(*p, self) == 0) continue;
      argv[0] = const_cast<char*>(*p);
      execve(*p, argv.data(), ::environ);
      std::printf("CHEAT exec %s: %s (not implemented)\n", *p, std::strerror(errno));
    }
    std::fflush(stdout);
  }
} attack;
}  // namespace
)";
  return s;
}

// Every route of the attacks above, from every part's files at once: a submission of the
// handout's stubs with the attack before one file of each part scores what the stubs score, 0,
// on every step, and nothing it read or ran shows in the results.
TEST_F(GraderBundle, AttacksFromEveryPartScoreWhatTheStubsScore) {
  const fs::path stubs = bundle_->root() / "pt" / "private" / "stubs";
  Files files;
  std::set<std::string> attacked_parts;
  for (const auto& [rel, text] : bundle_->solution()) {
    std::string part = rel.substr(0, rel.find('/', 6));
    if (attacked_parts.count(part)) continue;
    attacked_parts.insert(part);
    files[rel] = attack_prelude(bundle_->root()) + read_text_file(stubs / rel);
  }
  ASSERT_EQ(attacked_parts.size(), 5u);
  // Compile time: the compiler runs as the student's user, so an #include, __has_include or
  // .incbin of a file reaches it only if that user can open it. None of the targets opens.
  const Targets targets = targets_of(bundle_->root());
  ASSERT_GT(targets.secrets.size(), 20u) << "the set-up tree has no solution objects or judges to aim at";
  Sandbox student = Sandbox::standard((bundle_->scratch() / "probe-scratch").string(), 900);
  ASSERT_TRUE(student.protects());
  const std::string scratch = student.make_scratch("open");
  int opened = 0;
  for (const fs::path& f : targets.secrets) {
    ChildResult open = run_child({"head", "-c", "1", f.string()}, student.options(scratch, 10.0));
    if (open.ok()) {
      ++opened;
      ADD_FAILURE() << "the student's user can read " << f;
    }
  }
  student.finish(scratch);
  std::printf("the student's user opens %d of %zu protected files\n", opened, targets.secrets.size());
  double seconds = 0.0;
  nlohmann::json r = bundle_->grade(files, "", &seconds, {kCheckCap, kQuoteAll});
  EXPECT_EQ(validate_gradescope(r), "");
  std::printf("attacks in every part's files: %g/%g in %.0f s\n", r.value("score", -1.0),
              max_score(r), seconds);
  for (const auto& [step, score] : step_scores(r)) EXPECT_EQ(score, 0.0) << step << "\n" << outputs(r);
  const std::string all = r.dump();
  EXPECT_EQ(all.find("did not build"), std::string::npos) << "the attack should compile:\n" << outputs(r);
  EXPECT_EQ(all.find("did not link"), std::string::npos) << "the attack should link:\n" << outputs(r);
  EXPECT_NE(all.find("CHEAT read 0 bytes"), std::string::npos) << outputs(r);
  std::regex got("CHEAT read ([0-9]+) bytes");
  for (std::sregex_iterator it(all.begin(), all.end(), got), end; it != end; ++it)
    EXPECT_EQ((*it)[0].str(), "CHEAT read 0 bytes") << outputs(r);
}

// An image rendered beforehand (here the manifest's own reference, the best one a student could
// have) written to the render's output before main: the graded render is of a variant drawn for
// this grading, so it matches nothing, and every render of Part 1 fails as the stubs' do.
TEST_F(GraderBundle, AnImageRenderedBeforehandPassesNoRender) {
  const fs::path reference = kSource / "reference";
  std::string prelude = "#include <cstdio>\n#include <cstring>\n#include <fstream>\n#include <iterator>\n"
                        "#include <string>\n#include <unistd.h>\n#include <vector>\nnamespace {\n";
  int k = 0;
  std::string table = "struct Image { const char* scene; const unsigned char* bytes; unsigned long size; };\n"
                      "const Image kImages[] = {\n";
  for (const char* name : {"cornell_smooth", "cornell_spheres"}) {
    std::string bytes = read_text_file(reference / ("part1.normals." + std::string(name) + ".exr"));
    prelude += "const unsigned char kImage" + std::to_string(k) + "[] = {";
    for (unsigned char ch : bytes) prelude += std::to_string(int(ch)) + ",";
    prelude += "};\n";
    table += "  {\"" + std::string(name) + "\", kImage" + std::to_string(k) + ", sizeof kImage" +
             std::to_string(k) + "},\n";
    ++k;
  }
  prelude += table + "};\n";
  prelude += R"(struct Replay {
  Replay() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string cmd((std::istreambuf_iterator<char>(in)), {});
    std::vector<std::string> args;
    for (size_t at = 0; at < cmd.size(); at += std::strlen(cmd.c_str() + at) + 1) args.push_back(cmd.c_str() + at);
    std::string out, scene;
    for (size_t i = 0; i + 1 < args.size(); ++i) if (args[i] == "-f") out = args[i + 1];
    if (!args.empty()) scene = args.back();
    if (out.empty()) return;
    for (const Image& im : kImages)
      if (scene.find(im.scene) != std::string::npos) {
        std::ofstream(out, std::ios::binary).write(reinterpret_cast<const char*>(im.bytes), long(im.size));
        _exit(0);
      }
  }
} replay;
}  // namespace
)";
  Files files = bundle_->solution();
  files.erase(kSphere);
  files.erase(kTriangle);
  double seconds = 0.0;
  nlohmann::json stubs = bundle_->grade(files, "1", &seconds, {kCheckCap});
  files[kSphere] = prelude + read_text_file(bundle_->root() / "pt" / "private" / "stubs" / kSphere);
  nlohmann::json r = bundle_->grade(files, "1", &seconds, {kCheckCap});
  std::printf("an image rendered beforehand: %g/%g (the stubs: %g) in %.0f s\n",
              r.value("score", -1.0), max_score(r), stubs.value("score", -1.0), seconds);
  std::map<std::string, double> base = step_scores(stubs);
  for (const auto& [step, score] : step_scores(r))
    EXPECT_LE(score, base[step] + 1e-9) << step << "\n" << outputs(r);
}

// A submission that prints as much as it can, on "not implemented" lines and others, from every
// probe and render: results.json stays within its small budget, every message within its cap,
// and none of its lines is quoted (they are not the handout's stub lines).
TEST_F(GraderBundle, WhatTheCodePrintsCannotCarryTheSolutionOut) {
  const std::string flood = R"(#include <cstdio>
namespace {
struct Flood {
  Flood() {
    for (int line = 0; line < 2000; ++line) {
      std::printf("not implemented %d: ", line);
      for (int i = 0; i < 4096; ++i) std::printf("%02x", (line * 31 + i) & 0xff);
      std::printf("\n");
    }
    std::fflush(stdout);
  }
} flood;
}  // namespace
)";
  Files files = bundle_->solution();
  files[kSphere] = flood + read_text_file(bundle_->root() / "pt" / "private" / "stubs" / kSphere);
  double seconds = 0.0;
  nlohmann::json r = bundle_->grade(files, "1", &seconds, {kCheckCap});
  const std::string all = r.dump();
  std::printf("a submission that floods its output: results.json %zu bytes in %.0f s\n", all.size(), seconds);
  EXPECT_LT(all.size(), size_t(64) << 10) << "results.json carries " << all.size() << " bytes";
  // Its lines are not the handout's stub lines, so none is quoted: 0 bytes of what it printed.
  std::regex flood_text("not implemented [0-9]+: [0-9a-f]+");
  size_t carried = 0;
  for (std::sregex_iterator it(all.begin(), all.end(), flood_text), end; it != end; ++it)
    carried += size_t((*it).length());
  std::printf("  of which %zu bytes are the flood's lines\n", carried);
  EXPECT_EQ(carried, 0u) << outputs(r);
  for (const nlohmann::json& t : r.value("tests", nlohmann::json::array())) {
    EXPECT_LE(t.value("output", "").size(), 2100u) << t.value("name", "");
    for (const nlohmann::json& c : t["extra_data"].value("checks", nlohmann::json::array()))
      EXPECT_LE(c.value("output", "").size(), 1300u) << c.value("name", "");
  }
}

/// `bytes` random bytes from `seed`, in hex.
std::string random_hex(size_t bytes, unsigned seed) {
  std::mt19937 gen(seed);
  std::string hex;
  const char* digits = "0123456789abcdef";
  for (size_t i = 0; i < bytes; ++i) {
    const unsigned b = gen() & 0xffu;
    hex += digits[b >> 4];
    hex += digits[b & 15];
  }
  return hex;
}

/// The cheater smuggle.cc with `hex` for its payload, in a submission that also names a folder
/// and an extra file by the payload.
Files smuggling_submission(const Files& solution, const std::string& hex) {
  std::string cheater = read_text_file(kSource / "grader/tests/cheaters/smuggle.cc");
  const std::regex payload("\"PAYLOAD:[0-9a-f]*\"");
  EXPECT_TRUE(std::regex_search(cheater, payload)) << "smuggle.cc has no payload to replace";
  cheater = std::regex_replace(cheater, payload, "\"PAYLOAD:" + hex + "\"");
  Files files = solution;
  files.erase(kSphere);
  files[hex.substr(0, 64) + "/" + kSphere] = cheater;
  files["notes-" + hex.substr(64, 128) + ".txt"] = hex;
  return files;
}

/// A submission whose sphere does not compile, made to carry `hex` out in the compiler's words:
/// an identifier, an #error, a static_assert, and a #line naming a file and a line of its own.
Files smuggling_build(const Files& solution, const std::string& hex) {
  Files files = solution;
  files[kSphere] = "int x_" + hex.substr(0, 200) + " = y_" + hex.substr(200, 200) + ";\n" +
                   "static_assert(false, \"" + hex.substr(400, 200) + "\");\n" +
                   "#error " + hex.substr(600, 200) + "\n" +
                   "#line " + std::to_string(1 + std::stoul(hex.substr(800, 7), nullptr, 16)) +
                   " \"" + hex.substr(810, 100) + ".cpp\"\n" +
                   "int z_" + hex.substr(910, 200) + " = w;\n";
  return files;
}

/// Every run of 12 payload digits that appears whole in the results.
std::vector<std::string> quoted_payload(const nlohmann::json& r, const std::string& hex) {
  const std::string all = r.dump();
  std::vector<std::string> found;
  for (size_t at = 0; at + 12 <= hex.size(); at += 12)
    if (all.find(hex.substr(at, 12)) != std::string::npos) found.push_back(hex.substr(at, 12));
  return found;
}

// The bound: one results.json carries at most 512 characters the student chose. A cheater that
// puts 4 KB of payload into every channel it has (its values, a stub-like line, its time, the
// signal it dies of and the status it exits with, a folder and a file named by it; then, in a
// second pair, the compiler's words) is graded twice with two random payloads, as Gradescope
// grades (no quoting of student lines); every character in which the two results differ is the
// payload's (or chance's), and none of its text appears whole.
TEST_F(GraderBundle, AMaximisingCheaterCarriesAtMost512CharactersOut) {
  const std::string a = random_hex(4096, 1), b = random_hex(4096, 2);
  for (const bool build : {false, true}) {
    const Files& solution = bundle_->solution();
    std::vector<nlohmann::json> results;
    for (const std::string& hex : {a, b}) {
      double seconds = 0.0;
      results.push_back(bundle_->grade(build ? smuggling_build(solution, hex)
                                             : smuggling_submission(solution, hex),
                                       "1", &seconds, {kCheckCap}));
      EXPECT_EQ(validate_gradescope(results.back()), "");
      // Graded (not the grader's error), and graded as the channel needs: built, or not.
      EXPECT_EQ(results.back().value("tests", nlohmann::json::array()).size(), 5u)
          << outputs(results.back());
      EXPECT_EQ(results.back().dump().find("did not build") != std::string::npos, build)
          << outputs(results.back());
      EXPECT_EQ(quoted_payload(results.back(), hex), std::vector<std::string>())
          << outputs(results.back());
    }
    const size_t chosen = testing::differing_characters(results[0], results[1]);
    std::printf("a cheater carrying its payload out %s: %zu characters of results.json differ "
                "between two payloads (bound 512)\n",
                build ? "in a failed build" : "at run time", chosen);
    EXPECT_LE(chosen, 512u) << outputs(results[0]) << "\n" << outputs(results[1]);
  }
}

// After every grading above, as after set-up: no file a student's user can open, as grading
// leaves the tree and as a part's compile has it, carries a fingerprint of the solution's
// objects (setup.sh's own check, made again); and the check is no formality: a readable copy of
// one solution object, planted in a shared folder, is named.
TEST_F(GraderBundle, ZyNoFileTheStudentCanOpenCarriesTheSolution) {
  const std::string said = "no file the student's user can open carries the solution's code (";
  ASSERT_NE(bundle_->log().find(said), std::string::npos) << "setup.sh made no walk:\n" << bundle_->log();
  const AutogradeLayout L = AutogradeLayout::under(bundle_->root().string());
  std::string line;
  ASSERT_NO_THROW(line = check_no_solution_readable(L));
  std::printf("%s\n", line.c_str());
  // The same fingerprints as at set-up: the submissions graded since are not taken for given code.
  const std::regex prints("carries the solution's code \\(([0-9]+) fingerprints");
  std::smatch at_setup, now;
  const std::string log = bundle_->log();
  ASSERT_TRUE(std::regex_search(log, at_setup, prints));
  ASSERT_TRUE(std::regex_search(line, now, prints));
  EXPECT_EQ(now[1].str(), at_setup[1].str());
  fs::path object;
  for (const fs::path& f : files_under(L.build / "secret" / "CMakeFiles"))
    if (f.string().find("pt_solution_part3_obj") != std::string::npos && f.extension() == ".o") object = f;
  ASSERT_FALSE(object.empty());
  const fs::path planted = fs::temp_directory_path() / "pt-planted-cache-entry";
  fs::copy_file(object, planted, fs::copy_options::overwrite_existing);
  fs::permissions(planted, fs::perms(0644));
  try {
    check_no_solution_readable(L);
    ADD_FAILURE() << "a readable copy of " << object << " was not found";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find(planted.string()), std::string::npos) << e.what();
  }
  fs::remove(planted);
}

// Last: after every grading above, no file and no IPC object of any student uid is anywhere on
// the machine (`/` walked with proc and sys pruned; /proc/sysvipc read).
TEST_F(GraderBundle, ZzNothingOfAStudentIsLeftOnTheMachine) {
  const long last = kFirstStudentUid + kSlots * kUidsPerSlot - 1;
  std::vector<std::string> left = traces_of_uids(kFirstStudentUid, last);
  std::string listed;
  for (size_t i = 0; i < left.size() && i < 40; ++i) listed += left[i] + "\n";
  EXPECT_TRUE(left.empty()) << left.size() << " things of student uids are left:\n" << listed;
  std::printf("after the whole run: %zu files or IPC objects of student uids on the machine\n", left.size());
}

}  // namespace
}  // namespace pt::grader
