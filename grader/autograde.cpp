#include "grader/autograde.h"

#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <tuple>

#include <nlohmann/json.hpp>

#include "framework/text/text_file.h"
#include "grader/build_errors.h"
#include "grader/elf_object.h"
#include "grader/bundle.h"
#include "grader/grade.h"
#include "grader/handout.h"
#include "grader/manifest.h"
#include "grader/report.h"
#include "grader/scene_variant.h"
#include "grader/solution_fingerprints.h"
#include "grader/student_traces.h"
#include "grader/student_values.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

// What of a grader's error the results quote (the rest goes to the log).
constexpr size_t kGraderErrorChars = 300;

void write_file(const fs::path& path, const std::string& text, fs::perms mode) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot be written");
  fs::permissions(path, mode);
}

/// Sets `dir`'s folders to `dirs` and its files to `files` (`executables` for files with an
/// execute bit), links untouched, and nothing under `skip` (the build tree's secret folder).
void set_modes(const fs::path& dir, fs::perms dirs, fs::perms files, fs::perms executables,
               const fs::path& skip = {}) {
  auto apply = [&](const fs::path& p) {
    struct stat st;
    if (lstat(p.c_str(), &st) != 0 || S_ISLNK(st.st_mode)) return;
    fs::perms mode = S_ISDIR(st.st_mode)       ? dirs
                     : (st.st_mode & 0111) != 0 ? executables
                                                : files;
    chmod(p.c_str(), mode_t(mode));
  };
  apply(dir);
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!skip.empty() && it->path() == skip) {
      it.disable_recursion_pending();
      continue;
    }
    apply(it->path());
  }
}

/// The build tree's folder of everything that holds the complete solution's code or judges the
/// student's (grader/CMakeLists.txt): never the student's user's, never readable by it.
fs::path secret_of(const AutogradeLayout& L) { return L.build / "secret"; }

/// Locks the secret folder: reachable (0711) so the student's user can run the part's probes
/// inside, everything in it the grader's alone (folders 0700, files 0600, programs 0700) but the
/// programs `runnable`, which that user may run and not read (0711).
void lock_secret(const AutogradeLayout& L, const std::vector<std::string>& runnable) {
  const fs::path secret = secret_of(L);
  give_tree(secret, 0, 0);
  set_modes(secret, fs::perms(0700), fs::perms(0600), fs::perms(0700));
  fs::permissions(secret, fs::perms(0711));
  for (const std::string& name : runnable) {
    std::error_code ec;
    if (fs::exists(secret / name, ec)) fs::permissions(secret / name, fs::perms(0711), ec);
  }
}

/// The programs of part `part` that run the student's code with the solution's other parts
/// (its probes and its isolated renderer): linked for its grading alone, removed after it, so that
/// no part's code can ever run another part's.
std::vector<std::string> part_programs(const AutogradeLayout& L, int part) {
  std::vector<std::string> names;
  const std::string probe = "probe_part" + std::to_string(part) + "_";
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(secret_of(L), ec)) {
    std::string n = e.path().filename().string();
    if (n.rfind(probe, 0) == 0) names.push_back(n);
  }
  if (fs::exists(secret_of(L) / ("pathtracer_isolated" + std::to_string(part)), ec))
    names.push_back("pathtracer_isolated" + std::to_string(part));
  return names;
}

void remove_part_programs(const AutogradeLayout& L) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(secret_of(L), ec)) {
    std::string n = e.path().filename().string();
    if (n.rfind("probe_part", 0) == 0 || n.rfind("pathtracer_isolated", 0) == 0)
      fs::remove(e.path(), ec);
  }
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::vector<std::string> lines;
  std::istringstream in(read_text_file(path));
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) lines.push_back(l);
  return lines;
}

std::string excerpt(const std::string& output, size_t lines = 15) {
  std::vector<std::string> all, errors;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    all.push_back(line);
    if (line.find("error") != std::string::npos) errors.push_back(line);
  }
  const std::vector<std::string>& pick = errors.empty() ? all : errors;
  std::string s;
  for (size_t i = pick.size() > lines ? pick.size() - lines : 0; i < pick.size(); ++i)
    s += "    " + pick[i] + "\n";
  return s;
}

