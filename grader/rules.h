// The rules each step states, each enforced: the manifest's rule list printed, the rule a failing
// check enforces, and what keeps the list from being complete (a rule with no check that exists,
// or no catalogued bug that breaks it alone).
#pragma once

#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "grader/manifest.h"
#include "grader/mutants.h"

namespace pt::grader {

/// Whether the check `check` (a rule's entry) names the test or render `name`: the same name, or
/// a parameterised test's instance of it (`name` + "/...").
bool check_names(const std::string& check, const std::string& name);

/// The rules of `step` that the check `name` enforces.
std::vector<const Rule*> rules_enforced_by(const StepSpec& step, const std::string& name);

/// The names of the tests a build has (its `ctest -N` list); throws std::runtime_error naming the
/// build when ctest cannot list them.
std::set<std::string> listed_tests(const std::string& build_dir);

/// Why the rule list is not complete, one line each: a step with no rule, a rule with no check,
/// a check that names no test of `tests` nor a render of its step, a rule with no mutant, a
/// mutant the catalogue does not have or of another step, a catalogued mutant no rule names.
/// With `mutants` null (a handout has no catalogue), the mutants are not asked for.
std::vector<std::string> rule_problems(const Manifest& manifest,
                                       const std::vector<MutantSpec>* mutants,
                                       const std::set<std::string>& tests);

/// Every step's rules with their checks (and mutants, when given), as `grader rules` prints them.
void print_rules(std::ostream& out, const Manifest& manifest,
                 const std::vector<MutantSpec>* mutants);

}  // namespace pt::grader
