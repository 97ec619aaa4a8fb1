#include "grader/student_values.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

namespace pt::grader {
namespace {

// A marked value is kOpen, its bounded text, kClose: two control characters no message of the
// grader's holds, removed from whatever text comes in before anything is marked.
constexpr char kOpen = '\x1f';
constexpr char kClose = '\x1e';
const char* const kHidden = "\xe2\x80\xa6";  // …

/// A number printed again in at most kValueChars characters.
std::string bounded_number(const std::string& token) {
  char buf[64];
  if (token.size() > 2 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X')) {
    const unsigned long long v = std::strtoull(token.c_str(), nullptr, 16);
    std::snprintf(buf, sizeof buf, "%.*g", kValueDigits - 1, double(v));
    return buf;
  }
  const double v = std::strtod(token.c_str(), nullptr);
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e6)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.*g", kValueDigits, v);
  return buf;
}

/// The length of the number that starts at `at` (an optional sign, digits with a point and an
/// exponent, or 0x and hex digits), or 0.
size_t number_at(const std::string& s, size_t at) {
  size_t i = at;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  if (i + 2 < s.size() && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X') &&
      std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
    i += 2;
    while (i < s.size() && std::isxdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i - at;
  }
  const size_t digits_from = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  bool any = i > digits_from;
  if (i < s.size() && s[i] == '.' && i + 1 < s.size() &&
      std::isdigit(static_cast<unsigned char>(s[i + 1]))) {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    any = true;
  }
  if (!any) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    size_t j = i + 1;
    if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
    if (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) {
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      i = j;
    }
  }
  return i - at;
}

/// Whether the number at `at` ends the name of a test's source file and its line: "x_test.cpp:45".
bool source_position(const std::string& s, size_t at) {
  for (const char* ext : {".cpp:", ".h:", ".cc:"}) {
    const size_t n = std::char_traits<char>::length(ext);
    if (at >= n && s.compare(at - n, n, ext) == 0) return true;
  }
  return false;
}

}  // namespace

std::string mark_values(const std::string& text) {
  std::string s;
  for (char c : text)
    if (c != kOpen && c != kClose) s += c;
  // What GoogleTest prints of a value it has no printer for (its bytes), and of a character (the
  // character itself beside its code, which is marked as a number below).
  static const std::regex bytes("([0-9]+-byte object) <[^>]*>");
  static const std::regex character("'(\\\\.|[^'\\\\])+' \\(");
  s = std::regex_replace(s, bytes, std::string("$1 <") + kHidden + ">");
  s = std::regex_replace(s, character, std::string("'") + kHidden + "' (");
  // A word (a letter or '_', then letters, digits and '_') is the grader's; every other run of
  // digits is a number, with the sign before it and its point and exponent.
  std::string out;
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isalpha(c) || c == '_') {
      size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      out.append(s, i, j - i);
      i = j;
      continue;
    }
    const bool after_word = i > 0 && (std::isalnum(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '_');
    const bool sign = (c == '-' || c == '+') && !after_word;
    const size_t n = (sign || std::isdigit(c) || c == '.') ? number_at(s, i) : 0;
    if (n == 0) {
      out += s[i++];
      continue;
    }
    // A number of one or two digits glued to a word after it is that word's ("1-raygen", "3D").
    const bool glued = n <= 2 && std::isdigit(c) &&
                       std::all_of(s.begin() + long(i), s.begin() + long(i + n),
                                   [](char d) { return std::isdigit(static_cast<unsigned char>(d)); }) &&
                       i + n < s.size() &&
                       (std::isalpha(static_cast<unsigned char>(s[i + n])) || s[i + n] == '_' ||
                        (s[i + n] == '-' && i + n + 1 < s.size() &&
                         std::isalpha(static_cast<unsigned char>(s[i + n + 1]))));
    if (glued || source_position(s, i)) {
      out.append(s, i, n);
      i += n;
      continue;
    }
    out += kOpen;
    out += bounded_number(s.substr(i, n));
    out += kClose;
    i += n;
  }
  return out;
}

std::string release_values(const std::string& text, int* left, int per_text) {
  std::string out;
  int shown = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != kOpen) {
      if (text[i] != kClose) out += text[i];
      continue;
    }
    const size_t end = text.find(kClose, i);
    const std::string value = text.substr(i + 1, (end == std::string::npos ? text.size() : end) - i - 1);
    if (!left || (*left > 0 && shown < per_text)) {
      out += value;
      ++shown;
      if (left) --*left;
    } else {
      out += kHidden;
    }
    if (end == std::string::npos) break;
    i = end;
  }
  return out;
}

int marked_values(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == kOpen ? 1 : 0;
  return n;
}

}  // namespace pt::grader
