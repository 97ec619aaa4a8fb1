// bench render: the speed report. Runs the pathtracer command on the course's scenes at the
// flags the project's performance goals name, and prints what each run cost as JSON: wall and
// render seconds, rays per second, peak memory; and what a command that writes no image costs.
#pragma once

#include <string>
#include <vector>

#include "app/bench_command.h"

namespace pt {

/// One run of the pathtracer the report makes: a name, the scene (relative to the scenes
/// folder) and the flags (without -f, which the report adds).
struct SpeedCase {
  std::string name;
  std::string scene;  ///< empty for a command that takes no scene (--help)
  std::vector<std::string> flags;
  bool writes_image = true;
};

/// The runs of the report: the full one (the goals' own flags), or the quick one (the same
/// scenes and settings at a fraction of the samples, for a check in a minute or two).
std::vector<SpeedCase> speed_cases(bool quick);

/// `bench render [--quick] [--scenes DIR] [--pathtracer PATH] [--out FILE]`: the subcommand,
/// which runs the cases one after another, each as a child process, and prints the report: per
/// render its wall and render seconds, rays/s, peak memory, and the peak of its render phase
/// alone (before the image library is opened to write the image).
BenchCommand add_speed_report_command(CLI::App& bench);

}  // namespace pt
