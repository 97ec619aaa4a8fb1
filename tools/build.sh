#!/usr/bin/env bash
# Configures and builds the Release tree in build/ (or the tree named by $BUILD_DIR).
#   tools/build.sh [-DNAME=VALUE ...] [cmake --build arguments, e.g. --target pathtracer]
# The -D options go to the configure step (they stay in the tree's cache), the rest to the build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build}"
jobs="${JOBS:-$(getconf _NPROCESSORS_ONLN)}"  # the cores (a Mac has no nproc)
generator=()
if command -v ninja >/dev/null 2>&1 && [ ! -f "$build_dir/Makefile" ]; then generator=(-G Ninja); fi
launcher=()
# A compiler cache, where the machine has one, makes a second tree (or a rebuild) cheap.
# Its keys are taken relative to the project, so a copy of the project elsewhere (the handout the
# round-trip test builds, a mutant's scratch copy) finds the objects this tree compiled.
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
fi
configure=()
build=()
for a in "$@"; do
  case "$a" in
    -D*) configure+=("$a") ;;
    *) build+=("$a") ;;
  esac
done
cmake -S . -B "$build_dir" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
  "${configure[@]}" >/dev/null
cmake --build "$build_dir" -j "$jobs" "${build[@]}"
