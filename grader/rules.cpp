#include "grader/rules.h"

#include <map>
#include <sstream>

#include "grader/process/child_process.h"

namespace pt::grader {

bool check_names(const std::string& check, const std::string& name) {
  return name == check || (name.size() > check.size() && name.compare(0, check.size(), check) == 0 &&
                           name[check.size()] == '/');
}

std::vector<const Rule*> rules_enforced_by(const StepSpec& step, const std::string& name) {
  std::vector<const Rule*> rules;
  for (const Rule& r : step.rules)
    for (const std::string& c : r.checks)
      if (check_names(c, name)) {
        rules.push_back(&r);
        break;
      }
  return rules;
}

std::set<std::string> listed_tests(const std::string& build_dir) {
  ChildResult c = run_child({"ctest", "--test-dir", build_dir, "-N"}, 300.0);
  if (!c.ok()) throw std::runtime_error("ctest cannot list the tests of " + build_dir + " (" + c.describe() + ")");
  std::set<std::string> names;
  std::istringstream in(c.output);
  for (std::string line; std::getline(in, line);) {
    // "  Test  #35: name": ctest pads the number, so the spaces before '#' vary.
    const size_t test = line.find("Test ");
    if (test == std::string::npos) continue;
    const size_t hash = line.find_first_not_of(' ', test + 4);
    const size_t colon = line.find(": ", hash);
    if (hash == std::string::npos || line[hash] != '#' || colon == std::string::npos) continue;
    std::string name = line.substr(colon + 2);
    name = name.substr(0, name.find(' '));  // a parameterised test's "  # GetParam() = ..."
    names.insert(name);
  }
  return names;
}

std::vector<std::string> rule_problems(const Manifest& manifest,
                                       const std::vector<MutantSpec>* mutants,
                                       const std::set<std::string>& tests) {
  std::vector<std::string> problems;
  std::map<std::string, const MutantSpec*> catalogue;
  std::set<std::string> named;
  if (mutants)
    for (const MutantSpec& m : *mutants) catalogue[m.name] = &m;
  for (const PartSpec& part : manifest.parts)
    for (const StepSpec& step : part.steps) {
      const std::string sn = step.full_name();
      if (step.rules.empty()) problems.push_back(sn + ": states no rule");
      for (const Rule& rule : step.rules) {
        const std::string rn = rule.full_name(sn);
        if (rule.checks.empty()) problems.push_back(rn + ": no check enforces it");
        for (const std::string& c : rule.checks) {
          if (c.rfind(step.test_prefix(), 0) != 0) {
            problems.push_back(rn + ": the check " + c + " is not one of " + sn + "'s");
            continue;
          }
          bool found = false;
          for (const RenderCheck& r : step.renders) found = found || r.name == c;
          for (const RenderCheck& r : step.other_rule_renders) found = found || r.name == c;
          for (auto it = tests.lower_bound(c); !found && it != tests.end() && it->rfind(c, 0) == 0; ++it)
            found = check_names(c, *it);
          if (!found) problems.push_back(rn + ": the check " + c + " is no test or render of this build");
        }
        if (!mutants) continue;
        if (rule.mutants.empty()) problems.push_back(rn + ": no catalogued bug breaks it alone");
        for (const std::string& m : rule.mutants) {
          named.insert(m);
          auto it = catalogue.find(m);
          if (it == catalogue.end())
            problems.push_back(rn + ": the mutant " + m + " is not in the catalogue");
          else if (it->second->step != sn)
            problems.push_back(rn + ": the mutant " + m + " must lose points in " +
                               it->second->step + ", not in this rule's step");
        }
      }
    }
  for (const auto& [name, m] : catalogue)
    if (!named.count(name)) problems.push_back("the mutant " + name + " breaks no rule of the manifest");
  return problems;
}

void print_rules(std::ostream& out, const Manifest& manifest,
                 const std::vector<MutantSpec>* mutants) {
  size_t rules = 0;
  for (const PartSpec& part : manifest.parts)
    for (const StepSpec& step : part.steps) {
      out << "\n" << step.full_name() << " (" << step.points << " points): " << step.title << "\n";
      for (const Rule& rule : step.rules) {
        ++rules;
        out << "  #" << rule.id << "  " << rule.text << "\n";
        for (const std::string& c : rule.checks) out << "      check   " << c << "\n";
        if (mutants)
          for (const std::string& m : rule.mutants) out << "      mutant  " << m << "\n";
      }
    }
  out << "\n" << rules << " rules\n";
}

}  // namespace pt::grader
