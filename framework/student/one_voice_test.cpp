// Not needed for the assignment.
// Each step's rules said in one voice: the manifest (reference/manifest.json, which `grader
// rules` prints) states them; the step's STUDENT comments and its section of the part page
// (docs/handout/partN.md) name every call and setting the rules name, and the header's contract
// names no call that those two do not. Copies that drift (a header telling the hemisphere
// estimator to use one call, its STUDENT comment another) fail here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/testing/test_paths.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

std::string read(const std::string& relative) {
  std::ifstream in(std::string(test::source_dir()) + "/" + relative);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The code names a text uses: identifiers with an underscore (spawn_shadow_ray, light_samples)
/// and the last part of a member path (ctx.lights.radiance_along: radiance_along; ctx.lights:
/// lights), that last part when it is longer than two letters (not wi.z).
std::set<std::string> code_names(const std::string& text) {
  static const std::regex name(R"([A-Za-z_]\w*(?:(?:\.|->|::)[A-Za-z_]\w*)*)");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != std::sregex_iterator();
       ++it) {
    const std::string whole = it->str();
    const size_t cut = whole.find_last_of(".>:");
    const std::string last = cut == std::string::npos ? whole : whole.substr(cut + 1);
    const bool path = cut != std::string::npos;
    if (last.find('_') != std::string::npos || (path && last.size() > 2)) names.insert(last);
  }
  return names;
}

/// Every identifier of a text, each part of a member path on its own.
std::set<std::string> words(const std::string& text) {
  static const std::regex word(R"([A-Za-z_]\w*)");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator();
       ++it)
    out.insert(it->str());
  return out;
}

/// A step's section of its part page: from "## Step K: NAME" to the next "## ".
std::string page_section(const std::string& page, int step, const std::string& name) {
  const std::string head = "## Step " + std::to_string(step) + ": " + name;
  const size_t from = page.find(head);
  if (from == std::string::npos) return "";
  const size_t to = page.find("\n## ", from + head.size());
  return page.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

/// The `// STUDENT:` comment of function `function` (as the manifest names it, e.g.
/// DiffuseBsdf::f) in `source`: the comment lines from "// STUDENT:" after its definition.
std::string student_comment(const std::string& source, const std::string& function) {
  const std::vector<std::string> lines = lines_of(source);
  const std::regex definition("(^|[\\s&*])" + std::regex_replace(function, std::regex(":"), "\\:") +
                              "\\(");
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i][0] == ' ' || lines[i][0] == '/' ||
        !std::regex_search(lines[i], definition))
      continue;
    std::string comment;
    for (size_t j = i + 1; j < lines.size() && lines[j].rfind("}", 0) != 0; ++j) {
      const size_t at = lines[j].find("// STUDENT:");
      if (at == std::string::npos && comment.empty()) continue;
      const size_t slashes = lines[j].find("//");
      if (slashes == std::string::npos) break;
      comment += lines[j].substr(slashes + 2) + "\n";
    }
    return comment;
  }
  return "";
}

/// The `///` contracts above the declarations that say they are step K (NAME), in `header`.
std::string header_contract(const std::string& header, int step, const std::string& name) {
  const std::vector<std::string> lines = lines_of(header);
  const std::string mark = std::to_string(step) + " (" + name + ")";
  // A member's contract is indented (Bvh::traverse_nearest's): compare from the first non-blank.
  auto text_of = [&](size_t i) {
    const size_t at = lines[i].find_first_not_of(' ');
    return at == std::string::npos ? std::string() : lines[i].substr(at);
  };
  // Every block so marked: a step of two functions may give each its own (Bvh's two walks).
  std::string contract;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (text_of(i).rfind("/// Step", 0) != 0 || lines[i].find(mark) == std::string::npos) continue;
    for (size_t j = i; j < lines.size() && text_of(j).rfind("///", 0) == 0; ++j)
      contract += text_of(j).substr(3) + "\n";
  }
  return contract;
}