/// Gives `path` and everything below it but `skip` to `uid`:`uid` (links themselves, not
/// what they name).
void give_all_but(const fs::path& path, const fs::path& skip, long uid) {
  lchown(path.c_str(), uid_t(uid), gid_t(uid));
  std::error_code ec;
  for (fs::recursive_directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path() == skip) {
      it.disable_recursion_pending();
      continue;
    }
    lchown(it->path().c_str(), uid_t(uid), gid_t(uid));
  }
}

}  // namespace

void open_build_for_compile(const AutogradeLayout& L, long uid) {
  if (uid >= 0) give_all_but(L.build, secret_of(L), uid);
  set_modes(L.build, fs::perms(0755), fs::perms(0644), fs::perms(0755), secret_of(L));
}

void close_build_after_compile(const AutogradeLayout& L, bool given) {
  const fs::path secret = secret_of(L);
  if (given) give_all_but(L.build, secret, 0);
  set_modes(L.build, fs::perms(0711), fs::perms(0600), fs::perms(0711), secret);
  // A shared library is read by the loader (dlopen maps it): the image module, which every
  // render and image test loads, holds no solution, so it stays readable.
  std::error_code ec;
  for (fs::recursive_directory_iterator it(L.build, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path() == secret) {
      it.disable_recursion_pending();
      continue;
    }
    std::string name = it->path().filename().string();
    if (it->is_regular_file() && !it->is_symlink() && name.size() > 3 &&
        name.compare(name.size() - 3, 3, ".so") == 0)
      fs::permissions(it->path(), fs::perms(0755), ec);
  }
}

namespace {

/// The objects the compile of part `part`'s files made (its pt_partN_obj target).
fs::path objects_dir(const AutogradeLayout& L, int part) {
  return L.build / "parts" / "CMakeFiles" / ("pt_part" + std::to_string(part) + "_obj.dir");
}
std::vector<fs::path> part_objects(const AutogradeLayout& L, int part) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(objects_dir(L, part), ec), end; !ec && it != end;
       it.increment(ec))
    if (!it->is_symlink() && it->path().extension() == ".o") found.push_back(it->path());
  return found;
}
/// Removes what the compile of part `part`'s files made.
void remove_part_objects(const AutogradeLayout& L, int part) {
  std::error_code ec;
  for (const fs::path& object : part_objects(L, part)) fs::remove(object, ec);
}

/// The project file an object of part `part` was compiled from ("parts/1-raygen/x.cpp").
std::string source_of_object(const AutogradeLayout& L, int part, const fs::path& object) {
  std::string rel = object.lexically_relative(objects_dir(L, part)).string();
  if (rel.size() > 2 && rel.compare(rel.size() - 2, 2, ".o") == 0) rel.resize(rel.size() - 2);
  return "parts/" + rel;
}

/// Whether the student's build of a part succeeded, and its error excerpt when not.
struct BuildOutcome {
  bool ok = false;
  std::string output;
};

