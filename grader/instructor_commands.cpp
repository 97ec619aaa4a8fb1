#include "grader/instructor_commands.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "grader/process/child_process.h"
#include "grader/false_failures.h"
#include "grader/manifest.h"
#include "grader/mutants.h"
#include "grader/second_solution.h"

namespace fs = std::filesystem;

namespace pt::grader {

InstructorCommands::InstructorCommands(CLI::App& app) {
  mutants_ = app.add_subcommand(
      "mutants", "instructor: apply each catalogued bug (grader/mutants) to a scratch copy, grade "
                 "its part, and print where it lost points");
  mutants_->add_option("--only", only_, "only mutants whose name contains this (repeatable)");
  mutants_->add_option("--jobs", jobs_, "mutants graded at once, each in its own scratch tree")
      ->check(CLI::Range(1, 16));
  mutants_->add_option("--build-jobs", build_jobs_, "-j of each build")->check(CLI::Range(1, 64));
  mutants_->add_option("--work", work_, "scratch trees and results (default BUILD/mutants)");
  mutants_->add_option("--index", index_, "the catalogue (default grader/mutants/index.json)");
  mutants_->add_flag("--no-isolated", no_isolated_, "grade without --isolated");
  mutants_->add_flag("--report", report_only_,
                     "grade nothing: print the table from the results an earlier run left");

  false_failures_ = app.add_subcommand(
      "false-failures", "instructor: render every graded scene of the complete and the second "
                        "solution with many seeds and count how often correct code fails");
  false_failures_->add_option("--seeds", seeds_, "seeds per render and solution")
      ->check(CLI::Range(1, 100000))->capture_default_str();
  false_failures_->add_option("--first", first_, "the first seed offset (default 1)")
      ->check(CLI::Range(1, 1000000));
  false_failures_->add_option("--solution", solution_, "complete, second or both")
      ->check(CLI::IsMember({"complete", "second", "both"}))->capture_default_str();
  false_failures_->add_option("--part", part_, "only part N's renders")->check(CLI::Range(1, 5));
  false_failures_->add_option("--only", only_, "only renders whose name contains this (repeatable)");
  false_failures_->add_option("--work", work_, "scratch tree and renders (default BUILD/false-failures)");
  false_failures_->add_option("--log", log_, "the results log, appended to (default WORK/runs.tsv)");
  false_failures_->add_flag("--report", report_only_, "print the table from the log; render nothing");

  second_ = app.add_subcommand(
      "second-solution", "instructor: make the second correct solution (grader/second_solution) "
                         "in a scratch tree and grade every part of it");
  second_->add_option("--work", work_, "its scratch tree (default BUILD/false-failures/second)");
  second_->add_option("--part", part_, "grade only part N")->check(CLI::Range(1, 5));
}

bool InstructorCommands::chosen() const {
  return mutants_->parsed() || false_failures_->parsed() || second_->parsed();
}

int InstructorCommands::run(const GradeOptions& grade, const std::string& grader_exe) const {
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  try {
    if (mutants_->parsed()) {
      MutantRunOptions o;
      o.source_dir = grade.source_dir;
      o.index_path = index_.empty()
                         ? (fs::path(grade.source_dir) / "grader" / "mutants" / "index.json").string()
                         : index_;
      o.work_dir = work_.empty() ? (fs::path(grade.build_dir) / "mutants").string() : work_;
      o.grader_exe = grader_exe;
      o.only = only_;
      o.jobs = jobs_;
      o.build_jobs = build_jobs_;
      o.isolated = !no_isolated_;
      o.report_only = report_only_;
      std::vector<MutantOutcome> outcomes = run_mutants(o, std::cerr);
      print_mutant_table(std::cout, outcomes, elapsed());
      std::ofstream table(fs::path(o.work_dir) / "table.txt");
      print_mutant_table(table, outcomes, elapsed());
      // Per rule, from the manifest the copies were graded with.
      const Manifest manifest = read_manifest(grade.manifest_path);
      print_rule_table(std::cout, manifest, outcomes);
      print_rule_table(table, manifest, outcomes);
      for (const MutantOutcome& m : outcomes)
        if (m.verdict != "ok" && m.verdict != "OVERFLOW") return 1;
      return 0;
    }
    std::string work = work_.empty() ? (fs::path(grade.build_dir) / "false-failures").string() : work_;
    if (second_->parsed()) {
      std::string root = make_second_solution(grade.source_dir, work_.empty() ? work + "/second" : work,
                                              std::cerr);
      std::vector<std::string> argv = {grader_exe, "--source", root, "--build", root + "/build",
                                       "--pathtracer", root + "/build/app/pathtracer", "--out",
                                       root + "/grader-out", "--json", root + "/grader-out/results.json"};
      if (part_ != 0) argv.insert(argv.end(), {"--part", std::to_string(part_)});
      else argv.push_back("--all");
      std::cerr << command_line(argv) << "\n";
      ChildResult c = run_child(argv, 7200.0);
      std::cout << c.output;
      std::cerr << "second solution graded in " << elapsed() << " s\n";
      return c.exit_code == 0 ? 0 : (c.exit_code == 1 ? 1 : 2);
    }
    FalseFailureOptions o;
    o.seeds = seeds_;
    o.first = first_;
    o.part = part_;
    o.only = only_;
    if (solution_ != "both") o.solutions = {solution_};
    o.work_dir = work;
    o.log_path = log_.empty() ? (fs::path(work) / "runs.tsv").string() : log_;
    o.report_only = report_only_;
    o.build_jobs = build_jobs_;
    Manifest manifest = read_manifest(grade.manifest_path);
    if (!report_only_) {
      fs::create_directories(work);
      run_false_failures(manifest, grade, o, std::cerr);
    }
    std::vector<SeedRun> runs = read_seed_log(o.log_path, std::cerr);
    std::vector<SeedRun> kept;
    for (const SeedRun& r : runs)
      for (const std::string& s : o.solutions)
        if (r.solution == s) kept.push_back(r);
    print_false_failure_table(std::cout, manifest, kept);
    std::cerr << "false-failures: " << elapsed() << " s\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "grader: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace pt::grader