std::string joined(const std::set<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

struct StepText {
  std::string where;  // partN.stepK.NAME
  std::string rules, student, page, header;
};

/// Every step of parts `from`..`to` with its rules and the three texts that state them.
std::vector<StepText> steps_of_parts(int from, int to) {
  const nlohmann::json manifest = nlohmann::json::parse(read("reference/manifest.json"));
  std::vector<StepText> out;
  for (const auto& part : manifest.at("parts")) {
    const int n = part.at("part").get<int>();
    if (n < from || n > to) continue;
    const std::string page = read("docs/handout/part" + std::to_string(n) + ".md");
    for (const auto& step : part.at("steps")) {
      StepText t;
      const int k = step.at("step").get<int>();
      const std::string name = step.at("name").get<std::string>();
      t.where = "part" + std::to_string(n) + ".step" + std::to_string(k) + "." + name;
      for (const auto& rule : step.at("rules")) t.rules += rule.at("rule").get<std::string>() + "\n";
      t.page = page_section(page, k, name);
      std::set<std::string> folders;
      for (const auto& f : step.at("functions")) {
        const std::string entry = f.get<std::string>();  // "parts/3-direct/x.cpp: function"
        const size_t colon = entry.find(": ");
        const std::string file = entry.substr(0, colon), function = entry.substr(colon + 2);
        t.student += student_comment(read(file), function);
        folders.insert(file.substr(0, file.rfind('/')));
      }
      // The step's contract stands in one of its part's headers (Bvh::traverse_nearest's in bvh.h,
      // not beside bvh_traverse.cpp), marked "/// Step K (NAME)".
      for (const std::string& folder : folders)
        for (const auto& e : fs::directory_iterator(fs::path(test::source_dir()) / folder))
          if (e.path().extension() == ".h")
            t.header += header_contract(read(folder + "/" + e.path().filename().string()), k, name);
      out.push_back(t);
    }
  }
  return out;
}

// Every part: each step's rules are said the same way in its three texts.
constexpr int kFirstPart = 1, kLastPart = 5;

TEST(FrameworkStudentText, EveryStepHasItsThreeTexts) {
  const std::vector<StepText> steps = steps_of_parts(kFirstPart, kLastPart);
  ASSERT_FALSE(steps.empty()) << "no step of parts " << kFirstPart << "-" << kLastPart
                              << " in reference/manifest.json";
  for (const StepText& t : steps) {
    EXPECT_FALSE(t.rules.empty()) << t.where << ": the manifest states no rule";
    EXPECT_FALSE(t.student.empty()) << t.where << ": no // STUDENT: comment found";
    EXPECT_FALSE(t.page.empty()) << t.where << ": no '## Step' section on the part page";
    EXPECT_FALSE(t.header.empty()) << t.where << ": no '/// Step' contract in the header";
  }
}

TEST(FrameworkStudentText, StudentCommentAndPageNameEveryCallTheRulesName) {
  for (const StepText& t : steps_of_parts(kFirstPart, kLastPart)) {
    const std::set<std::string> student = code_names(t.student), page = code_names(t.page);
    std::set<std::string> not_in_student, not_on_page;
    for (const std::string& name : code_names(t.rules)) {
      if (!student.count(name)) not_in_student.insert(name);
      if (!page.count(name)) not_on_page.insert(name);
    }
    EXPECT_TRUE(not_in_student.empty())
        << t.where << ": the manifest's rules name " << joined(not_in_student)
        << ", its STUDENT comment does not";
    EXPECT_TRUE(not_on_page.empty()) << t.where << ": the manifest's rules name "
                                     << joined(not_on_page) << ", its part page does not";
  }
}

TEST(FrameworkStudentText, TheHeaderNamesNoCallTheOthersDoNot) {
  for (const StepText& t : steps_of_parts(kFirstPart, kLastPart)) {
    // Against every word of the others: a header's ray.tmin is the rules' plain "tmin".
    const std::set<std::string> elsewhere = words(t.student + t.page + t.rules);
    std::set<std::string> only_in_header;
    for (const std::string& name : code_names(t.header))
      if (!elsewhere.count(name)) only_in_header.insert(name);
    EXPECT_TRUE(only_in_header.empty())
        << t.where << ": its header's contract names " << joined(only_in_header)
        << ", which neither the manifest's rules, its STUDENT comment nor its part page name";
  }
}

// The check itself: the drift this test was made for is caught.
TEST(FrameworkStudentText, CodeNamesFindsTheCallsOfAContract) {
  const std::set<std::string> names =
      code_names("its ray's zero_bounce_radiance, ctx.lights.radiance_along, wi.z, ctx.lights");
  EXPECT_EQ(names, (std::set<std::string>{"zero_bounce_radiance", "radiance_along", "lights"}));
}

}  // namespace
}  // namespace pt
