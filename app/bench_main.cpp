// bench: the project's measurements, one subcommand each: `rays` (BVH build and rays per second,
// beside Embree), `render` (the speed report), `convergence` (error against time), `agreement`
// (do the sampling strategies render one image?) and `layers` (does the fast layer change a bit?).
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_parse.h"
#include "app/convergence.h"
#include "app/layer_identity.h"
#include "app/ray_benchmark.h"
#include "app/speed_report.h"
#include "app/strategy_agreement.h"

namespace pt {
namespace {

int run(int argc, char** argv) {
  CLI::App app{"bench: the project's measurements, printed as JSON or tables", "bench"};
  app.require_subcommand(1);
  const std::vector<BenchCommand> commands = {add_rays_command(app), add_speed_report_command(app),
                                              add_convergence_command(app),
                                              add_agreement_command(app),
                                              add_layers_command(app)};
  app.footer("Run bench COMMAND --help for a command's options.");
  // No command, or a first word that is none (a scene, or the old `--render` form), is named as
  // such, where the parser would only say that an argument was not expected.
  std::string names;
  bool known = false;
  for (const BenchCommand& c : commands) {
    names += (names.empty() ? "" : ", ") + c.command->get_name();
    known = known || (argc > 1 && c.command->get_name() == argv[1]);
  }
  const bool help = argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0);
  if (!known && !help) {
    if (argc > 1)
      std::cerr << "bench: '" << argv[1] << "' is not a command; ";
    else
      std::cerr << "bench: say which command: ";
    std::cerr << "the commands are " << names << " (bench COMMAND ARGS..., e.g. bench rays SCENE.dae)\n"
              << "Run bench --help for what each does.\n";
    return 2;
  }
  if (auto code = parse_or_exit(app, argc, argv, "bench",
                                "Run bench --help for the commands, bench COMMAND --help for the "
                                "options of one.",
                                std::cout, std::cerr))
    return *code;
  for (const BenchCommand& c : commands)
    if (c.command->parsed()) return c.run();
  return 2;  // require_subcommand(1) leaves no way here
}

}  // namespace
}  // namespace pt

int main(int argc, char** argv) {
  try {
    return pt::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "bench: " << e.what() << "\n";
    return 1;
  }
}