/// Compiles part `part`'s files as the sandbox's user, and nothing else: the build tree is that
/// user's while it compiles (all but the secret folder, which it cannot even list), so an
/// #include, .incbin or __has_include of anything the grader protects fails at compile time.
/// No code of the student's runs during a build. Then the grader, as itself, links the part's
/// probes and isolated renderer in the secret folder, refusing if the link would compile
/// anything (the grader never compiles a student's file with its own rights).
BuildOutcome student_build(int part, const AutogradeLayout& L, const Sandbox& sandbox,
                           double timeout, int jobs) {
  BuildOutcome r;
  const std::string objects = "pt_part" + std::to_string(part) + "_obj";
  std::string scratch = sandbox.make_scratch("build");
  ChildOptions o = sandbox.options(scratch, timeout);
  o.limits.wall_seconds = timeout;  // the build's own limit, never a test run's cap
  o.limits.cpu_seconds = timeout * 4 + 10;
  o.limits.address_space = size_t(8) << 30;  // the compiler on CGAL's headers
  o.limits.file_size = size_t(1) << 30;
  o.limits.disk_bytes = size_t(4) << 30;
  o.environment.push_back("CCACHE_DISABLE=1");
  const long builder = sandbox.uid_of(scratch);
  open_build_for_compile(L, sandbox.protects() ? builder : -1);
  o.confinement.writable.push_back(L.build.string());
  ChildResult c = run_child({"cmake", "--build", L.build.string(), "--target", objects, "-j",
                             std::to_string(std::max(1, jobs))}, o);
  close_build_after_compile(L, sandbox.protects());
  sandbox.finish(scratch);
  if (!c.ok()) {
    // Where its first errors are and what kind, never the compiler's words (they quote the code).
    r.output = "your code did not build (the build " + c.describe() + "):\n" +
               build_errors(c.output, L.project.string());
    return r;
  }
  // The link, as the grader: only objects, never a compile. An object that holds link-time code
  // (or is no relocatable object at all) would have a linker with a compiler plugin compile it,
  // with the grader's rights: refused, in the grader's words (a section's name is the student's).
  for (const fs::path& object : part_objects(L, part)) {
    const std::string why = link_time_code_in(object);
    if (why.empty()) continue;
    std::cerr << "autograde: refused: " << why << "\n";
    r.output = "your code did not build: the object of " + source_of_object(L, part, object) +
               " holds link-time code or is no machine code, which would make the linker compile "
               "it with the grader's rights; the grader links only compiled machine code";
    return r;
  }
  const std::string programs = "probes_part" + std::to_string(part);
  ChildResult plan = run_child({"ninja", "-C", L.build.string(), "-n", programs}, 120.0);
  if (!plan.ok() || plan.output.find("Building C") != std::string::npos) {
    r.output = "the grader would have had to compile code to link your part (it refuses to)";
    return r;
  }
  ChildResult link = run_child({"cmake", "--build", L.build.string(), "--target", programs, "-j",
                                std::to_string(std::max(1, jobs))}, timeout);
  if (!link.ok()) {
    r.output = "your part's objects did not link (" + link.describe() + "):\n" +
               build_errors(link.output, L.project.string());
    return r;
  }
  lock_secret(L, part_programs(L, part));
  r.ok = true;
  return r;
}

}  // namespace

AutogradeLayout AutogradeLayout::under(const std::string& root) {
  AutogradeLayout L;
  L.root = fs::absolute(root);
  L.project = L.root / "source" / "project";
  L.submission = L.root / "submission";
  L.results = L.root / "results" / "results.json";
  L.build = L.project / "build";
  L.private_dir = L.root / "pt" / "private";
  L.scratch = L.root / "pt" / "scratch";
  return L;
}

std::string mount_tree_over(const std::string& tree, const std::string& project) {
  if (unshare(CLONE_NEWNS) != 0)
    return std::string("cannot make a mount namespace of its own: ") + std::strerror(errno);
  // Nothing mounted here may reach the caller's namespace.
  if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
    return std::string("cannot make the mounts private: ") + std::strerror(errno);
  if (mount(tree.c_str(), project.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0)
    return "cannot mount " + tree + " over " + project + ": " + std::strerror(errno);
  return "";
}

void give_tree(const fs::path& dir, long uid, long gid) {
  if (uid < 0) return;
  auto give = [&](const fs::path& p) {
    if (lchown(p.c_str(), uid_t(uid), gid_t(gid)) != 0)
      throw std::runtime_error("cannot give " + p.string() + " to user " + std::to_string(uid));
  };
  give(dir);
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) give(e.path());
}

