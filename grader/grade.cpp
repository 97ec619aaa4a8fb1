#include "grader/grade.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <pugixml.hpp>
#include <xxhash.h>

#include "framework/image/estimate_exr.h"
#include "framework/image/image.h"
#include "framework/text/text_file.h"
#include "grader/process/child_process.h"
#include "framework/stats/variance_consistency.h"
#include "grader/build_errors.h"
#include "grader/compare.h"
#include "grader/judged_tests.h"
#include "grader/reference_mean.h"
#include "grader/rules.h"
#include "grader/scene_variant.h"
#include "grader/step_at_fault.h"
#include "grader/student_values.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

std::string fixed(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

/// The last `lines` lines of a child's output that mention an error, or its tail.
std::string output_excerpt(const std::string& output, size_t lines = 12) {
  std::vector<std::string> all, errors;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    all.push_back(line);
    if (line.find("error") != std::string::npos || line.find("Error") != std::string::npos)
      errors.push_back(line);
  }
  const std::vector<std::string>& pick = errors.empty() ? all : errors;
  std::string s;
  for (size_t i = pick.size() > lines ? pick.size() - lines : 0; i < pick.size(); ++i)
    s += "    " + pick[i] + "\n";
  return s;
}

fs::path scene_path(const RenderCheck& check, const GradeOptions& options) {
  fs::path root = options.source_dir;
  return check.course_scene ? root / ".." / "shared" / "scenes" / "cs184" / check.scene
                            : root / check.scene;
}

/// The variance check of a render: its own block size, and the sample count its flags ask for
/// (`-s N`; with `-a`, adaptive, at most N).
VarianceConsistencyOptions variance_options(const Manifest& manifest, const RenderCheck& check) {
  VarianceConsistencyOptions o;
  o.block_size = manifest.block_size;
  for (size_t i = 0; i + 1 < check.args.size(); ++i)
    if (check.args[i] == "-s") o.expected_count = std::atoi(check.args[i + 1].c_str());
  for (const std::string& a : check.args) o.adaptive = o.adaptive || a == "-a" || a == "--adaptive";
  return o;
}

/// The first failure a GoogleTest output reports (the file:line line and what follows), short.
std::string first_failure(const std::string& output) {
  std::istringstream in(output);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].find("Failure") == std::string::npos &&
        lines[i].find("error:") == std::string::npos)
      continue;
    std::string s;
    for (size_t k = i; k < lines.size() && k < i + 40; ++k) {
      if (k > i && lines[k].rfind("[  ", 0) == 0) break;  // the next gtest status line
      s += (s.empty() ? "" : "\n") + lines[k];
    }
    return s;
  }
  return "";
}

// What a check's message may hold: the judge's own words whole up to a length, and of the
// student's output only a few short "not implemented" lines (docs/grading.md, "What reaches the
// student").
constexpr size_t kCheckMessageChars = 1200;
constexpr int kStudentLinesPerCheck = 3;
constexpr size_t kStudentLineChars = 160;

/// `text` cut to at most `limit` characters, saying so.
std::string bounded(const std::string& text, size_t limit) {
  if (text.size() <= limit) return text;
  return text.substr(0, limit) + " [...]";
}

/// The project's relative name for a path the compiler wrote absolutely.
std::string relative_to(const std::string& text, const std::string& root) {
  std::string r = text, prefix = fs::weakly_canonical(root).string() + "/";
  for (size_t at; (at = r.find(prefix)) != std::string::npos;) r.erase(at, prefix.size());
  return r;
}

/// The step a test's name names ("part3.step4.importance.x" or "isolated.part3.step4..."), or 0.
int step_of(const std::string& test, int part) {
  std::string name = test.rfind("isolated.", 0) == 0 ? test.substr(9) : test;
  std::string prefix = "part" + std::to_string(part) + ".step";
  if (name.rfind(prefix, 0) != 0) return 0;
  size_t at = prefix.size(), end = at;
  while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
  if (end == at || end >= name.size() || name[end] != '.') return 0;
  return std::stoi(name.substr(at, end - at));
}

std::string part_target(int part, const GradeOptions& options) {
  return "grade_part" + std::to_string(part) + (options.isolated ? "_isolated" : "");
}

std::string part_label(int part) { return "^part" + std::to_string(part) + "$"; }

std::string pathtracer_for(int part, const GradeOptions& options) {
  if (!(options.isolated && options.isolated_separate)) return options.pathtracer;
  return (fs::path(options.build_dir) / "secret" / ("pathtracer_isolated" + std::to_string(part)))
      .string();
}

/// What of the student's own output a check's message may carry: its "not implemented" lines,
/// a few and cut short, never more (a message is no channel out of the grader).
std::string student_lines(const std::string& output, const GradeOptions& options) {
  std::string s;
  int n = 0;
  std::istringstream in(not_implemented_lines(output, options.stub_messages));
  for (std::string line; std::getline(in, line) && n < kStudentLinesPerCheck; ++n)
    s += bounded(line, kStudentLineChars) + "\n";
  return s;
}

/// A skipped check's message: why it could not run, and what to do (the step says it is not
/// counted).
std::string skipped_message(const std::string& why) { return "could not run here: " + why; }

