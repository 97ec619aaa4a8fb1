// libFuzzer's entry into the scene loader: any bytes must load into a scene that keeps its
// promises (scene_invariants.h) or fail with a SceneError; anything else (a crash, another
// exception, a sanitizer report, a hang, an allocation past the run's limit) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"
#include "fuzz/fuzz_limits.h"
#include "fuzz/scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    const pt::Scene scene = pt::load_collada_string(xml, "fuzz.dae", [](const std::string&) {},
                                                 pt::fuzz::kFuzzLimits);
    const std::string broken = pt::fuzz::scene_invariant_violation(scene);
    if (!broken.empty()) {
      std::fprintf(stderr, "loaded scene breaks a promise: %s\n", broken.c_str());
      __builtin_trap();
    }
  } catch (const pt::SceneError&) {
    // A clear refusal is a right answer.
  }
  return 0;
}
