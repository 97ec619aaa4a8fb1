// The write-up's directives: fenced blocks whose info string names one (```render, ```grid,
// ```plot) followed by key=value attributes, values quoted when they hold spaces.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace pt::web {

/// A directive's name and attributes, e.g. render scene=a.dae flags="-s 64" caption="64 spp".
struct Directive {
  std::string name;
  std::map<std::string, std::string> attributes;
  /// The attribute, or `fallback` when it was not given.
  std::string get(const std::string& key, const std::string& fallback = "") const;
};

/// A directive that cannot be read; the message says what is wrong with it.
class DirectiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads "name key=value key="value with spaces"" (also used for one line of a grid).
/// When `has_name` is false the text holds attributes only.
Directive parse_directive(const std::string& text, bool has_name = true);

/// Splits a command-line string into arguments the way a shell would for plain quoting
/// ("-s 64 -r 160 120" -> {"-s","64","-r","160","120"}); no variables, no globbing.
std::vector<std::string> split_flags(const std::string& flags);

/// The flags of `base` with those of `extra` laid over them: an option `extra` names again
/// ("-r 64 48" over "-r 160 120") replaces the base's, since a command line may not repeat it.
std::string merge_flags(const std::string& base, const std::string& extra);

/// The values after the last of `names` in `flags` ("-s" or "--samples"), or none when absent.
std::vector<std::string> flag_values(const std::string& flags, const std::vector<std::string>& names);

/// The flags with every "-r W H" (or --resolution) halved, at least 1 each: a draft of the same
/// picture at a quarter of the pixels, whose samples, depths and captions all stay true.
std::string halve_resolution(const std::string& flags);

}  // namespace pt::web