/// Part N's step tests, each run as a probe of the student's code and decided by its judge
/// (grader/judged_tests.h): in the sandbox when the bundle grades, else as the grader's user.
std::vector<CheckResult> run_judged(int part, const PartSpec& spec, const GradeOptions& options,
                                    std::string* problem) {
  std::vector<CheckResult> checks;
  const std::string judge_build = options.judge_build_dir.empty() ? options.build_dir
                                                                  : options.judge_build_dir;
  std::vector<JudgedTest> tests;
  try {
    tests = list_judged_tests(part, options.build_dir, judge_build);
  } catch (const std::exception& e) {
    *problem = std::string("the tests of part ") + std::to_string(part) + " cannot be listed: " + e.what();
    return checks;
  }
  Sandbox local;
  if (!options.sandbox) {
    local.scratch_root = (fs::absolute(options.out_dir) / "scratch").string();
    fs::create_directories(local.scratch_root);
    local.jobs = int(std::max(1u, std::thread::hardware_concurrency()));
  }
  const Sandbox& sandbox = options.sandbox ? *options.sandbox : local;
  double limit = load_scaled_limit(spec.test_timeout);
  if (sandbox.max_check_seconds > 0.0) limit = std::min(limit, sandbox.max_check_seconds);
  const std::string work = (fs::absolute(options.out_dir) / "records").string();
  // What each test took the last time this folder graded it: the longest start first.
  const fs::path timings = fs::absolute(options.out_dir) / "test-seconds.json";
  std::ifstream timings_in(timings);
  nlohmann::json seconds = nlohmann::json::parse(timings_in, nullptr, false);
  if (!seconds.is_object()) seconds = nlohmann::json::object();
  std::vector<double> expected;
  for (const JudgedTest& t : tests)
    expected.push_back(seconds.contains(t.name) && seconds[t.name].is_number()
                           ? seconds[t.name].get<double>()
                           : 0.0);
  std::vector<JudgedOutcome> outcomes = run_judged_tests(tests, sandbox, limit, work, expected);
  for (size_t i = 0; i < tests.size(); ++i) seconds[tests[i].name] = outcomes[i].seconds;
  std::ofstream(timings) << seconds.dump(1) << "\n";
  for (size_t i = 0; i < tests.size(); ++i) {
    CheckResult r;
    r.kind = "test";
    r.name = tests[i].name;
    r.seconds = outcomes[i].seconds;
    r.pass = outcomes[i].pass;
    r.skipped = outcomes[i].skipped;
    if (r.skipped) {
      r.output = skipped_message(
          bounded(relative_to(outcomes[i].message, options.source_dir), kCheckMessageChars));
    } else if (!r.pass) {
      // The judge's words, its numbers the student's values (bounded, released under a budget).
      r.output = mark_values(
          bounded(relative_to(outcomes[i].message, options.source_dir), kCheckMessageChars));
      r.todo = student_lines(outcomes[i].student_output, options);
    }
    checks.push_back(r);
  }
  if (tests.empty()) *problem = "part " + std::to_string(part) + " has no judged tests in " + judge_build;
  return checks;
}

std::vector<CheckResult> run_tests(int part, const PartSpec& spec, const GradeOptions& options,
                                   std::string* problem) {
  if (has_judges(options.build_dir, part)) return run_judged(part, spec, options, problem);
  std::vector<CheckResult> checks;
  fs::path junit = fs::absolute(options.out_dir) / ("part" + std::to_string(part) + "-tests.xml");
  fs::remove(junit);
  char timeout[32];
  std::snprintf(timeout, sizeof timeout, "%.0f", std::ceil(load_scaled_limit(spec.test_timeout)));
  // The whole run has a time limit too, so that even a wedged ctest cannot stop the grader.
  ChildResult c = run_child({"ctest", "--test-dir", options.build_dir, "-L", part_label(part),
                             "--timeout", timeout, "--output-junit", junit.string(), "-j2"},
                            spec.build_timeout);
  pugi::xml_document doc;
  if (!doc.load_file(junit.c_str())) {
    *problem = "the tests of part " + std::to_string(part) + " did not run (ctest " + c.describe() +
               ")";
    return checks;
  }
  for (pugi::xpath_node n : doc.select_nodes("//testcase")) {
    pugi::xml_node t = n.node();
    CheckResult r;
    r.kind = "test";
    r.name = t.attribute("name").as_string();
    if (r.name.rfind("isolated.", 0) == 0) r.name = r.name.substr(9);
    r.seconds = t.attribute("time").as_double();
    std::string status = t.attribute("status").as_string();
    std::string out = t.child("system-out").text().as_string();
    r.skipped = t.child("skipped") || status == "disabled" || status == "notrun";
    r.pass = !r.skipped && !t.child("failure") && !t.child("error") && status != "fail";
    if (r.skipped) {
      const std::string why = gtest_skip_reason(out);
      r.output = skipped_message(why.empty() ? "the test did not run"
                                              : relative_to(why, options.source_dir));
    } else if (!r.pass) {
      std::string f = first_failure(out);
      std::string message = t.child("failure").attribute("message").as_string();
      if (f.empty()) {
        f = message.empty() ? "failed" : message;
        if (out.find("Timeout") != std::string::npos || message.find("Timeout") != std::string::npos)
          f = "timed out (" + std::string(timeout) + " s): an endless loop, or far too slow?";
        else if (out.find("SEGFAULT") != std::string::npos || message.find("SEGFAULT") != std::string::npos ||
                 out.find("Exception") != std::string::npos)
          f = "crashed (" + (message.empty() ? std::string("signal") : message) + ")";
      }
      r.output = mark_values(bounded(relative_to(f, options.source_dir), kCheckMessageChars));
      r.todo = student_lines(out, options);
    }
    checks.push_back(r);
  }
  return checks;
}

}  // namespace

int StepResult::counted() const {
  int n = 0;
  for (const CheckResult& c : checks) n += c.skipped ? 0 : 1;
  return n;
}

