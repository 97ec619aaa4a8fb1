// Grading renders through a stand-in renderer: a good render passes, one that crashes, hangs
// or writes garbage fails alone, and a reference that does not match its checksum is refused.
#include "grader/grade.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/image/estimate_exr.h"
#include "grader/report.h"
#include "grader/tests/synthetic.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

/// A project in a temporary folder: a manifest, references, and a fake `pathtracer` script
/// whose behaviour the scene's name chooses (the scene file of "good" is the render itself).
class GraderGrade : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("pt-grader-grade-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "reference");
    fs::create_directories(root_ / "scenes");
    write_estimate_exr((root_ / "reference" / "ref.exr").string(), testing::full_render(64, 1));
    write_estimate_exr((root_ / "scenes" / "good.exr").string(), testing::full_render(16, 2));
    write_estimate_exr((root_ / "scenes" / "dark.exr").string(),
                       testing::full_render(64, 3, 0.95f));
    for (const char* s : {"crash", "hang", "garbage"}) std::ofstream(root_ / "scenes" / s) << "x";
    fs::path script = root_ / "fake-pathtracer";
    std::ofstream(script) << "#!/bin/sh\n"
                             "while [ $# -gt 1 ]; do [ \"$1\" = -f ] && out=$2; shift; done\n"
                             "case \"$1\" in\n"
                             "  *crash) kill -SEGV $$ ;;\n"
                             "  *hang) sleep 60 ;;\n"
                             "  *garbage) echo garbage > \"$out\" ;;\n"
                             "  *) cp \"$1\" \"$out\" ;;\n"
                             "esac\n";
    fs::permissions(script, fs::perms::owner_all);
    std::string sum = file_checksum((root_ / "reference" / "ref.exr").string());
    nlohmann::ordered_json m;
    m["block_size"] = 16;
    m["alpha"] = 0.01;
    nlohmann::ordered_json part = {{"part", 3}, {"test_points", 0}, {"renders", nlohmann::ordered_json::array()}};
    for (const char* s : {"good.exr", "crash", "hang", "garbage", "dark.exr"}) {
      part["renders"].push_back({{"name", std::string("part3.") + s},
                                 {"scene", std::string("scenes/") + s},
                                 {"args", {"-s", "16"}},
                                 {"reference_args", {"-s", "64"}},
                                 {"seed", 2},
                                 {"reference_seed", 1},
                                 {"points", 5},
                                 {"timeout", 1.0},
                                 {"reference", "reference/ref.exr"},
                                 {"made", {{"crc32", sum}}}});
    }
    m["parts"] = {part};
    std::ofstream(root_ / "reference" / "manifest.json") << m.dump(2);
    options_.source_dir = root_.string();
    options_.manifest_path = (root_ / "reference" / "manifest.json").string();
    options_.pathtracer = script.string();
    options_.out_dir = (root_ / "out").string();
    options_.build = false;
    options_.run_tests = false;
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path root_;
  GradeOptions options_;
};

TEST_F(GraderGrade, EachFailureStaysInItsOwnCheck) {
  Manifest m = read_manifest(options_.manifest_path);
  std::vector<CheckResult> r = grade_part(m, 3, options_);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_TRUE(r[0].pass) << r[0].output;
  EXPECT_EQ(r[0].score, 5.0);
  EXPECT_FALSE(r[1].pass);
  EXPECT_NE(r[1].output.find("crashed (SIGSEGV"), std::string::npos) << r[1].output;
  EXPECT_FALSE(r[2].pass);
  EXPECT_NE(r[2].output.find("time limit"), std::string::npos) << r[2].output;
  EXPECT_LT(r[2].seconds, 10.0);
  EXPECT_FALSE(r[3].pass);
  EXPECT_NE(r[3].output.find("cannot be read"), std::string::npos) << r[3].output;
  EXPECT_FALSE(r[4].pass);
  EXPECT_NE(r[4].output.find("slightly too dark everywhere"), std::string::npos) << r[4].output;
  EXPECT_NE(r[4].output.find("part3.dark.exr_diff.png"), std::string::npos) << r[4].output;
  EXPECT_TRUE(fs::exists(root_ / "out" / "part3.dark.exr_diff.png"));
  std::ostringstream table;
  print_score_table(table, r);
  EXPECT_NE(table.str().find("Total: 5/25"), std::string::npos) << table.str();
  EXPECT_EQ(validate_gradescope(gradescope_results(r, 1.0)), "");
}

TEST_F(GraderGrade, AReferenceThatDoesNotMatchItsChecksumIsRefused) {
  std::ofstream(root_ / "reference" / "ref.exr", std::ios::app) << "tampered";
  Manifest m = read_manifest(options_.manifest_path);
  CheckResult r = grade_render(m, m.parts[0].renders[0], options_);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.output.find("checksum"), std::string::npos) << r.output;
}

TEST_F(GraderGrade, AMissingReferenceSaysHowToMakeIt) {
  fs::remove(root_ / "reference" / "ref.exr");
  Manifest m = read_manifest(options_.manifest_path);
  CheckResult r = grade_render(m, m.parts[0].renders[0], options_);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.output.find("--make-reference"), std::string::npos) << r.output;
}

TEST_F(GraderGrade, ABadManifestNamesTheEntry) {
  std::ofstream(options_.manifest_path) << R"({"parts": [{"part": 1, "test_points": 5,
      "renders": [{"name": "x", "scene": "s"}]}]})";
  try {
    read_manifest(options_.manifest_path);
    FAIL() << "a render without args was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("render \"x\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("args"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pt::grader
