// Not needed for the assignment.
// Which files a student opens: the part pages (docs/handout/partN.md, "The files you open") list
// them step by step; every other source of framework/ and pipeline/ opens with "Not needed for
// the assignment", and a listed one does not; the headers a part's own sources include are
// listed, so a student never has to open a marked file to know what they call.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "framework/testing/test_paths.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

const std::string kMark = "// Not needed for the assignment";

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path root() { return fs::path(test::source_dir()); }

/// The files the part pages list under "## The files you open", relative to the project.
std::set<std::string> listed_files() {
  std::set<std::string> files;
  static const std::regex link(R"(\]\(\.\./\.\./([^)#]+)\))");
  for (int part = 1; part <= 5; ++part) {
    const std::string page = read(root() / "docs/handout" / ("part" + std::to_string(part) + ".md"));
    const size_t from = page.find("## The files you open");
    EXPECT_NE(from, std::string::npos) << "part" << part << ".md: no 'The files you open' section";
    if (from == std::string::npos) continue;
    const size_t to = page.find("\n## ", from + 1);
    const std::string section = page.substr(from, to == std::string::npos ? to : to - from);
    for (auto it = std::sregex_iterator(section.begin(), section.end(), link);
         it != std::sregex_iterator(); ++it)
      files.insert((*it)[1].str());
  }
  return files;
}

bool is_source(const fs::path& p) { return p.extension() == ".h" || p.extension() == ".cpp"; }

TEST(FrameworkStudentFiles, EveryListedFileExists) {
  for (const std::string& f : listed_files())
    EXPECT_TRUE(fs::is_regular_file(root() / f)) << f << ": listed on a part page, not found";
}

TEST(FrameworkStudentFiles, EveryUnlistedFileIsMarkedAndNoListedOneIs) {
  const std::set<std::string> listed = listed_files();
  int sources = 0;
  for (const char* layer : {"framework", "pipeline"}) {
    for (const auto& e : fs::recursive_directory_iterator(root() / layer)) {
      if (!e.is_regular_file() || !is_source(e.path())) continue;
      ++sources;
      const std::string relative = fs::relative(e.path(), root()).generic_string();
      const bool marked = read(e.path()).rfind(kMark, 0) == 0;
      if (listed.count(relative))
        EXPECT_FALSE(marked) << relative << ": a part page lists it, yet it says it is not needed";
      else
        EXPECT_TRUE(marked) << relative << ": no part page lists it, and its first line is not '"
                            << kMark << "'";
    }
  }
  EXPECT_GT(sources, 100) << "the framework's and pipeline's sources were not found under "
                          << root();
}

TEST(FrameworkStudentFiles, WhatAPartIncludesIsListed) {
  const std::set<std::string> listed = listed_files();
  static const std::regex include("#include \"((framework|pipeline)/[^\"]+)\"");
  for (const auto& e : fs::recursive_directory_iterator(root() / "parts")) {
    const std::string relative = fs::relative(e.path(), root()).generic_string();
    if (!e.is_regular_file() || !is_source(e.path()) ||
        relative.find("/tests/") != std::string::npos)
      continue;
    const std::string text = read(e.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), include);
         it != std::sregex_iterator(); ++it) {
      const std::string header = (*it)[1].str();
      // The stub macro's folder: the stubs call it, and go with it.
      if (header.rfind("framework/student/", 0) == 0) continue;
      EXPECT_TRUE(listed.count(header))
          << relative << " includes " << header << ", which no part page lists";
    }
  }
}

}  // namespace
}  // namespace pt