int StepResult::failed() const {
  int n = 0;
  for (const CheckResult& c : checks) n += (!c.skipped && !c.pass) ? 1 : 0;
  return n;
}

int StepResult::skipped() const { return int(checks.size()) - counted(); }

double StepResult::skipped_points() const {
  return checks.empty() ? 0.0 : max_score * double(skipped()) / double(checks.size());
}

int PartResult::skipped_checks() const {
  int n = 0;
  for (const StepResult& r : steps) n += r.skipped();
  return n;
}

double PartResult::skipped_points() const {
  double s = 0.0;
  for (const StepResult& r : steps) s += r.skipped_points();
  return s;
}

double PartResult::score() const {
  double s = 0.0;
  for (const StepResult& r : steps) s += r.score;
  return s;
}

double PartResult::max_score() const {
  double s = 0.0;
  for (const StepResult& r : steps) s += r.max_score;
  return s;
}

int PartResult::failing_steps() const {
  int n = 0;
  for (const StepResult& r : steps) n += r.passed() ? 0 : 1;
  return n;
}

namespace {

/// The rules the failing checks after the first enforce that the first's message did not name,
/// each once: the step's message names every rule its failing checks hold the code to, not only
/// the first check's. Bounded: the step's checks' rules, each once.
std::string other_failing_rules(const StepSpec& spec, const std::vector<CheckResult>& checks) {
  std::set<std::string> named;
  std::vector<std::string> others;
  std::string rules;
  bool first = true;
  for (const CheckResult& c : checks) {
    if (c.skipped || c.pass) continue;
    const std::vector<const Rule*> enforced = rules_enforced_by(spec, c.name);
    if (first) {
      for (const Rule* rule : enforced) named.insert(rule->id);
      first = false;
      continue;
    }
    bool adds = false;
    for (const Rule* rule : enforced)
      if (named.insert(rule->id).second) {
        rules += "\nThe rule it checks, #" + rule->id + ": " + rule->text;
        adds = true;
      }
    if (adds) others.push_back(c.name.substr(c.name.rfind('.') + 1));
  }
  if (others.empty()) return "";
  std::string names;
  for (size_t i = 0; i < others.size(); ++i) names += (i ? ", " : "") + others[i];
  return "\nAlso failing: " + names + rules;
}

}  // namespace

StepResult score_step(const StepSpec& spec, std::vector<CheckResult> checks) {
  StepResult r;
  r.part = spec.part;
  r.step = spec.step;
  r.name = spec.full_name();
  r.max_score = spec.points;
  r.checks = std::move(checks);
  const int counted = r.counted(), failed = r.failed();
  // Why checks were skipped, each reason once: what the student can do to run them.
  std::string skips;
  {
    std::set<std::string> seen;
    for (const CheckResult& c : r.checks)
      if (c.skipped && seen.insert(c.output).second && seen.size() <= 2)
        skips += "\n  " + c.name + ": " + c.output;
  }
  const std::string skipped_line =
      r.skipped() == 0
          ? ""
          : "\n" + std::to_string(r.skipped()) + " of " + std::to_string(r.checks.size()) +
                " checks skipped, not counted (the step's points are shared among the " +
                std::to_string(counted) + " that ran):" + skips;
  if (counted == 0) {
    r.message = r.checks.empty() ? "no check of this step ran (none was built or registered)"
                                 : "every check of this step was skipped: nothing to score" +
                                       skipped_line;
    return r;
  }
  r.score = spec.points * double(counted - failed) / double(counted);
  // A failing check says which of the step's rules it enforces: the rule the code breaks.
  for (CheckResult& c : r.checks) {
    if (c.skipped || c.pass) continue;
    std::string broken;
    for (const Rule* rule : rules_enforced_by(spec, c.name))
      broken += "\nThe rule it checks, #" + rule->id + ": " + rule->text;
    c.output += broken;
  }
  std::set<std::string> todo_seen;
  std::string todo;
  for (const CheckResult& c : r.checks) {
    std::istringstream in(c.todo);
    for (std::string line; std::getline(in, line);)
      if (line.find("not implemented") != std::string::npos) {
        size_t start = line.find_first_not_of(' ');
        std::string l = start == std::string::npos ? line : line.substr(start);
        if (todo_seen.insert(l).second && todo_seen.size() <= 4) todo += "\n" + l;
      }
  }
  // The first failing check whole: what it expected and what came back, then its rule.
  for (const CheckResult& c : r.checks) {
    if (c.skipped || c.pass) continue;
    r.message = c.name + ": " + c.output;
    break;
  }
  if (failed > 0) {
    r.message += "\n" + std::to_string(failed) + " of " + std::to_string(counted) +
                 " checks failed" + other_failing_rules(spec, r.checks) + todo;
  } else {
    r.message = "all " + std::to_string(counted) + " checks pass";
  }
  r.message += skipped_line;
  return r;
}

std::string not_implemented_lines(const std::string& output, const std::set<std::string>& only) {
  std::set<std::string> seen;
  std::string s;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    if (line.find("not implemented") == std::string::npos) continue;
    if (!only.empty() && !only.count(line)) continue;
    if (seen.insert(line).second && seen.size() <= 10) s += "    " + line + "\n";
  }
  return s;
}