void autograde_setup(const std::string& root, const std::string& grader_exe, int jobs) {
  AutogradeLayout L = AutogradeLayout::under(root);
  fs::create_directories(L.private_dir);
  std::vector<std::string> files = student_files(L.project.string());
  if (files.empty()) throw std::runtime_error(L.project.string() + ": no student files (no BEGIN SOLUTION under parts/)");
  std::string list;
  for (const std::string& f : files) list += f + "\n";
  write_file(L.student_list(), list, fs::perms(0600));
  for (const std::string& f : files)
    write_file(L.stubs() / f, strip_solution(read_text_file(L.project / f), f), fs::perms(0644));
  fs::copy_file(grader_exe, L.grader(), fs::copy_options::overwrite_existing);
  fs::permissions(L.grader(), fs::perms(0700));
  // The tree keeps no solution the student's user can read: the stubs take the student files'
  // place, solution-only files (the wide BVH) are the grader's alone.
  for (const std::string& f : files) {
    fs::remove(L.project / f);
    fs::copy_file(L.stubs() / f, L.project / f);
    fs::permissions(L.project / f, fs::perms(0644));
  }
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(L.project)) {
    if (e.is_regular_file() && !e.is_symlink() && is_solution_only(read_text_file(e.path())))
      fs::permissions(e.path(), fs::perms(0600));
  }
  // A part's isolated renderer links the later parts' stubs, the copy just written: configured
  // again, so that the build knows them.
  ChildResult configured =
      run_child({"cmake", "-DPT_STUB_DIR=" + L.stubs().string(), L.build.string()}, 600.0);
  if (!configured.ok())
    throw std::runtime_error("the build cannot be configured with the stubs (" +
                             configured.describe() + "):\n" + excerpt(configured.output, 30));
  // What grading runs, built now with the stubs in the part folders: the judges (no student
  // code), the complete solution's renderer (the references of the renders' variants), and every
  // object a part's probes link, so that a submission's build compiles its own files only. The
  // solution's objects, and the stubs' a part's renderer links for the parts after it, are
  // compiled into the secret folder.
  std::vector<std::string> targets = {"pathtracer_solution"};
  Manifest manifest = read_manifest((L.project / "reference" / "manifest.json").string());
  for (const PartSpec& spec : manifest.parts) {
    targets.push_back("judges_part" + std::to_string(spec.part));
    targets.push_back("probes_part" + std::to_string(spec.part));
    // Every part's stubs compiled apart: the given code the fingerprints are told from.
    targets.push_back("pt_stub_part" + std::to_string(spec.part) + "_obj");
  }
  std::vector<std::string> argv = {"cmake", "--build", L.build.string(), "-j",
                                   std::to_string(std::max(1, jobs)), "--target"};
  argv.insert(argv.end(), targets.begin(), targets.end());
  ChildResult built = run_child(argv, 7200.0);
  if (!built.ok())
    throw std::runtime_error("the grading programs do not build (" + built.describe() + "):\n" +
                             excerpt(built.output, 30));
  // No part's probes wait in the tree between gradings: each part's are linked for it alone.
  remove_part_programs(L);
  lock_secret(L, {});
  // The references and the manifest: the grader's alone (the renders are compared by it).
  set_modes(L.project / "reference", fs::perms(0700), fs::perms(0600), fs::perms(0600));
  // The private folder: reachable (the build stats the solution copy's files, whose names are
  // no secret), nothing in it readable but the stubs.
  set_modes(L.private_dir, fs::perms(0755), fs::perms(0600), fs::perms(0700));
  set_modes(L.stubs(), fs::perms(0755), fs::perms(0644), fs::perms(0644));
  fs::permissions(L.private_dir, fs::perms(0711));
  fs::create_directories(L.results.parent_path());
  fs::permissions(L.results.parent_path(), fs::perms(0700));
  fs::create_directories(L.scratch);
  fs::permissions(L.scratch, fs::perms(0711));
  std::cerr << "autograde-setup: " << files.size() << " student files, grading programs built, "
            << "private folder " << L.private_dir << "\n";
  std::cerr << "autograde-setup: " << check_no_solution_readable(L) << "\n";
}

