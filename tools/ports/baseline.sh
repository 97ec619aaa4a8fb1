#!/usr/bin/env bash
# No AVX (PT_ISA=baseline: x86-64's SSE2 only, the code an arm64 Mac compiles, which has no AVX)
# and no Linux sandbox (PT_LINUX_SANDBOX off: child processes as a Mac or a Windows student's
# own grader runs them): the five parts' step tests, the pathtracer and the grader, built and
# the tests run. tools/ports/no_sandbox.sh grades in the same tree.
#   tools/ports/baseline.sh       the tree in build-baseline (or $BUILD_DIR)
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/ports/common.sh
dir="${BUILD_DIR:-build-baseline}"
ports_stage build
ports_build "$dir" -DPT_ISA=baseline -DPT_LINUX_SANDBOX=OFF
cmake --build "$dir" -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" --target pathtracer grader
if grep -q -- '-mavx' "$dir/compile_commands.json"; then
  echo "ports/baseline: an AVX option in $dir/compile_commands.json" >&2
  exit 1
fi
ports_stage test
ports_test "$dir"
ports_done baseline