namespace {

std::string parts_list(const std::vector<int>& parts) {
  std::string s = parts.size() > 1 ? "Parts " : "Part ";
  for (size_t i = 0; i < parts.size(); ++i)
    s += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + std::to_string(parts[i]);
  return s;
}

/// What a render that fails with every earlier step of its part passing should say: look at this
/// step, unless an earlier part it runs fails (or is not known to pass).
std::string look_here_or_earlier(const EarlierParts& parts, const std::string& lead) {
  if (!parts.failing.empty())
    return lead + ", but it also runs your " + parts_list(parts.failing) + ", which " +
           (parts.failing.size() > 1 ? "fail" : "fails") +
           " (as last graded): fix that first, this render may fail for it.";
  std::string s = lead + ", so look first at this step's code.";
  if (!parts.unknown.empty())
    s += " It also runs your " + parts_list(parts.unknown) +
         ", not graded since its files last changed: grade " +
         (parts.unknown.size() > 1 ? "them" : "it") + " to know whether " +
         (parts.unknown.size() > 1 ? "they pass." : "it passes.");
  return s;
}

}  // namespace

std::string render_rests_on_line(const PartSpec& spec, const RenderCheck& check,
                                 const std::vector<std::pair<int, int>>& tests_failed_of,
                                 const EarlierParts& parts) {
  if (check.rests_on_steps.empty())
    return look_here_or_earlier(parts, "This render runs only this step's functions of this part");
  std::string line = "This render also runs this part's step";
  line += check.rests_on_steps.size() > 1 ? "s " : " ";
  bool any_failing = false;
  for (size_t i = 0; i < check.rests_on_steps.size(); ++i) {
    const int k = check.rests_on_steps[i];
    const StepSpec* st = nullptr;
    for (const StepSpec& s : spec.steps)
      if (s.step == k) st = &s;
    line += i == 0 ? "" : i + 1 == check.rests_on_steps.size() ? " and " : ", ";
    line += std::to_string(k) + " (" + (st ? st->name : std::string("?")) + ": ";
    const auto [failed, counted] = k < int(tests_failed_of.size()) ? tests_failed_of[size_t(k)]
                                                                   : std::make_pair(0, 0);
    if (counted == 0)
      line += "no checks ran";
    else if (failed == 0)
      line += "its checks pass";
    else
      line += std::to_string(failed) + " of " + std::to_string(counted) + " checks fail";
    any_failing = any_failing || failed > 0 || counted == 0;
    line += ")";
  }
  if (any_failing)
    return line + ": fix the failing step first, this render may fail for it "
                  "(while it fails, the render's points are charged to it).";
  return look_here_or_earlier(parts, line + ": their checks pass");
}

