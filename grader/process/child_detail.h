// What the two ways of running a child (linux_keeper.cpp, with the Linux keeper; posix_runner.cpp,
// without it) share: the files that catch its output, its environment, the names of the steps of
// starting it. Internal to grader/process.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

extern char** environ;

namespace pt::child_detail {

/// A temporary file for a child's output, removed when the run is over. Output goes to files
/// rather than pipes: nothing to drain while we wait, and a child that floods its output only
/// grows a file (bounded by the file-size limit) that we read the head of. mkstemp makes it
/// 0600 and ours: a child running as another user writes it only through the descriptor.
struct OutputFile {
  std::string path;
  int fd = -1;
  OutputFile() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "pt-child-XXXXXX").string();
    fd = mkstemp(tmpl.data());
    if (fd >= 0) path = tmpl;
  }
  ~OutputFile() {
    if (fd >= 0) close(fd);
    if (!path.empty()) std::remove(path.c_str());
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Its first `max_output` bytes, with a mark where the rest was cut.
  std::string head(size_t max_output) const {
    std::ifstream in(path, std::ios::binary);
    std::string text(max_output, '\0');
    in.read(text.data(), std::streamsize(max_output));
    text.resize(size_t(in.gcount()));
    std::error_code ec;
    if (std::filesystem::file_size(path, ec) > max_output) text += "\n[... output cut ...]\n";
    return text;
  }
};

/// The caller's environment with `extra` NAME=VALUE entries added or replacing.
inline std::vector<std::string> merged_environment(const std::vector<std::string>& extra) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    std::string entry = *e;
    std::string name = entry.substr(0, entry.find('='));
    bool replaced = false;
    for (const std::string& x : extra) replaced = replaced || x.substr(0, x.find('=')) == name;
    if (!replaced) env.push_back(entry);
  }
  env.insert(env.end(), extra.begin(), extra.end());
  return env;
}

/// Why a child never ran, by the step of starting it that failed (1 chdir, 2 limits, 3 group,
/// 4 user, 5 exec, 6 namespaces, 7 seccomp filter).
inline const char* start_step(int step) {
  switch (step) {
    case 1: return "cannot enter the working folder";
    case 2: return "cannot set its limits";
    case 3: return "cannot switch to its group";
    case 4: return "cannot switch to its user (the grader must run as root for that)";
    case 6: return "cannot give it namespaces and empty shared folders of its own";
    case 7: return "cannot install its seccomp filter";
    default: return "cannot run";
  }
}

}  // namespace pt::child_detail
