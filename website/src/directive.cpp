#include "website/src/directive.h"

#include <algorithm>
#include <cctype>

namespace pt::web {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

/// Reads one word, with '"' or '\'' quoting and backslash escapes inside double quotes.
std::string read_word(const std::string& s, size_t& i, const std::string& context) {
  std::string word;
  while (i < s.size() && !is_space(s[i])) {
    char c = s[i];
    if (c == '"' || c == '\'') {
      size_t close = i + 1;
      std::string quoted;
      while (close < s.size() && s[close] != c) {
        if (c == '"' && s[close] == '\\' && close + 1 < s.size()) ++close;
        quoted += s[close++];
      }
      if (close >= s.size()) {
        throw DirectiveError("unclosed " + std::string(1, c) + " quote in " + context);
      }
      word += quoted;
      i = close + 1;
    } else {
      word += c;
      ++i;
    }
  }
  return word;
}

}  // namespace

std::string Directive::get(const std::string& key, const std::string& fallback) const {
  auto it = attributes.find(key);
  return it == attributes.end() ? fallback : it->second;
}

Directive parse_directive(const std::string& text, bool has_name) {
  Directive d;
  size_t i = 0;
  auto skip = [&] {
    while (i < text.size() && is_space(text[i])) ++i;
  };
  skip();
  if (has_name) {
    while (i < text.size() && !is_space(text[i])) d.name += text[i++];
  }
  const std::string context = "'" + text + "'";
  for (skip(); i < text.size(); skip()) {
    size_t eq = text.find('=', i);
    size_t space = i;
    while (space < text.size() && !is_space(text[space])) ++space;
    if (eq == std::string::npos || eq > space) {
      throw DirectiveError("expected key=value, found '" + text.substr(i, space - i) + "' in " +
                           context);
    }
    std::string key = text.substr(i, eq - i);
    i = eq + 1;
    std::string value = read_word(text, i, context);
    if (d.attributes.count(key)) throw DirectiveError("'" + key + "' given twice in " + context);
    d.attributes[key] = value;
  }
  return d;
}

std::vector<std::string> split_flags(const std::string& flags) {
  std::vector<std::string> out;
  size_t i = 0;
  while (true) {
    while (i < flags.size() && is_space(flags[i])) ++i;
    if (i >= flags.size()) break;
    out.push_back(read_word(flags, i, "flags \"" + flags + "\""));
  }
  return out;
}

namespace {

/// An option with the values after it; "-5" or "-0.5" is a value, "-s" an option.
using Group = std::vector<std::string>;

std::vector<Group> groups(const std::string& flags) {
  std::vector<Group> out;
  for (const std::string& word : split_flags(flags)) {
    bool option = word.size() > 1 && word[0] == '-' &&
                  !std::isdigit(static_cast<unsigned char>(word[1])) && word[1] != '.';
    if (option || out.empty()) out.push_back({});
    out.back().push_back(word);
  }
  return out;
}

std::string join(const std::vector<Group>& merged) {
  std::string out;
  for (const Group& g : merged) {
    for (const std::string& w : g) {
      bool quote = w.find_first_of(" \t\"'") != std::string::npos || w.empty();
      out += (out.empty() ? "" : " ") + (quote ? "'" + w + "'" : w);
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> flag_values(const std::string& flags, const std::vector<std::string>& names) {
  std::vector<std::string> values;
  for (const Group& g : groups(flags)) {
    if (std::find(names.begin(), names.end(), g.front()) != names.end()) {
      values.assign(g.begin() + 1, g.end());
    }
  }
  return values;
}

std::string halve_resolution(const std::string& flags) {
  std::vector<Group> all = groups(flags);
  for (Group& g : all) {
    if ((g.front() == "-r" || g.front() == "--resolution") && g.size() == 3) {
      for (size_t i = 1; i < 3; ++i) {
        try {
          g[i] = std::to_string(std::max(1, std::stoi(g[i]) / 2));
        } catch (const std::exception&) {
          // not a number: leave it for the pathtracer to refuse with its own message
        }
      }
    }
  }
  return join(all);
}

std::string merge_flags(const std::string& base, const std::string& extra) {
  std::vector<Group> merged = groups(base);
  for (const Group& g : groups(extra)) {
    auto same = [&](const Group& m) { return m.front() == g.front(); };
    auto it = std::find_if(merged.begin(), merged.end(), same);
    if (it != merged.end()) *it = g;
    else merged.push_back(g);
  }
  return join(merged);
}

}  // namespace pt::web
