#include "grader/grade.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include <pugixml.hpp>

#include "framework/image/estimate_exr.h"
#include "framework/image/image.h"
#include "framework/process/child_process.h"
#include "framework/stats/variance_consistency.h"
#include "grader/compare.h"

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

CheckResult build_check(int part, const PartSpec& spec, const GradeOptions& options) {
  CheckResult r;
  r.name = "part" + std::to_string(part) + ".build";
  r.part = part;
  ChildResult c = run_child({"cmake", "--build", options.build_dir, "--target",
                             "grade_part" + std::to_string(part), "-j2"},
                            spec.build_timeout);
  r.seconds = c.seconds;
  r.pass = c.ok();
  r.output = r.pass ? "built" : "the build " + c.describe() + ":\n" + output_excerpt(c.output);
  return r;
}

CheckResult test_check(int part, const PartSpec& spec, const GradeOptions& options) {
  CheckResult r;
  r.name = "part" + std::to_string(part) + ".tests";
  r.part = part;
  r.max_score = spec.test_points;
  fs::path junit = fs::absolute(options.out_dir) / ("part" + std::to_string(part) + "-tests.xml");
  fs::remove(junit);
  char timeout[32];
  std::snprintf(timeout, sizeof timeout, "%g", spec.test_timeout);
  // Each test is its own process with its own time limit (ctest's); the whole run has one too,
  // so that even a wedged ctest cannot stop the grader.
  ChildResult c = run_child({"ctest", "--test-dir", options.build_dir, "-L",
                             "^part" + std::to_string(part) + "$", "--timeout", timeout,
                             "--output-on-failure", "--output-junit", junit.string(), "-j2"},
                            spec.build_timeout);
  r.seconds = c.seconds;
  pugi::xml_document doc;
  int total = 0, failed = 0, skipped = 0;
  std::vector<std::string> failures;
  if (doc.load_file(junit.c_str())) {
    for (pugi::xpath_node n : doc.select_nodes("//testcase")) {
      pugi::xml_node t = n.node();
      ++total;
      std::string status = t.attribute("status").as_string();
      if (t.child("skipped") || status == "disabled" || status == "notrun") {
        ++skipped;
      } else if (t.child("failure") || t.child("error") || status == "fail") {
        ++failed;
        failures.push_back(t.attribute("name").as_string());
      }
    }
  }
  int counted = total - skipped;
  if (counted <= 0) {
    r.output = "no tests of part " + std::to_string(part) + " ran (ctest " + c.describe() +
               ")\n" + output_excerpt(c.output, 6);
    return r;
  }
  r.score = r.max_score * double(counted - failed) / counted;
  r.pass = failed == 0;
  r.output = std::to_string(counted - failed) + " of " + std::to_string(counted) +
             " tests passed";
  if (skipped) r.output += " (" + std::to_string(skipped) + " skipped)";
  r.output += "; JUnit XML: " + junit.string();
  for (size_t i = 0; i < failures.size() && i < 20; ++i) r.output += "\n    failed: " + failures[i];
  if (failures.size() > 20) r.output += "\n    ... and " + std::to_string(failures.size() - 20) + " more";
  std::string todo = not_implemented_lines(c.output);
  if (!todo.empty()) r.output += "\n" + todo;
  return r;
}

}  // namespace

std::string not_implemented_lines(const std::string& output) {
  std::set<std::string> seen;
  std::string s;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    if (line.find("not implemented") == std::string::npos) continue;
    if (seen.insert(line).second && seen.size() <= 10) s += "    " + line + "\n";
  }
  return s;
}

CheckResult grade_render(const Manifest& manifest, const RenderCheck& check,
                         const GradeOptions& options) {
  CheckResult r;
  r.name = check.name;
  r.part = check.part;
  r.max_score = check.points;
  fs::path scene = scene_path(check, options);
  if (check.course_scene && !fs::exists(scene)) {
    r.skipped = true;
    r.max_score = 0;
    r.output = "skipped: the course scene " + scene.string() + " is not there";
    return r;
  }
  fs::path reference = fs::path(options.source_dir) / check.reference;
  if (!fs::exists(reference)) {
    r.output = "the reference " + reference.string() +
               " is missing: an instructor makes it with `grader --make-reference`";
    return r;
  }
  try {
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
  }
  std::vector<std::string> argv = {options.pathtracer};
  argv.insert(argv.end(), check.args.begin(), check.args.end());
  argv.insert(argv.end(), {"--seed", std::to_string(check.seed), "-f", out.string(), scene.string()});
  ChildResult c = options.sandbox ? run_child(argv, options.sandbox->options(scratch, check.timeout))
                                  : run_child(argv, check.timeout);
  struct ScratchCleanup {
    const Sandbox* sandbox;
    std::string dir;
    ~ScratchCleanup() {
      if (sandbox) sandbox->finish(dir);
    }
  } cleanup{options.sandbox, scratch};
  r.seconds = c.seconds;
  std::string todo = not_implemented_lines(c.output);
  if (!c.ok()) {
    r.output = "the render " + c.describe() + ": " + command_line(argv) + "\n" +
               (todo.empty() ? output_excerpt(c.output, 8) : todo);
    return r;
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
  } catch (const std::exception& e) {
    r.output = std::string("the render's output cannot be read: ") + e.what();
    return r;
  }
  try {
    ref = read_estimate_exr(reference.string());
  } catch (const std::exception& e) {
    r.output = std::string("the reference cannot be read: ") + e.what();
    return r;
  }
  VarianceConsistencyResult plausible =
      check_variance_consistency(render, ref, variance_options(manifest, check));
  if (!plausible.pass) {
    r.output = plausible.summary;
    return r;
  }
  BlockTestOptions bt;
  bt.block_size = manifest.block_size;
  bt.alpha = manifest.alpha;
  Comparison cmp =
      compare_render(render, ref, bt, (fs::absolute(options.out_dir) / (check.name + "_diff.png")).string());
  r.pass = cmp.pass;
  r.score = cmp.pass ? check.points : 0.0;
  r.output = cmp.message;
  if (!todo.empty()) r.output += "\n" + todo;
  return r;
}

