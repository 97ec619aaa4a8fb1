#include "grader/bundle.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "grader/process/child_process.h"
#include "framework/text/text_file.h"
#include "grader/handout.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

constexpr uintmax_t kMaxStudentFile = 1 << 20;

/// Copies a regular file, replacing the target, with mode 0644 (the grader's, readable by the
/// student's build).
void copy_as_ours(const fs::path& from, const fs::path& to) {
  fs::create_directories(to.parent_path());
  fs::remove(to);
  fs::copy_file(from, to);
  fs::permissions(to, fs::perms(0644));
}

void copy_tree_files(const fs::path& from_root, const std::vector<std::string>& rels,
                     const fs::path& to_root) {
  for (const std::string& rel : rels) {
    fs::path to = to_root / rel;
    fs::create_directories(to.parent_path());
    fs::copy_file(from_root / rel, to, fs::copy_options::overwrite_existing);
    fs::permissions(to, fs::status(from_root / rel).permissions());
  }
}

}  // namespace

std::vector<std::string> student_files(const std::string& source_dir) {
  std::vector<std::string> files;
  fs::path parts = fs::path(source_dir) / "parts";
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(parts)) {
    if (!e.is_regular_file()) continue;
    fs::path rel = fs::relative(e.path(), source_dir);
    std::string r = rel.generic_string();
    if (r.find("/tests/") != std::string::npos) continue;
    if (read_text_file(e.path()).find("// BEGIN SOLUTION") == std::string::npos) continue;
    files.push_back(r);
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string SubmissionIntake::summary() const {
  std::string s = "Graded files from your submission: " + std::to_string(taken.size()) + " of " +
                  std::to_string(taken.size() + missing.size() + refused.size()) + ".";
  for (const std::string& m : missing)
    s += "\n  missing: " + m + " (graded as the handout's unimplemented stub)";
  for (const std::string& r : refused) s += "\n  not used: " + r + " (graded as the handout's stub)";
  // Counted, never named: a submission's own names are text the student chose
  // (docs/grading.md, "What reaches the student").
  if (!ignored.empty())
    s += "\n  not graded: " +
         (ignored.size() > 99 ? std::string("more than 99") : std::to_string(ignored.size())) +
         " other file" + (ignored.size() == 1 ? "" : "s") +
         " of the submission (only the files above are graded)";
  return s;
}

SubmissionIntake take_submission(const std::vector<std::string>& files,
                                 const std::string& submission_dir,
                                 const std::string& project_dir, const std::string& stub_dir) {
  SubmissionIntake intake;
  // Every entry of the submission, by relative path, links included (lstat: never followed).
  std::vector<std::string> entries;
  std::error_code ec;
  if (fs::is_directory(submission_dir, ec)) {
    for (fs::recursive_directory_iterator it(submission_dir, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (it->is_directory(ec) && !it->is_symlink(ec)) continue;
      entries.push_back(fs::relative(it->path(), submission_dir, ec).generic_string());
    }
  }
  std::map<std::string, bool> used;
  for (const std::string& rel : files) {
    std::string name = fs::path(rel).filename().string();
    std::vector<std::string> exact, by_name;
    for (const std::string& e : entries) {
      if (e == rel || (e.size() > rel.size() && e.compare(e.size() - rel.size(), rel.size(), rel) == 0 &&
                       e[e.size() - rel.size() - 1] == '/'))
        exact.push_back(e);
      else if (fs::path(e).filename() == name)
        by_name.push_back(e);
    }
    const std::vector<std::string>& found = !exact.empty() ? exact : by_name;
    fs::path stub = fs::path(stub_dir) / rel, target = fs::path(project_dir) / rel;
    std::string why;
    if (found.empty()) {
      intake.missing.push_back(rel);
    } else if (found.size() > 1) {
      why = rel + ": the submission has more than one file that could be it";
    } else {
      fs::path from = fs::path(submission_dir) / found[0];
      struct stat st;
      used[found[0]] = true;
      if (lstat(from.c_str(), &st) != 0 || S_ISLNK(st.st_mode)) {
        why = rel + ": a symbolic link, not a file";
      } else if (!S_ISREG(st.st_mode)) {
        why = rel + ": not a regular file";
      } else if (uintmax_t(st.st_size) > kMaxStudentFile) {
        why = rel + ": larger than 1 MB";
      } else {
        copy_as_ours(from, target);
        intake.taken.push_back(rel);
        continue;
      }
    }
    for (const std::string& f : found) used[f] = true;
    if (!why.empty()) intake.refused.push_back(why);
    copy_as_ours(stub, target);
  }
  for (const std::string& e : entries)
    if (!used.count(e)) intake.ignored.push_back(e);
  return intake;
}

BundleSummary make_gradescope_bundle(const std::string& source_dir, const std::string& out_zip) {
  fs::path src = fs::absolute(source_dir);
  fs::path zip = fs::absolute(out_zip);
  // The bundle never skips a check: what the tests and renders read beside the project (the
  // course's scenes, the ray sets) goes in, or no bundle is made.
  for (const char* shared : {"scenes/cs184", "rays"})
    if (!fs::is_directory(src.parent_path() / "shared" / shared))
      throw std::runtime_error((src.parent_path() / "shared" / shared).lexically_normal().string() +
                               " is not there: the bundle ships the course's scenes and ray sets, "
                               "so that no graded check skips on Gradescope; put them there first");
  fs::path stage = fs::temp_directory_path() / ("pt-bundle-" + std::to_string(::getpid()));
  fs::remove_all(stage);
  BundleSummary summary;
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{stage};
  std::vector<std::string> tracked = tracked_files(source_dir);
  std::vector<std::string> present;
  for (const std::string& rel : tracked) {
    // The write-up is not needed to grade (and needs a browser and npm): it stays out.
    if (rel.rfind("website/", 0) == 0) continue;
    // The mutant catalogue and the second solution are patches that quote the solution's lines:
    // an instructor's tools, never needed to grade, so never in a tree a student's code can read.
    if (in_solution_only_folder(src, rel)) continue;
    if (fs::is_regular_file(src / rel)) present.push_back(rel);
  }
  copy_tree_files(src, present, stage / "project");
  summary.project_files = int(present.size());
  for (const char* script : {"setup.sh", "run_autograder"}) {
    fs::path from = src / "grader" / "bundle" / script;
    if (!fs::is_regular_file(from))
      throw std::runtime_error(from.string() + ": missing (the bundle's scripts live there)");
    fs::copy_file(from, stage / script);
    fs::permissions(stage / script, fs::perms(0755));
  }
  // What tests and renders read beside the project (../shared): the course scenes and the ray
  // sets, so that no graded test skips on Gradescope for want of them.
  for (const char* shared : {"scenes/cs184", "rays"}) {
    fs::path from_root = src.parent_path() / "shared" / shared;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(from_root)) {
      if (!e.is_regular_file()) continue;
      fs::path to = stage / "shared" / shared / fs::relative(e.path(), from_root);
      fs::create_directories(to.parent_path());
      fs::copy_file(e.path(), to);
      ++summary.shared_files;
    }
  }
  fs::create_directories(zip.parent_path());
  fs::remove(zip);
  ChildOptions o;
  o.limits.wall_seconds = 600.0;
  o.working_dir = stage.string();
  ChildResult r = run_child({"zip", "-q", "-r", "-X", zip.string(), "."}, o);
  if (!r.ok())
    throw std::runtime_error("zip " + r.describe() + " (is `zip` installed?): " + r.output);
  summary.bytes = (long long)fs::file_size(zip);
  return summary;
}

}  // namespace pt::grader
