// grader: builds and tests a part, compares its renders with the references, prints the score;
// `grader handout DIR` makes the student handout.
#include <chrono>
#include <filesystem>
#include <optional>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>

#include "grader/autograde.h"
#include "grader/batch.h"
#include "grader/bundle.h"
#include "grader/grade.h"
#include "grader/handout.h"
#include "grader/handout_guard.h"
#include "grader/instructor_commands.h"
#include "grader/manifest.h"
#include "grader/report.h"
#include "grader/rules.h"

namespace fs = std::filesystem;
using namespace pt::grader;

namespace {

/// Whether `dir` holds the complete solution: its parts' files still have their solution blocks.
bool holds_solution(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir / "parts", ec)) {
    if (!e.is_regular_file(ec) || e.path().extension() != ".cpp") continue;
    std::ifstream in(e.path());
    for (std::string line; std::getline(in, line);)
      if (line.find("// BEGIN SOLUTION") != std::string::npos) return true;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Grades the path tracer one part at a time against the reference images."};
  GradeOptions options;
  options.source_dir = GRADER_SOURCE_DIR;
  options.build_dir = GRADER_BINARY_DIR;
  options.pathtracer = GRADER_PATHTRACER;
  int part = 0;
  bool all = false, make_reference = false, no_tests = false, no_build = false;
  std::string solution_dir = GRADER_SOLUTION_DIR;
  options.isolated_separate = GRADER_ISOLATED_SEPARATE;
  std::string json_path;
  app.add_option("--part", part, "grade part N (1-5): build it, run its tests, compare renders")
      ->check(CLI::Range(1, 5));
  app.add_flag("--all", all, "grade every part");
  app.add_option("--json", json_path, "also write the Gradescope results to FILE");
  app.add_flag("--make-reference", make_reference,
               "render the reference images with this (complete) solution (of --part N only, if "
               "given) and record them in the manifest");
  app.add_option("--source", options.source_dir, "the project's folder");
  app.add_option("--build", options.build_dir, "its CMake build tree");
  app.add_option("--manifest", options.manifest_path, "the manifest (default reference/manifest.json)");
  app.add_option("--pathtracer", options.pathtracer, "the renderer to run");
  app.add_option("--out", options.out_dir, "where renders, diff images and JUnit XML go")
      ->capture_default_str();
  app.add_flag("--no-build", no_build, "do not build first");
  app.add_flag("--no-tests", no_tests, "skip the step tests, grade the renders only");
  app.add_flag("--isolated", options.isolated,
               "grade part N alone: its code linked with the complete solution of every other "
               "part (the build's grade_partN_isolated), so that no other part costs it points");
  app.add_option("--seed-offset", options.seed_offset,
                 "render with seed + K instead of the manifest's seeds (a false-failure study)")
      ->capture_default_str();
  std::string handout_dir;
  CLI::App* handout = app.add_subcommand("handout", "write the student handout to a new folder");
  handout->add_option("OUT_DIR", handout_dir, "the folder to create")->required();
  bool check_rules = false;
  CLI::App* rules = app.add_subcommand(
      "rules", "print the rules each step states, with the checks that enforce them (and the "
               "catalogued bugs that break them, where the catalogue is)");
  rules->add_flag("--check", check_rules,
                  "fail (exit 1) if a rule has no check this build has, or no catalogued bug");
  InstructorCommands instructor(app);  // mutants, false-failures, second-solution
  // The Gradescope bundle (grader/bundle/, docs/grading.md "The Gradescope bundle").
  std::string bundle_zip, autograde_root, autograde_parts;
  CLI::App* gradescope = app.add_subcommand("gradescope", "write the Gradescope autograder zip");
  gradescope->add_option("OUT_ZIP", bundle_zip, "the zip to write")->required();
  CLI::App* setup = app.add_subcommand(
      "autograde-setup", "(the bundle's setup.sh) record what grading trusts, protect it");
  setup->add_option("--root", autograde_root, "the root folder (/autograder)")->required();
  int setup_jobs = int(std::max(1u, std::thread::hardware_concurrency()));
  setup->add_option("--jobs", setup_jobs, "build jobs for the grading programs")
      ->check(CLI::Range(1, 256));
  CLI::App* autograde_cmd = app.add_subcommand(
      "autograde", "(the bundle's run_autograder) grade ROOT/submission into ROOT/results");
  autograde_cmd->add_option("--root", autograde_root, "the root folder (/autograder)")->required();
  autograde_cmd->add_option("--parts", autograde_parts, "only these parts, e.g. 1,3");
  AutogradeTuning tuning;
  double disk_mb = 0.0;
  autograde_cmd->add_option("--max-check-seconds", tuning.max_check_seconds,
                            "cap every test's and render's time (a test run of the bundle)");
  autograde_cmd->add_option("--disk-mb", disk_mb, "the disk a check may fill (default 1024)");
  autograde_cmd->add_option("--jobs", tuning.jobs, "tests run at once, each as a uid of its own (default: one per core)");
  autograde_cmd->add_option("--build-jobs", tuning.build_jobs, "the student's build's jobs")->capture_default_str();
  autograde_cmd->add_option("--slot", tuning.slot, "take the first free slot from SLOT on (its uids: 60000 + 64 SLOT ...)")->capture_default_str();
  autograde_cmd->add_flag("--quote-student-lines", tuning.quote_student_lines,
                          "quote any \"not implemented\" line, not only the stubs' (a test run reading what an attack got)");
  autograde_cmd->add_option("--submission", tuning.submission, "the submission folder (default ROOT/submission)");
  autograde_cmd->add_option("--results", tuning.results, "the results file (default ROOT/results/results.json)");
  autograde_cmd->add_option("--tree", tuning.tree,
                            "grade in this copy of the set-up tree, mounted over ROOT/source/project");
  // Many submissions on one machine (grader/batch.h).
  BatchOptions batch_options;
  std::string batch_parts;
  CLI::App* batch = app.add_subcommand(
      "batch", "grade every submission folder under DIR in parallel, as the bundle does");
  batch->add_option("DIR", batch_options.submissions, "one folder per submission")->required();
  batch->add_option("--root", batch_options.root, "a root folder set up by the bundle's setup.sh")->required();
  batch->add_option("--out", batch_options.out_dir, "where each NAME/results.json and scores.csv go (default DIR-results)");
  batch->add_option("--jobs", batch_options.jobs, "submissions graded at once (default: one per core)");
  batch->add_option("--parts", batch_parts, "only these parts, e.g. 1,3");
  batch->add_option("--max-check-seconds", batch_options.tuning.max_check_seconds,
                    "cap every test's and render's time (a test run)");
  batch->add_flag("--quote-student-lines", batch_options.tuning.quote_student_lines,
                  "quote any \"not implemented\" line (a test run)");
  CLI11_PARSE(app, argc, argv);
  // Tests and renders run in scratch folders of their own, so a folder named relative to where
  // the grader was started must be made absolute first.
  // (A --pathtracer without a slash is looked up on PATH, as a shell would.)
  for (std::string* path : {&options.source_dir, &options.build_dir, &options.pathtracer,
                            &options.manifest_path, &options.out_dir})
    if (!path->empty() && (path != &options.pathtracer || path->find('/') != std::string::npos))
      *path = fs::absolute(*path).lexically_normal().string();
  // The tree graded (--build may name another, a mutant's scratch copy) says whether it has
  // separate isolated targets; the compiled-in answer is this grader's own tree's.
  if (std::optional<bool> separate = has_separate_solution(options.build_dir))
    options.isolated_separate = *separate;

  if (*gradescope) {
    try {
      BundleSummary s = make_gradescope_bundle(options.source_dir, bundle_zip);
      std::cout << "bundle " << bundle_zip << ": " << s.project_files << " project files, "
                << s.shared_files << " course scene files, " << s.bytes / 1024 << " KiB\n";
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "grader gradescope: " << e.what() << "\n";
      return 2;
    }
  }
  if (*setup) {
    try {
      autograde_setup(autograde_root, fs::read_symlink("/proc/self/exe").string(), setup_jobs);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "grader autograde-setup: " << e.what() << "\n";
      return 2;
    }
  }
  if (*batch) {
    std::stringstream list(batch_parts);
    for (std::string p; std::getline(list, p, ',');)
      if (!p.empty()) batch_options.parts.push_back(std::atoi(p.c_str()));
    batch_options.grader_exe = fs::read_symlink("/proc/self/exe").string();
    return grade_batch(batch_options);
  }
  if (*autograde_cmd) {
    std::vector<int> parts;
    std::stringstream list(autograde_parts);
    for (std::string p; std::getline(list, p, ',');)
      if (!p.empty()) parts.push_back(std::atoi(p.c_str()));
    tuning.disk_bytes = size_t(disk_mb * 1024 * 1024);
    return autograde(autograde_root, parts, tuning);
  }

  if (*handout) {
    try {
      HandoutSummary s = make_handout(options.source_dir, handout_dir);
      std::cout << "handout in " << handout_dir << ": " << s.files << " files, " << s.blocks
                << " solution blocks removed, " << s.dropped << " solution-only files left out\n";
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "grader handout: " << e.what() << "\n";
      return 1;
    }
  }
  if (options.manifest_path.empty())
    options.manifest_path = (fs::path(options.source_dir) / "reference" / "manifest.json").string();
  options.build = !no_build;
  options.run_tests = !no_tests;
  if (options.pathtracer.empty())
    options.pathtracer = (fs::path(options.build_dir) / "app" / "pathtracer").string();

  Manifest manifest;
  try {
    manifest = read_manifest(options.manifest_path);
  } catch (const std::exception& e) {
    std::cerr << "grader: " << e.what() << "\n";
    return 2;
  }
  if (*rules) {
    const fs::path index = fs::path(options.source_dir) / "grader" / "mutants" / "index.json";
    try {
      std::optional<std::vector<MutantSpec>> mutants;
      if (fs::exists(index)) mutants = read_mutant_index(index.string());
      print_rules(std::cout, manifest, mutants ? &*mutants : nullptr);
      if (!check_rules) return 0;
      const std::vector<std::string> problems =
          rule_problems(manifest, mutants ? &*mutants : nullptr, listed_tests(options.build_dir));
      for (const std::string& p : problems) std::cerr << "grader rules: " << p << "\n";
      if (problems.empty())
        std::cerr << "grader rules: every rule has a check" << (mutants ? " and a mutant" : "")
                  << "\n";
      return problems.empty() ? 0 : 1;
    } catch (const std::exception& e) {
      std::cerr << "grader rules: " << e.what() << "\n";
      return 2;
    }
  }
  if (make_reference && !has_solution(options.source_dir)) {
    std::cerr << "grader: --make-reference is the instructor's: it renders the references with "
                 "the complete solution, and " << options.source_dir << " has none (a handout). "
                 "Grade against the references you were given.\n";
    return 2;
  }
  if (make_reference) return make_references(manifest, part, options) ? 0 : 1;
  if (instructor.chosen())
    return instructor.run(options, fs::canonical("/proc/self/exe").string());
  if (!all && part == 0) {
    std::cerr << "grader: say which part (--part N) or --all\n" << app.help();
    return 2;
  }
  if (all || part == 5) {
    const std::string mismatch = stopping_rule_mismatch(manifest, options.build_dir);
    if (!mismatch.empty()) {
      std::cerr << "grader: " << mismatch << "\n";
      return 2;
    }
  }
  if (options.isolated && !holds_solution(solution_dir)) {
    std::cerr << "grader: --isolated links the complete solution of the other parts, and "
              << solution_dir << " holds none (a handout). Configure the build with "
              << "-DPT_SOLUTION_DIR=<a copy of the complete solution>.\n";
    return 2;
  }
  for (const PartSpec& p : manifest.parts) {
    for (const RenderCheck* r : p.renders()) {
      int64_t seed = int64_t(r->seed) + options.seed_offset;
      if (seed < 0 || r->is_reference_seed(uint64_t(seed))) {
        std::cerr << "grader: --seed-offset " << options.seed_offset << " gives " << r->name
                  << " the seed " << seed << ", "
                  << (seed < 0 ? "below 0" : "its reference's own: the same random numbers") << "\n";
        return 2;
      }
    }
  }
  auto start = std::chrono::steady_clock::now();
  std::vector<PartResult> results;
  // A student's own run (or an instructor's tool) shows every value of the student's own code:
  // nothing leaves the machine it ran on. The bundle's results, which do, hold a budget
  // (autograde.cpp).
  for (const PartSpec& p : manifest.parts) {
    if (!all && p.part != part) continue;
    std::cerr << "grading part " << p.part << (options.isolated ? " (isolated)" : "") << " ...\n";
    if (no_build)
      std::cerr << stale_warning(sources_newer_than(
          options.source_dir, part_binaries(options.build_dir, options.pathtracer, p.part)));
    results.push_back(grade_part(manifest, p.part, options));
    record_state(results.back(), options);
  }
  if (results.empty()) {
    std::cerr << "grader: the manifest " << options.manifest_path << " has no part " << part << "\n";
    return 2;
  }
  double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_score_table(std::cout, results);
  if (!json_path.empty()) {
    std::ofstream out(json_path);
    RunInfo info;
    info.isolated = options.isolated;
    info.seed_offset = options.seed_offset;
    info.seconds = seconds;
    out << gradescope_results(results, info).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    if (!out) {
      std::cerr << "grader: cannot write " << json_path << "\n";
      return 2;
    }
  }
  return all_passed(results) ? 0 : 1;
}