CheckResult grade_render(const Manifest& manifest, const RenderCheck& check,
                         const GradeOptions& options) {
  CheckResult r;
  r.name = check.name;
  r.kind = "render";
  r.seed = uint64_t(int64_t(check.seed) + options.seed_offset);
  fs::path scene = scene_path(check, options);
  if (check.course_scene && !fs::exists(scene)) {
    r.skipped = true;
    r.output = skipped_message("the course's scene " + check.scene +
                               " is not there: put the course's scenes at "
                               "../shared/scenes/cs184 (beside the project) and grade again");
    return r;
  }
  fs::path reference = fs::path(options.source_dir) / check.reference;
  const bool variant = !options.reference_renderer.empty();
  if (variant) {
    // A variant drawn for this grading, its reference rendered now, in the grader's own folder.
    const fs::path dir = fs::absolute(options.out_dir) / "variants" / check.name;
    fs::create_directories(dir);
    fs::path variant_scene = dir / scene.filename();
    reference = dir / "reference.exr";
    try {
      write_scene_variant(scene.string(), variant_key_for(options.variant_key, check.name),
                          variant_scene.string());
    } catch (const std::exception& e) {
      r.output = std::string("the grader cannot make the scene's variant: ") + e.what();
      return r;
    }
    scene = variant_scene;
  } else if (!fs::exists(reference)) {
    r.output = "the reference " + reference.string() +
               " is missing: an instructor makes it with `grader --make-reference`";
    return r;
  }
  if (!variant) try {
    std::string sum = file_checksum(reference.string());
    if (sum != check.checksum) {
      r.output = "the reference " + reference.string() + " has checksum " + sum +
                 " but the manifest says " + (check.checksum.empty() ? "none" : check.checksum) +
                 ": it was changed or never recorded; remake it with `grader --make-reference`";
      return r;
    }
  } catch (const std::exception& e) {
    r.output = e.what();
    return r;
  }
  fs::create_directories(options.out_dir);
  fs::path out = fs::absolute(options.out_dir) / (check.name + ".exr");
  fs::remove(out);
  std::string scratch;
  if (options.sandbox) {
    // The render writes only in its scratch folder; the grader reads the file back only if the
    // render made it there itself (not a link to a reference).
    scratch = options.sandbox->make_scratch("render");
    out = fs::path(scratch) / (check.name + ".exr");
    if (variant) {
      // The render reads its scene from its own folder: the grader's folder stays the grader's.
      fs::path mine = fs::path(scratch) / scene.filename();
      fs::copy_file(scene, mine, fs::copy_options::overwrite_existing);
      if (options.sandbox->protects() &&
          chown(mine.c_str(), uid_t(options.sandbox->uid_of(scratch)),
                gid_t(options.sandbox->uid_of(scratch))) != 0) {
        r.output = "the grader cannot hand the render its scene";
        options.sandbox->finish(scratch);
        return r;
      }
      scene = mine;
    }
  }
  std::vector<std::string> argv = {pathtracer_for(check.part, options)};
  argv.insert(argv.end(), check.args.begin(), check.args.end());
  argv.insert(argv.end(), {"--seed", std::to_string(r.seed), "-f", out.string(), scene.string()});
  const double limit = load_scaled_limit(check.timeout);
  ChildResult c = options.sandbox ? run_child(argv, options.sandbox->options(scratch, limit))
                                  : run_child(argv, limit);
  struct ScratchCleanup {
    const Sandbox* sandbox;
    std::string dir;
    ~ScratchCleanup() {
      if (sandbox) sandbox->finish(dir);
    }
  } cleanup{options.sandbox, scratch};
  if (c.killed_from_outside)
    throw std::runtime_error(check.name + " was killed by no limit of its own (from outside its "
                             "sandbox): the grader's error, not a verdict");
  r.seconds = c.seconds;
  r.todo = student_lines(c.output, options);
  if (!c.ok()) {
    // Nothing of its own output but the stubs' lines (r.todo): the command shows the rest to
    // whoever runs it. Its exit status is the student's value.
    // In the sandbox the command names the grader's private folders (and its process ids):
    // the student is shown what to run, the flags and the scene's name.
    std::vector<std::string> shown = argv;
    if (options.sandbox) {
      shown.front() = "pathtracer";
      shown[shown.size() - 2] = out.filename().string();
      shown.back() = scene.filename().string();
    }
    r.output = "the render " + mark_values(c.describe()) + ": " + command_line(shown);
    return r;
  }
  // A stub of this part that ran is not the student's answer. No stub gives a right image (that
  // is the guard a submission cannot silence); the stub also says so itself (PT_STUDENT_TODO),
  // once per process, and a render that says so fails at once.
  if (c.output.find("part " + std::to_string(check.part) + " not implemented") != std::string::npos) {
    r.output = "the render ran this part's unwritten stubs (their lines are below), so it shows "
               "no code of yours";
    return r;
  }
  if (variant) {
    // The variant's reference, rendered now (only for a render that got this far: a stub's or a
    // crashed render costs no reference).
    double seconds = 0.0;
    const fs::path private_scene = fs::absolute(options.out_dir) / "variants" / check.name /
                                   scene.filename();
    std::string why = render_reference(check, options.reference_renderer, private_scene.string(),
                                       reference.string(), &seconds, false);
    if (!why.empty()) {
      r.output = "the grader could not render the reference (not a verdict on your code): " + why;
      return r;
    }
  }
  RenderEstimate render, ref;
  if (options.sandbox) {
    std::string not_its_own = check_scratch_output(out.string(), *options.sandbox);
    if (!not_its_own.empty()) {
      r.output = "the render's output is not used: " + not_its_own;
      return r;
    }
  }
  try {
    render = read_estimate_exr(out.string());
  } catch (const std::exception&) {
    // Not the reader's words: they may quote the file's own header, which the student wrote.
    r.output = "the render's output cannot be read as the renderer's EXR (its mean, variance and "
               "count per pixel)";
    return r;
  }
  try {
    ref = read_estimate_exr(reference.string());
  } catch (const std::exception& e) {
    r.output = std::string("the reference cannot be read: ") + e.what();
    return r;
  }
  VarianceConsistencyOptions plausibility = variance_options(manifest, check);
  // The sample counts are checked where the student's renderer is not trusted (the bundle); a
  // developer's own grading (and the grader's tests' stand-in renderer) may state any count.
  if (!options.sandbox) plausibility.expected_count = 0;
  VarianceConsistencyResult plausible = check_variance_consistency(render, ref, plausibility);
  if (!plausible.pass) {
    r.output = mark_values(plausible.summary);
    return r;
  }
  BlockTestOptions bt;
  bt.block_size = manifest.block_size;
  bt.alpha = manifest.alpha;
  bt.relative_tolerance =
      check.relative_tolerance >= 0.0 ? check.relative_tolerance : manifest.relative_tolerance;
  bt.absolute_tolerance = manifest.absolute_tolerance;
  Comparison cmp = compare_render(render, ref, bt, check.kind,
                                  (fs::absolute(options.out_dir) / (check.name + "_diff.png")).string());
  r.pass = cmp.pass;
  // Statistics of the student's image: its values, as a judge's are.
  r.output = mark_values(cmp.message);
  if (r.pass && check.noise_limit > 0.0) {
    std::string noise = check_noise(render, ref, check.noise_limit);
    if (!noise.empty()) {
      r.pass = false;
      r.output = mark_values(noise);
    }
  }
  return r;
}

namespace {
fs::path part_folder(int part, const GradeOptions& options);

/// Shows the student's values in the results' words. With a budget (`left`: the bundle's
/// results, which leave the grading machine) step by step while it lasts: each step's message
/// quotes its first failing check's (at most kValuesPerStep), and no check's own output quotes
/// any (the step's message is where a student reads them, and a value said twice would be a
/// second copy of the student's bytes in the results). Without one (a run on the student's own
/// machine) every value, each in its bounded form.
void release_student_values(PartResult& result, int* left) {
  int none = 0;
  for (StepResult& st : result.steps) {
    st.message = release_values(st.message, left);
    for (CheckResult& c : st.checks) c.output = release_values(c.output, left ? &none : nullptr);
  }
}
}  // namespace