std::string check_no_solution_readable(const AutogradeLayout& L) {
  if (geteuid() != 0) return "not root: the walk as the student's user was not made";
  // The solution's objects, and the given code's and the stubs' (set-up compiles every part's
  // stubs apart, pt_stub_partN_obj). The part folders' own objects are left out: after a grading
  // they are the last submission's, which may be the solution's own code.
  std::set<fs::path> of_parts;
  for (const PartSpec& spec : read_manifest((L.project / "reference" / "manifest.json").string()).parts)
    for (const fs::path& object : part_objects(L, spec.part)) of_parts.insert(object);
  std::vector<fs::path> solution, given;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(L.build, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file() || it->path().extension() != ".o" || of_parts.count(it->path()))
      continue;
    if (it->path().string().find("/CMakeFiles/pt_solution_part") != std::string::npos)
      solution.push_back(it->path());
    else
      given.push_back(it->path());
  }
  if (solution.empty())
    throw std::runtime_error(secret_of(L).string() + ": no objects of the solution to take prints of");
  const Fingerprints prints = fingerprints_of(solution, given);
  if (prints.by_hash.size() < 100)
    throw std::runtime_error("the solution's objects give only " +
                             std::to_string(prints.by_hash.size()) + " fingerprints");
  // Where the set-up wrote, or a process could have: the root, the shared writable places, the
  // set-up user's home (a compiler cache).
  std::vector<fs::path> roots = {L.root};
  for (const std::string& f : world_writable_places().folders) roots.push_back(f);
  if (const char* home = std::getenv("HOME")) roots.push_back(home);
  // A uid of the first slot, which owns nothing: what any student's process can open.
  const long uid = kFirstStudentUid;
  auto walk = [&](const char* when, WalkCount* n) {
    const std::vector<Carrier> found = files_carrying_as(uid, prints, roots, n);
    if (found.empty()) return;
    std::string list;
    for (size_t i = 0; i < found.size() && i < 10; ++i)
      list += "\n  " + found[i].path + " (at byte " + std::to_string(found[i].offset) + ": " +
              found[i].fingerprint + ")";
    throw std::runtime_error(std::to_string(found.size()) + " file(s) the student's user can open " +
                             when + " carry the solution's code:" + list);
  };
  WalkCount after, compiling;
  walk("after set-up", &after);
  open_build_for_compile(L, uid);
  try {
    walk("while a part compiles", &compiling);
  } catch (...) {
    close_build_after_compile(L, true);
    throw;
  }
  close_build_after_compile(L, true);
  char line[400];
  std::snprintf(line, sizeof line,
                "no file the student's user can open carries the solution's code (%zu "
                "fingerprints of %zu objects; after set-up %zu files, %.1f MB read; while a part "
                "compiles %zu files, %.1f MB)",
                prints.by_hash.size(), prints.objects, after.files, after.bytes / 1048576.0,
                compiling.files, compiling.bytes / 1048576.0);
  return line;
}

