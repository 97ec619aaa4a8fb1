// bench rays: how fast the BVH builds and answers rays, as JSON, optionally beside Intel Embree on
// the very same rays (the ray sets of rays-format.md, read from files or made from the scene).
#pragma once

#include "app/bench_command.h"

namespace pt {

/// `bench rays SCENE [--rays PREFIX] [--bvh sah|median|both] [--wide] [--embree] ...`: the
/// subcommand. The tracers are timed round by round, taking turns, so that their ratios compare
/// runs made seconds apart.
BenchCommand add_rays_command(CLI::App& bench);

}  // namespace pt
