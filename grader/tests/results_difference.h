// How much of a results file the student chose, measured: grade two submissions that are the
// same but for a payload, and count the characters in which their results differ. Whatever
// differs was decided by the payload (or by chance: the time taken, a scene's variant), so the
// count is at least what the payload carried into the results (docs/grading.md, the bound).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pt::grader::testing {

/// The characters of `a` and `b` outside their longest common subsequence, the larger side:
/// what one must be told, at least, to make one text from the other.
inline size_t differing_characters(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1, 0), next(b.size() + 1, 0);
  for (size_t i = 0; i < a.size(); ++i) {
    for (size_t j = 0; j < b.size(); ++j)
      next[j + 1] = a[i] == b[j] ? row[j] + 1 : std::max(row[j + 1], next[j]);
    std::swap(row, next);
  }
  return std::max(a.size(), b.size()) - row[b.size()];
}

/// The differing characters of two results, field by field: a field or an element only one
/// of them has counts whole, two strings (or two numbers, as JSON writes them) count what
/// differing_characters says.
inline size_t differing_characters(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_object() && b.is_object()) {
    size_t n = 0;
    for (auto it = a.begin(); it != a.end(); ++it)
      n += b.contains(it.key()) ? differing_characters(it.value(), b[it.key()])
                                : it.key().size() + it.value().dump().size();
    for (auto it = b.begin(); it != b.end(); ++it)
      if (!a.contains(it.key())) n += it.key().size() + it.value().dump().size();
    return n;
  }
  if (a.is_array() && b.is_array()) {
    size_t n = 0;
    for (size_t i = 0; i < std::max(a.size(), b.size()); ++i)
      n += i >= a.size()   ? b[i].dump().size()
           : i >= b.size() ? a[i].dump().size()
                           : differing_characters(a[i], b[i]);
    return n;
  }
  const std::string sa = a.is_string() ? a.get<std::string>() : a.dump();
  const std::string sb = b.is_string() ? b.get<std::string>() : b.dump();
  return differing_characters(sa, sb);
}

}  // namespace pt::grader::testing
