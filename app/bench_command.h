// One of bench's subcommands (`bench rays`, `render`, `convergence`, `agreement`, `layers`): the
// subcommand added to bench's command line with its options, and what runs when it is chosen.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace pt {

/// A subcommand of bench. Its options are bound to state the `run` function holds, so the
/// command line fills them in when it is parsed; `run` then returns the exit code (0 done,
/// 1 the study found something wrong or could not read its input, 2 options it cannot honour).
struct BenchCommand {
  CLI::App* command = nullptr;
  std::function<int()> run;
};

}  // namespace pt
