// The instancing limits the fuzz target loads with (and the corpus test, which replays what the
// fuzzer saw).
#pragma once

#include <cstdint>

#include "framework/scene/collada_loader.h"

namespace pt::fuzz {

/// 2^16 primitives and node instances. With the full limits (2^24) a mutated doubling chain just
/// under them is a valid scene of millions of triangles, which takes the sanitized target past its
/// time limit for an input (reproducers/doubling_chain_under_the_limit.dae);
/// lowered, such a chain is refused at once and the limit's error path is reached often. The full
/// limits are tested by framework/scene/hostile_scene_test.cpp.
inline constexpr LoadLimits kFuzzLimits{uint64_t(1) << 16, uint64_t(1) << 16};

}  // namespace pt::fuzz