PartResult grade_part(const Manifest& manifest, int part, const GradeOptions& options) {
  auto start = std::chrono::steady_clock::now();
  PartResult result;
  result.part = part;
  result.graded_alone = options.isolated;
  const PartSpec* spec = manifest.find_part(part);
  if (!spec) {
    result.built = false;
    result.build_output = "the manifest has no part " + std::to_string(part);
    return result;
  }
  fs::create_directories(options.out_dir);
  // The files as they are when grading starts: an edit made while it runs is not what it graded.
  if (const fs::path folder = part_folder(part, options); !folder.empty())
    result.files = folder_fingerprint(folder.string());
  result.rests_on = rests_on_line(manifest, part, options);
  // Part 5's rule is the instructor's choice: the student is told which one is graded.
  const std::vector<const RenderCheck*> every_rule = spec->renders_of_every_rule();
  if (std::any_of(every_rule.begin(), every_rule.end(),
                  [](const RenderCheck* r) { return !r->stopping_rule.empty(); }))
    result.rests_on += std::string(result.rests_on.empty() ? "" : "\n") + "Part " +
                       std::to_string(part) + " is graded on the " + manifest.stopping_rule +
                       " stopping rule (reference/manifest.json's stopping_rule).";
  if (options.build) {
    ChildResult c = run_child({"cmake", "--build", options.build_dir, "--target",
                               part_target(part, options), "-j2"},
                              spec->build_timeout);
    result.built = c.ok();
    if (!result.built)
      result.build_output = "part " + std::to_string(part) + " does not build (" + c.describe() +
                            "):\n" + build_errors(c.output, options.source_dir);
  }
  if (!result.built) {
    for (const StepSpec& st : spec->steps) {
      StepResult r;
      r.part = part;
      r.step = st.step;
      r.name = st.full_name();
      r.max_score = st.points;
      r.message = "not graded: part " + std::to_string(part) + " does not build (above)";
      result.steps.push_back(r);
    }
    return result;
  }
  std::vector<std::vector<CheckResult>> by_step(spec->steps.size() + 1);
  std::string test_problem;
  if (options.run_tests && !has_judges(options.build_dir, part))
    result.rests_on += std::string(result.rests_on.empty() ? "" : "\n") +
                       "This build has no judges (its linker cannot make probes): the tests' own "
                       "programs decided them, which is a developer's check, not a grade.";
  if (options.run_tests) {
    for (CheckResult& c : run_tests(part, *spec, options, &test_problem)) {
      int k = step_of(c.name, part);
      if (k >= 1 && k <= int(spec->steps.size()))
        by_step[size_t(k)].push_back(std::move(c));
      else
        result.unassigned.push_back(c.name);
    }
  }
  // Each step's tests, as they stand before the renders: a failing render says the state of the
  // earlier steps it rests on (a render belongs to the latest step it runs, docs/grading.md).
  std::vector<std::pair<int, int>> tests_failed_of(spec->steps.size() + 1, {0, 0});
  for (size_t k = 1; k < by_step.size(); ++k)
    for (const CheckResult& c : by_step[k])
      if (!c.skipped) {
        ++tests_failed_of[k].second;
        tests_failed_of[k].first += !c.pass;
      }
  const EarlierParts earlier = earlier_parts(manifest, part, options);
  for (const StepSpec& st : spec->steps) {
    for (const RenderCheck& check : st.renders) {
      CheckResult c = grade_render(manifest, check, options);
      if (!c.pass && !c.skipped && options.run_tests)
        c.output += "\n" + render_rests_on_line(*spec, check, tests_failed_of, earlier);
      by_step[size_t(st.step)].push_back(std::move(c));
    }
    StepResult r = score_step(st, std::move(by_step[size_t(st.step)]));
    if (!test_problem.empty() && r.counted() == 0) r.message = test_problem;
    if (options.skip_is_error)
      for (const CheckResult& c : r.checks)
        if (c.skipped)
          throw std::runtime_error("the check " + c.name + " could not run (" + c.output +
                                   "): the bundle must ship everything its checks need");
    result.steps.push_back(std::move(r));
  }
  charge_steps_at_fault(*spec, result.steps);
  compare_with_gradescope(manifest, result, options);
  release_student_values(result, options.quote_budget);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

namespace {

fs::path part_folder(int part, const GradeOptions& options) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(options.source_dir) / "parts", ec))
    if (e.is_directory() && e.path().filename().string().rfind(std::to_string(part) + "-", 0) == 0)
      return e.path();
  return {};
}

std::string clock_time(double epoch) {
  std::time_t t = std::time_t(epoch);
  char buf[32];
  std::strftime(buf, sizeof buf, "%H:%M", std::localtime(&t));
  return buf;
}

/// Whether part `part`'s files are no longer those its record in state.json was graded on.
bool changed_since_graded(const nlohmann::json& record, int part, const GradeOptions& options) {
  const fs::path folder = part_folder(part, options);
  if (folder.empty() || !record.contains("files") || !record["files"].is_string()) return false;
  return record["files"].get<std::string>() != folder_fingerprint(folder.string());
}

nlohmann::json read_state(const GradeOptions& options) {
  std::ifstream in(fs::path(options.out_dir) / "state.json");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() ? j : nlohmann::json::object();
}

}  // namespace

std::string rests_on_line(const Manifest& manifest, int part, const GradeOptions& options) {
  const PartSpec* spec = manifest.find_part(part);
  if (!spec || spec->renders_rest_on.empty()) return "";
  std::string parts;
  for (size_t i = 0; i < spec->renders_rest_on.size(); ++i) {
    parts += (i == 0 ? "" : i + 1 == spec->renders_rest_on.size() ? " and " : ", ");
    parts += "Part " + std::to_string(spec->renders_rest_on[i]);
  }
  const std::string head = "Part " + std::to_string(part) + "'s renders trace rays with ";
  if (options.isolated)
    return head + "the complete solution of " + parts + " (--isolated): only Part " +
           std::to_string(part) + "'s code is graded.";
  nlohmann::json state = read_state(options);
  std::string line = head + "your " + parts + ":";
  for (size_t i = 0; i < spec->renders_rest_on.size(); ++i) {
    int k = spec->renders_rest_on[i];
    std::string key = std::to_string(k);
    line += i == 0 ? " " : ", ";
    if (!state.contains(key) || !state[key].is_object()) {
      line += "Part " + key + " not graded yet (grader --part " + key + ")";
      continue;
    }
    const nlohmann::json& s = state[key];
    double when = s.value("time", 0.0);
    int failing = s.value("failing_steps", -1);
    bool built = s.value("built", true);
    line += "Part " + key;
    if (!built) line += " did not build";
    else if (failing == 0) line += " passed";
    else line += " has " + std::to_string(failing) + " failing step" + (failing == 1 ? "" : "s");
    line += " (" + clock_time(when);
    if (s.value("isolated", false)) line += ", isolated";
    if (changed_since_graded(s, k, options)) line += ", changed since";
    line += ")";
  }
  return line + ".";
}

