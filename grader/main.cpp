// grader: builds and tests a part, compares its renders with the references, prints the score;
// `grader handout DIR` makes the student handout.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>

#include "grader/grade.h"
#include "grader/handout.h"
#include "grader/handout_guard.h"
#include "grader/instructor_commands.h"
#include "grader/manifest.h"
#include "grader/report.h"

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
  InstructorCommands instructor(app);  // mutants, false-failures, second-solution
  CLI11_PARSE(app, argc, argv);

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
  if (options.isolated && !holds_solution(solution_dir)) {
    std::cerr << "grader: --isolated links the complete solution of the other parts, and "
              << solution_dir << " holds none (a handout). Configure the build with "
              << "-DPT_SOLUTION_DIR=<a copy of the complete solution>.\n";
    return 2;
  }
  for (const PartSpec& p : manifest.parts) {
    for (const RenderCheck* r : p.renders()) {
      int64_t seed = int64_t(r->seed) + options.seed_offset;
      if (seed < 0 || uint64_t(seed) == r->reference_seed) {
        std::cerr << "grader: --seed-offset " << options.seed_offset << " gives " << r->name
                  << " the seed " << seed << ", "
                  << (seed < 0 ? "below 0" : "its reference's own: the same random numbers") << "\n";
        return 2;
      }
    }
  }
  auto start = std::chrono::steady_clock::now();
  std::vector<PartResult> results;
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
    out << gradescope_results(results, info).dump(2) << "\n";
    if (!out) {
      std::cerr << "grader: cannot write " << json_path << "\n";
      return 2;
    }
  }
  return all_passed(results) ? 0 : 1;
}
