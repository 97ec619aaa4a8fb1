// Not needed for the assignment.
// A fresh folder in the temp directory for one test, removed when the test ends: the one every
// test that writes files uses.
#pragma once

#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace pt::test {

/// A new folder (mode 0755) named `prefix` plus a unique suffix, deleted with all it holds when
/// the object goes.
class TempFolder {
 public:
  explicit TempFolder(const std::string& prefix = "pt-test") {
    std::string tmpl = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (!mkdtemp(tmpl.data())) std::abort();  // no temp directory: no test can run
    root_ = tmpl;
    std::filesystem::permissions(root_, std::filesystem::perms(0755));
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return root_; }

  /// Writes `text` to the file `rel` inside (folders made as needed, mode 0644); returns its path.
  std::filesystem::path write(const std::string& rel, const std::string& text) const {
    std::filesystem::path p = root_ / rel;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    std::filesystem::permissions(p, std::filesystem::perms(0644));
    return p;
  }

 private:
  std::filesystem::path root_;
};

}  // namespace pt::test