std::vector<CheckResult> grade_part(const Manifest& manifest, int part,
                                    const GradeOptions& options) {
  std::vector<CheckResult> results;
  const PartSpec* spec = manifest.find_part(part);
  if (!spec) {
    CheckResult r;
    r.name = "part" + std::to_string(part);
    r.part = part;
    r.output = "the manifest has no part " + std::to_string(part);
    results.push_back(r);
    return results;
  }
  fs::create_directories(options.out_dir);
  bool built = true;
  if (options.build) {
    results.push_back(build_check(part, *spec, options));
    built = results.back().pass;
  }
  auto not_built = [&](CheckResult r) {
    r.output = "not graded: part " + std::to_string(part) + " did not build (see part" +
               std::to_string(part) + ".build)";
    return r;
  };
  if (options.run_tests) {
    if (built) {
      results.push_back(test_check(part, *spec, options));
    } else {
      CheckResult r;
      r.name = "part" + std::to_string(part) + ".tests";
      r.part = part;
      r.max_score = spec->test_points;
      results.push_back(not_built(r));
    }
  }
  for (const RenderCheck& check : spec->renders) {
    if (built) {
      results.push_back(grade_render(manifest, check, options));
    } else {
      CheckResult r;
      r.name = check.name;
      r.part = part;
      r.max_score = check.points;
      results.push_back(not_built(r));
    }
  }
  return results;
}

bool make_references(const Manifest& manifest, int part, const GradeOptions& options) {
  bool ok = true;
  for (const PartSpec& p : manifest.parts) {
    if (part != 0 && p.part != part) continue;
    for (const RenderCheck& check : p.renders) {
      fs::path scene = scene_path(check, options);
      if (check.course_scene && !fs::exists(scene)) {
        std::cerr << check.name << ": skipped, the course scene " << scene << " is not there\n";
        continue;
      }
      fs::path out = fs::path(options.source_dir) / check.reference;
      fs::create_directories(out.parent_path());
      std::vector<std::string> args = check.reference_args;
      args.insert(args.end(), {"--seed", std::to_string(check.reference_seed), "-f"});
      std::vector<std::string> argv = {options.pathtracer};
      argv.insert(argv.end(), args.begin(), args.end());
      argv.insert(argv.end(), {out.string(), scene.string()});
      std::cerr << check.name << ": " << command_line(argv) << "\n";
      ChildResult c = run_child(argv, 3600.0);
      if (!c.ok()) {
        std::cerr << check.name << ": the reference render " << c.describe() << "\n"
                  << output_excerpt(c.output) << "\n";
        ok = false;
        continue;
      }
      try {
        read_estimate_exr(out.string());  // a reference must carry its variance
        nlohmann::ordered_json made;
        // Paths relative to the project, so the record reads the same on every machine.
        std::string relative_command = "pathtracer " + command_line(args) + " " +
                                       check.reference + " " +
                                       (check.course_scene ? "../shared/scenes/cs184/" : "") +
                                       check.scene;
        made["command"] = relative_command;
        made["seed"] = check.reference_seed;
        made["seconds"] = std::round(c.seconds * 10.0) / 10.0;
        made["crc32"] = file_checksum(out.string());
        record_reference(options.manifest_path, check.name, made);
        std::cerr << check.name << ": made in " << fixed(c.seconds) << " s, crc32 "
                  << made["crc32"].get<std::string>() << "\n";
      } catch (const std::exception& e) {
        std::cerr << check.name << ": " << e.what() << "\n";
        ok = false;
      }
    }
  }
  return ok;
}

}  // namespace pt::grader
