#!/usr/bin/env bash
# GCC 11, the compiler of Ubuntu 22.04 (Gradescope's default image), where the bundle's setup.sh
# builds the grader: the five parts' step tests, the pathtracer and the grader, built with
# Debian's gcc-11 and the tests run. The libraries are Debian 12's, newer than Ubuntu 22.04's
# (docs/setup.md says what that leaves untested).
#   tools/ports/gcc11.sh          the tree in build-gcc11 (or $BUILD_DIR)
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/ports/common.sh
dir="${BUILD_DIR:-build-gcc11}"
command -v g++-11 >/dev/null || { echo "ports/gcc11: no g++-11 (tools/setup.sh --for developer)" >&2; exit 1; }
ports_stage build
ports_build "$dir" -DCMAKE_C_COMPILER=gcc-11 -DCMAKE_CXX_COMPILER=g++-11
cmake --build "$dir" -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" --target pathtracer grader
if ! grep -q 'CMAKE_CXX_COMPILER_VERSION "11\.' "$dir"/CMakeFiles/*/CMakeCXXCompiler.cmake; then
  echo "ports/gcc11: $dir was not configured with GCC 11" >&2
  exit 1
fi
ports_stage test
ports_test "$dir"
ports_done gcc11
