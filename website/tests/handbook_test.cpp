// The student's handbook (docs/handout): the pages build into a site whose every link works, each
// step of every part has its row in the README and its section on the part's page, and every
// function or type the pages say is in a file is in that file. Run in the instructor's tree and,
// since the test ships with it, in the handout, where the sources hold the stubs.
#include "framework/testing/test_paths.h"
#include "website/src/handbook.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "framework/text/text_file.h"
#include "website/tests/test_folder.h"

namespace fs = std::filesystem;

namespace pt::web {
namespace {

const fs::path kRoot = pt::test::source_dir();
const fs::path kPages = kRoot / "docs" / "handout";

std::string read(const fs::path& p) { return fs::exists(p) ? read_text_file(p) : std::string(); }

/// The text with every run of white space made one space, so a pattern may span a line break.
std::string one_line(std::string s) {
  std::string out;
  bool space = false;
  for (char c : s) {
    const bool ws = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (ws && !space) out += ' ';
    if (!ws) out += c;
    space = ws;
  }
  return out;
}

/// A step of the rubric, as the part's test files name it: parts/N-*/tests/stepK_NAME_test.cpp
/// (or stepK_NAME_exact_test.cpp). The long stress checks are not graded, so they make no step.
struct Step {
  int part = 0, step = 0;
  std::string name;
  std::string id() const {
    return "part" + std::to_string(part) + ".step" + std::to_string(step) + "." + name;
  }
  bool operator<(const Step& o) const { return id() < o.id(); }
};

std::set<Step> steps_from_tests() {
  std::set<Step> steps;
  const std::regex file(R"(step(\d+)_([a-z_]+?)(_exact)?_test\.cpp)");
  for (const fs::directory_entry& part : fs::directory_iterator(kRoot / "parts")) {
    if (!part.is_directory() || !fs::is_directory(part.path() / "tests")) continue;
    const int n = std::stoi(part.path().filename().string());
    for (const fs::directory_entry& t : fs::directory_iterator(part.path() / "tests")) {
      std::smatch m;
      const std::string name = t.path().filename().string();
      if (name.size() > 16 && name.compare(name.size() - 16, 16, "_stress_test.cpp") == 0) continue;
      if (std::regex_match(name, m, file)) steps.insert({n, std::stoi(m[1]), m[2]});
    }
  }
  return steps;
}

std::vector<fs::path> pages() {
  std::vector<fs::path> out;
  for (const fs::directory_entry& e : fs::directory_iterator(kPages))
    if (e.path().extension() == ".md") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(handbook, pages_build_and_every_link_resolves) {
  testing::TestFolder tmp;
  HandbookOptions o;
  o.pages_dir = kPages;
  o.project_root = kRoot;
  o.out_dir = tmp.path() / "handbook";
  o.web_dir = PT_WEBSITE_DIR;
  o.pathtracer = PT_FAKE_PATHTRACER;
  const HandbookReport r = build_handbook(o);
  std::string problems;
  for (const Problem& p : r.problems) problems += p.to_string() + "\n";
  ASSERT_TRUE(r.problems.empty()) << problems;
  // The README and one page per part, each a real page (its title, its sections).
  for (const char* page : {"index.html", "part1.html", "part2.html", "part3.html", "part4.html", "part5.html"}) {
    EXPECT_TRUE(std::find(r.pages.begin(), r.pages.end(), page) != r.pages.end()) << page;
    EXPECT_NE(read(o.out_dir / page).find("<h2>"), std::string::npos) << page;
  }
  // The README links to every part's page and every part's page back to the README.
  const std::string index = read(o.out_dir / "index.html");
  for (int n = 1; n <= 5; ++n)
    EXPECT_NE(index.find("href=\"part" + std::to_string(n) + ".html\""), std::string::npos) << n;
  EXPECT_NE(read(o.out_dir / "part3.html").find("href=\"index.html\""), std::string::npos);
  // Source links point at copies of the project's files (check_folder found each one).
  EXPECT_GT(r.sources.size(), 20u);
  for (const std::string& s : r.sources) {
    EXPECT_TRUE(fs::is_regular_file(o.out_dir / "source" / s)) << s;
    EXPECT_EQ(read(o.out_dir / "source" / s), read(kRoot / s)) << s;
  }
}

TEST(handbook, a_broken_link_is_named_with_its_page_and_line) {
  testing::TestFolder tmp;
  tmp.write("pages/README.md", "# Hand\n\n## A\n\nSee [the code](../no/such_file.cpp).\n");
  HandbookOptions o;
  o.pages_dir = tmp.path() / "pages";
  o.project_root = tmp.path();
  o.out_dir = tmp.path() / "out";
  o.web_dir = PT_WEBSITE_DIR;
  o.pathtracer = PT_FAKE_PATHTRACER;
  const HandbookReport r = build_handbook(o);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_NE(r.problems[0].to_string().find("README.md:5"), std::string::npos) << r.problems[0].to_string();
  EXPECT_NE(r.problems[0].message.find("no/such_file.cpp"), std::string::npos) << r.problems[0].message;
}

TEST(handbook, links_between_pages_and_to_code_are_rewritten_for_the_site) {
  std::set<std::string> sources;
  std::vector<std::string> outside;
  const std::string md =
      "[Part 3](part3.md) [back](README.md#grading) [code](../../parts/3-direct/x.cpp#L3)\n"
      "`[not a link](part3.md)` [web](https://example.org/a.md) [out](../../../elsewhere.md)\n"
      "```\n[in a block](part3.md)\n```\n";
  const std::string out = handbook_markdown(md, "docs/handout", {"README.md", "part3.md"}, &sources, &outside);
  EXPECT_NE(out.find("[Part 3](part3.html)"), std::string::npos) << out;
  EXPECT_NE(out.find("[back](index.html#grading)"), std::string::npos) << out;
  EXPECT_NE(out.find("[code](source/parts/3-direct/x.cpp#L3)"), std::string::npos) << out;
  EXPECT_NE(out.find("`[not a link](part3.md)`"), std::string::npos) << out;
  EXPECT_NE(out.find("[web](https://example.org/a.md)"), std::string::npos) << out;
  EXPECT_NE(out.find("[in a block](part3.md)"), std::string::npos) << out;
  EXPECT_EQ(sources, std::set<std::string>{"parts/3-direct/x.cpp"});
  EXPECT_EQ(outside, std::vector<std::string>{"../../../elsewhere.md"});
}

TEST(handbook, every_step_has_its_row_and_its_section) {
  const std::set<Step> steps = steps_from_tests();
  ASSERT_GE(steps.size(), 15u) << "the parts' step tests were not found";
  const std::string readme = read(kPages / "README.md");
  for (const Step& s : steps) {
    EXPECT_NE(readme.find("`" + s.id() + "`"), std::string::npos)
        << "README.md has no row for " << s.id();
    const std::string page = read(kPages / ("part" + std::to_string(s.part) + ".md"));
    EXPECT_NE(page.find("## Step " + std::to_string(s.step) + ": " + s.name), std::string::npos)
        << "part" << s.part << ".md has no section '## Step " << s.step << ": " << s.name << "'";
  }
  // And no row for a step that does not exist.
  const std::regex row(R"(`part(\d)\.step(\d+)\.([a-z_]+)`)");
  for (std::sregex_iterator it(readme.begin(), readme.end(), row), end; it != end; ++it) {
    const Step s{std::stoi((*it)[1]), std::stoi((*it)[2]), (*it)[3]};
    EXPECT_TRUE(steps.count(s)) << "README.md names " << s.id() << ", which no test file makes";
  }
}

/// The manifest is the one rubric: each of its steps has its README row, and the row names each
/// of the step's functions with a link to the file the manifest gives for it.
TEST(handbook, every_manifest_step_row_names_its_functions_at_their_files) {
  const nlohmann::json manifest = nlohmann::json::parse(read(kRoot / "reference" / "manifest.json"));
  const std::string readme = one_line(read(kPages / "README.md"));
  int functions = 0;
  for (const nlohmann::json& part : manifest.at("parts")) {
    const int n = part.at("part");
    if (!part.contains("steps")) GTEST_SKIP() << "the manifest has no steps yet";
    int k = 0;
    for (const nlohmann::json& step : part.at("steps")) {
      const std::string id = "part" + std::to_string(n) + ".step" + std::to_string(++k) + "." +
                             step.at("name").get<std::string>();
      const size_t at = readme.find("- `" + id + "`");
      ASSERT_NE(at, std::string::npos) << "README.md has no row for " << id;
      const size_t next = readme.find(" - `part", at + 3);
      const std::string row = readme.substr(at, next == std::string::npos ? std::string::npos : next - at);
      for (const nlohmann::json& f : step.value("functions", nlohmann::json::array())) {
        const std::string entry = f.get<std::string>();  // "parts/3-direct/x.cpp: name"
        const size_t colon = entry.find(": ");
        ASSERT_NE(colon, std::string::npos) << entry;
        const std::string file = entry.substr(0, colon), name = entry.substr(colon + 2);
        EXPECT_NE(row.find("`" + name + "`"), std::string::npos) << id << "'s row does not name " << name;
        EXPECT_NE(row.find("[`" + file + "`](../../" + file + ")"), std::string::npos)
            << id << "'s row does not link " << file;
        ++functions;
      }
    }
  }
  EXPECT_GE(functions, 20);
}

/// `f` and `g` in [`path`](...): each function is defined or declared in that file ("f(").
/// `Type` ([`path`](...)): the name is in that file as a word.
TEST(handbook, every_code_reference_names_a_file_that_holds_it) {
  const std::regex functions(R"(((?:`[A-Za-z_][\w:]*`(?:, | and | or )?)+) in \[`([^`]+)`\]\()");
  const std::regex types(R"(`([A-Za-z_][\w:]*)` \(\[`([^`]+)`\]\()");
  const std::regex name(R"(`([A-Za-z_][\w:]*)`)");
  int checked = 0;
  for (const fs::path& page : pages()) {
    const std::string text = one_line(read(page));
    auto check = [&](const std::string& names, const std::string& file, bool call) {
      const std::string code = read(kRoot / file);
      ASSERT_FALSE(code.empty()) << page.filename() << ": " << file << " is not in the project";
      for (std::sregex_iterator n(names.begin(), names.end(), name), end; n != end; ++n) {
        const std::string id = (*n)[1];
        const std::string last = id.substr(id.rfind(':') == std::string::npos ? 0 : id.rfind(':') + 1);
        const bool found = call ? (code.find(id + "(") != std::string::npos ||
                                   code.find(" " + last + "(") != std::string::npos)
                                : std::regex_search(code, std::regex("\\b" + last + "\\b"));
        EXPECT_TRUE(found) << page.filename() << " says `" << id << "` is in " << file;
        ++checked;
      }
    };
    for (std::sregex_iterator m(text.begin(), text.end(), functions), end; m != end; ++m)
      check((*m)[1], (*m)[2], true);
    for (std::sregex_iterator m(text.begin(), text.end(), types), end; m != end; ++m)
      check("`" + (*m)[1].str() + "`", (*m)[2], false);
  }
  EXPECT_GE(checked, 60) << "the pages' code references were not found";
}

/// The function's file opens by naming its step, so a student who opens it sees where it
/// belongs: each part file a step row links to names the step in its first lines.
TEST(handbook, each_step_row_links_files_that_name_the_step) {
  const std::string readme = one_line(read(kPages / "README.md"));
  const std::regex row(R"(- `part(\d)\.step(\d+)\.([a-z_]+)`:(.*?)(?= - `part|###|$))");
  const std::regex link(R"(\]\(\.\./\.\./(parts/[^)]+)\))");
  int rows = 0;
  for (std::sregex_iterator it(readme.begin(), readme.end(), row), end; it != end; ++it) {
    const std::string body = (*it)[4], step = (*it)[3];
    for (std::sregex_iterator l(body.begin(), body.end(), link), e; l != e; ++l) {
      const std::string file = (*l)[1];
      const std::string head = read(kRoot / file).substr(0, 400);
      EXPECT_NE(head.find("(" + step + ")"), std::string::npos)
          << file << " does not name step " << step << " in its first lines:\n" << head;
      ++rows;
    }
  }
  EXPECT_GE(rows, 15);
}

TEST(handbook, pages_say_nothing_of_the_instructors_tree) {
  for (const fs::path& page : pages()) {
    const std::string text = read(page);
    for (const char* word : {"BEGIN SOLUTION", "END SOLUTION", "SOLUTION-ONLY", "--make-reference",
                             "mutants", "PT_SOLUTION_DIR"})
      EXPECT_EQ(text.find(word), std::string::npos) << page.filename() << " mentions " << word;
  }
}

}  // namespace
}  // namespace pt::web