EarlierParts earlier_parts(const Manifest& manifest, int part, const GradeOptions& options) {
  EarlierParts parts;
  const PartSpec* spec = manifest.find_part(part);
  if (!spec || options.isolated) return parts;
  const nlohmann::json state = read_state(options);
  for (int k : spec->renders_rest_on) {
    const std::string key = std::to_string(k);
    if (!state.contains(key) || !state[key].is_object() ||
        changed_since_graded(state[key], k, options))
      parts.unknown.push_back(k);
    else if (!state[key].value("built", true) || state[key].value("failing_steps", 0) > 0)
      parts.failing.push_back(k);
  }
  return parts;
}

void compare_with_gradescope(const Manifest& manifest, PartResult& result,
                             const GradeOptions& options) {
  const PartSpec* spec = manifest.find_part(result.part);
  result.graded_alone = options.isolated;
  if (!spec || options.isolated) return;
  // The earlier parts of the student's that fail, as last graded.
  const nlohmann::json state = read_state(options);
  auto failing = [&](int k) {
    const std::string key = std::to_string(k);
    if (!state.contains(key) || !state[key].is_object()) return false;
    return !state[key].value("built", true) || state[key].value("failing_steps", 0) > 0;
  };
  result.changed_parts_run.clear();
  for (int k : spec->renders_rest_on) {
    const std::string key = std::to_string(k);
    if (failing(k) && changed_since_graded(state[key], k, options))
      result.changed_parts_run.push_back(k);
  }
  // With a complete solution apart (PT_SOLUTION_DIR), the tests run it, not the student's.
  const bool tests_run_students = !has_separate_solution(options.build_dir).value_or(false);
  std::set<int> ran;
  double open = 0.0;
  for (const StepResult& st : result.steps) {
    const int counted = st.counted();
    if (counted == 0) continue;
    for (const CheckResult& c : st.checks) {
      if (c.pass || c.skipped) continue;
      const std::vector<int>& parts = c.kind == "render" ? spec->renders_rest_on
                                      : tests_run_students ? spec->tests_rest_on
                                                           : std::vector<int>();
      bool open_check = false;
      for (int k : parts)
        if (failing(k)) {
          ran.insert(k);
          open_check = true;
        }
      if (!open_check) continue;
      ++result.open_checks;
      open += st.max_score / double(counted);
    }
  }
  result.open_points = std::min(open, result.max_score() - result.score());
  result.failing_parts_run.assign(ran.begin(), ran.end());
}

void record_state(const PartResult& result, const GradeOptions& options) {
  nlohmann::json state = read_state(options);
  double now = double(std::chrono::duration_cast<std::chrono::seconds>(
                          std::chrono::system_clock::now().time_since_epoch()).count());
  state[std::to_string(result.part)] = {{"time", now},
                                        {"built", result.built},
                                        {"failing_steps", result.failing_steps()},
                                        {"score", result.score()},
                                        {"max_score", result.max_score()},
                                        {"isolated", options.isolated}};
  // The files graded, by content: an edit made in the same second as this record is seen, and
  // an edit undone is no change.
  if (!result.files.empty()) state[std::to_string(result.part)]["files"] = result.files;
  fs::create_directories(options.out_dir);
  std::ofstream(fs::path(options.out_dir) / "state.json") << state.dump(2) << "\n";
}