int autograde(const std::string& root, const std::vector<int>& parts,
              const AutogradeTuning& tuning) {
  auto start = std::chrono::steady_clock::now();
  AutogradeLayout L = AutogradeLayout::under(root);
  if (!tuning.submission.empty()) L.submission = fs::absolute(tuning.submission);
  if (!tuning.results.empty()) L.results = fs::absolute(tuning.results);
  nlohmann::json results;
  try {
    if (!tuning.tree.empty()) {
      std::string why = mount_tree_over(tuning.tree, L.project.string());
      if (!why.empty()) throw std::runtime_error(why);
    }
    std::vector<std::string> files = read_lines(L.student_list());
    SubmissionIntake intake =
        take_submission(files, L.submission.string(), L.project.string(), L.stubs().string());
    Sandbox sandbox = Sandbox::standard(L.scratch.string(), tuning.slot);
    sandbox.max_check_seconds = tuning.max_check_seconds;
    sandbox.jobs = tuning.jobs > 0 ? tuning.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
    if (tuning.disk_bytes > 0) sandbox.limits.disk_bytes = tuning.disk_bytes;
    Manifest manifest = read_manifest((L.project / "reference" / "manifest.json").string());
    GradeOptions options;
    options.source_dir = L.project.string();
    options.build_dir = L.build.string();
    options.manifest_path = (L.project / "reference" / "manifest.json").string();
    options.pathtracer = (L.build / "app" / "pathtracer").string();
    // Renders and diff images: a folder of this run's own (runs of grader batch go side by side).
    options.out_dir = (L.private_dir / ("out-" + std::to_string(tuning.slot))).string();
    // The records, the variants and their references: the grader's alone, whatever the umask.
    fs::create_directories(options.out_dir);
    fs::permissions(options.out_dir, fs::perms(0700));
    options.build = false;  // built below, as the student's user
    options.isolated = true;
    options.isolated_separate = true;
    options.sandbox = &sandbox;
    options.skip_is_error = true;  // the bundle ships the course's scenes and ray sets
    // Each graded render is of a scene variant drawn now; its reference is rendered now, by the
    // complete solution's renderer, which the student's user can neither read nor run.
    options.reference_renderer = (secret_of(L) / "pathtracer_solution").string();
    options.variant_key = draw_variant_key();
    // Of what the student's code prints, only the handout's own stub lines are quoted.
    if (!tuning.quote_student_lines) options.stub_messages = stub_messages(L.stubs(), files);
    // One results file: one budget of the student's values for every part.
    int values_left = kValuesPerResults;
    options.quote_budget = &values_left;
    remove_part_programs(L);
    // No compile sees what an earlier one made: the objects of any part's files (an earlier
    // submission's, in a root graded twice) are gone before the first compile and after each part.
    for (const PartSpec& spec : manifest.parts) remove_part_objects(L, spec.part);
    std::vector<PartResult> all;
    for (const PartSpec& spec : manifest.parts) {
      if (!parts.empty() && std::find(parts.begin(), parts.end(), spec.part) == parts.end())
        continue;
      std::cerr << "autograde: part " << spec.part << ": building\n";
      BuildOutcome built = student_build(spec.part, L, sandbox, spec.build_timeout, tuning.build_jobs);
      if (built.ok) {
        std::cerr << "autograde: part " << spec.part << ": grading\n";
        all.push_back(grade_part(manifest, spec.part, options));
      }
      remove_part_programs(L);
      remove_part_objects(L, spec.part);
      if (!built.ok) {
        PartResult r;
        r.part = spec.part;
        r.built = false;
        r.build_output = built.output;
        for (const StepSpec& st : spec.steps) {
          StepResult step;
          step.part = spec.part;
          step.step = st.step;
          step.name = st.full_name();
          step.max_score = st.points;
          // Once, in the results' output: the same lines under every step would say no more.
          step.message = "not graded: part " + std::to_string(spec.part) +
                         " did not build (the results' output says where)";
          r.steps.push_back(step);
        }
        all.push_back(r);
      }
      // Nothing a process of this part left may reach the next part: what could not be removed
      // makes the grading the grader's error, never a verdict.
      std::string left = sandbox.leftovers();
      if (!left.empty())
        throw std::runtime_error("a process of the student's left what the grader could not remove: " + left);
    }
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RunInfo info;
    info.isolated = true;
    info.seconds = seconds;
    results = gradescope_results(all, info);
    std::string protection =
        sandbox.protects()
            ? "Your code ran as unprivileged users of its own, one per process, with limits, "
              "and each process left nothing for the next."
            : "UNPROTECTED: the grader did not run as root, so your code ran as the grader's own "
              "user (a developer's run, not an official grade).";
    results["output"] = results["output"].get<std::string>() + "\n" + intake.summary() + "\n" + protection;
    results["extra_data"]["protected"] = sandbox.protects();
    results["extra_data"]["namespaces"] = sandbox.namespaces;
    results["extra_data"]["taken"] = intake.taken;
    results["extra_data"]["missing"] = intake.missing;
    results["extra_data"]["refused"] = intake.refused;
  } catch (const std::exception& e) {
    // The grader's words, but they may name what a student's process left (a file's name): cut
    // short, they are the only text of these results (docs/grading.md, the bound).
    std::cerr << "autograde: " << e.what() << "\n";
    std::string why = e.what();
    if (why.size() > kGraderErrorChars) why = why.substr(0, kGraderErrorChars) + " [...]";
    results = {{"score", 0},
               {"output", std::string("The autograder could not grade this submission: ") + why +
                              ". This is not a verdict on your code: please tell the "
                              "course staff."},
               {"tests", nlohmann::json::array()}};
  }
  try {
    fs::create_directories(L.results.parent_path());
    write_file(L.results, results.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n", fs::perms(0600));
  } catch (const std::exception& e) {
    std::cerr << "autograde: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace pt::grader
