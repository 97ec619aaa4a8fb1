// Parsing a command line with CLI11 the way every program here does: --help prints the options
// and succeeds, a bad flag says what is wrong and how to see the options, and exits 2.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <ostream>
#include <string>

namespace pt {

/// Parses `argv` into `app`. Returns nothing when the program goes on, or the exit code it ends
/// with: 0 after printing --help to `out`, 2 after naming the error to `err` as
/// "PROGRAM: what\n" followed by `hint` (e.g. "Run with --help for the options.").
inline std::optional<int> parse_or_exit(CLI::App& app, int argc, char** argv,
                                        const std::string& program, const std::string& hint,
                                        std::ostream& out, std::ostream& err) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    err << program << ": " << e.what() << "\n" << hint << "\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace pt