std::string render_reference(const RenderCheck& check, const std::string& renderer,
                             const std::string& scene, const std::string& out, double* seconds,
                             bool verbose) {
  // One render, or several (seeds reference_seed, +1, ...) whose mean is the reference, made in
  // a folder of their own (an adaptive render writes its sample-rate image beside it).
  std::vector<RenderEstimate> runs;
  const fs::path run_dir = fs::path(out).parent_path() / ("runs-" + check.name);
  std::error_code made_dir;
  fs::create_directories(run_dir, made_dir);
  if (made_dir) return "cannot make " + run_dir.string() + ": " + made_dir.message();
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{run_dir};
  for (int k = 0; k < check.reference_runs; ++k) {
    const fs::path file = run_dir / ("run" + std::to_string(k) + ".exr");
    std::vector<std::string> argv = {renderer};
    argv.insert(argv.end(), check.reference_args.begin(), check.reference_args.end());
    argv.insert(argv.end(), {"--seed", std::to_string(check.reference_seed + uint64_t(k)), "-f",
                             file.string(), scene});
    if (verbose) std::cerr << check.name << ": " << command_line(argv) << "\n";
    ChildResult c = run_child(argv, 3600.0);
    *seconds += c.seconds;
    if (!c.ok()) return "the reference render " + c.describe() + "\n" + output_excerpt(c.output);
    try {
      runs.push_back(read_estimate_exr(file.string()));  // a reference must carry its variance
    } catch (const std::exception& e) {
      return e.what();
    }
  }
  try {
    if (check.reference_runs == 1)
      fs::copy_file(run_dir / "run0.exr", out, fs::copy_options::overwrite_existing);
    else
      write_estimate_exr(out, mean_of_renders(runs));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool make_references(const Manifest& manifest, int part, const GradeOptions& options) {
  bool ok = true;
  for (const PartSpec& p : manifest.parts) {
    if (part != 0 && p.part != part) continue;
    // Every stopping rule's references, so that the instructor's choice in the manifest needs
    // nothing remade.
    for (const RenderCheck* checkp : p.renders_of_every_rule()) {
      const RenderCheck& check = *checkp;
      fs::path scene = scene_path(check, options);
      if (check.course_scene && !fs::exists(scene)) {
        std::cerr << check.name << ": skipped, the course scene " << scene << " is not there\n";
        continue;
      }
      fs::path out = fs::path(options.source_dir) / check.reference;
      fs::create_directories(out.parent_path());
      double seconds = 0.0;
      const std::string why = render_reference(check, options.pathtracer, scene.string(),
                                               out.string(), &seconds, true);
      if (!why.empty()) {
        std::cerr << check.name << ": " << why << "\n";
        ok = false;
        continue;
      }
      try {
        nlohmann::ordered_json made;
        // Paths relative to the project, so the record reads the same on every machine.
        std::string relative_command = "pathtracer " + command_line(check.reference_args) +
                                       " --seed " + std::to_string(check.reference_seed) + " -f " +
                                       check.reference + " " +
                                       (check.course_scene ? "../shared/scenes/cs184/" : "") +
                                       check.scene;
        made["command"] = relative_command;
        made["seed"] = check.reference_seed;
        if (check.reference_runs > 1)
          made["runs"] = "the mean of " + std::to_string(check.reference_runs) +
                         " renders, seeds " + std::to_string(check.reference_seed) + " to " +
                         std::to_string(check.reference_seed + uint64_t(check.reference_runs) - 1);
        made["seconds"] = std::round(seconds * 10.0) / 10.0;
        made["crc32"] = file_checksum(out.string());
        record_reference(options.manifest_path, check.name, made);
        std::cerr << check.name << ": made in " << fixed(seconds) << " s, crc32 "
                  << made["crc32"].get<std::string>() << "\n";
      } catch (const std::exception& e) {
        std::cerr << check.name << ": " << e.what() << "\n";
        ok = false;
      }
    }
  }
  return ok;
}

std::string folder_fingerprint(const std::string& folder) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(folder, ec))
    if (e.is_regular_file(ec)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  XXH3_state_t* st = XXH3_createState();
  XXH3_64bits_reset(st);
  for (const fs::path& f : files) {
    // The name, its length and the bytes: moving bytes from one file to the next changes it too.
    const std::string name = f.lexically_relative(folder).generic_string();
    std::string bytes;
    try {
      bytes = read_text_file(f.string());
    } catch (const std::exception&) {
      bytes = "(unreadable)";
    }
    const uint64_t sizes[2] = {name.size(), bytes.size()};
    XXH3_64bits_update(st, sizes, sizeof sizes);
    XXH3_64bits_update(st, name.data(), name.size());
    XXH3_64bits_update(st, bytes.data(), bytes.size());
  }
  const uint64_t h = XXH3_64bits_digest(st);
  XXH3_freeState(st);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

double load_scaled_limit(double seconds, double load_average, int cores) {
  if (!(load_average > 0.0) || cores < 1) return seconds;
  return seconds * std::clamp(load_average / double(cores), 1.0, kMaxLoadFactor);
}

double load_scaled_limit(double seconds) {
  double load[1] = {0.0};
  if (getloadavg(load, 1) != 1) return seconds;
  return load_scaled_limit(seconds, load[0], int(std::thread::hardware_concurrency()));
}

std::optional<std::string> cmake_cache_value(const std::string& build_dir, const std::string& key) {
  std::ifstream cache(fs::path(build_dir) / "CMakeCache.txt");
  if (!cache) return std::nullopt;
  for (std::string line; std::getline(cache, line);) {
    if (line.rfind(key + ":", 0) != 0) continue;
    const size_t eq = line.find('=');
    return eq == std::string::npos ? std::string() : line.substr(eq + 1);
  }
  return std::string();
}

std::optional<bool> has_separate_solution(const std::string& build_dir) {
  const std::optional<std::string> solution = cmake_cache_value(build_dir, "PT_SOLUTION_DIR");
  if (!solution) return std::nullopt;
  if (solution->empty()) return false;
  const std::string home = cmake_cache_value(build_dir, "CMAKE_HOME_DIRECTORY").value_or("");
  std::error_code ec1, ec2;
  const fs::path a = fs::weakly_canonical(*solution, ec1), b = fs::weakly_canonical(home, ec2);
  return !(a == b);
}

std::string stopping_rule_mismatch(const Manifest& manifest, const std::string& build_dir) {
  const std::optional<std::string> rule = cmake_cache_value(build_dir, "PT_ASSIGNMENT_STOPPING_RULE");
  if (!rule || rule->empty() || *rule == manifest.stopping_rule) return "";
  return "the build in " + build_dir + " was configured for Part 5's " + *rule +
         " stopping rule, but the manifest asks for the " + manifest.stopping_rule +
         " rule: configure it again (cmake -B " + build_dir + " -DPT_STOPPING_RULE=" +
         manifest.stopping_rule + ") so that its tests and renders are the assignment's";
}

}  // namespace pt::grader
