// Does the fast layer change a bit? `bench layers` renders each scene twice in one binary, its
// light samples and shadow rays answered once by the fast layer and once by the framework's own
// definitions, and compares the films to the bit.
#pragma once

#include "app/bench_command.h"

namespace pt {

/// Adds `bench layers SCENE...` to bench's command line.
BenchCommand add_layers_command(CLI::App& bench);

}  // namespace pt
