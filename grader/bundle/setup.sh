#!/usr/bin/env bash
# The autograder's setup: Gradescope runs it once, as root, when it builds the image, with this
# bundle unpacked in $ROOT/source. It installs what grading needs, builds the instructor's tree
# tree's grader once, then `grader autograde-setup` records what grading trusts (the student
# files, their stubs, a copy of the grader and of the solution) where the student's code cannot
# read it, takes the solution out of the tree and builds what grading runs.
#
# Target: Ubuntu 22.04 "jammy", Gradescope's default base image; it also runs on Debian 12
# "bookworm", the project's own machines, where CI runs it. The packages are the grading subset of
# tools/setup.sh, under names both releases share. The differences are handled here: Ubuntu keeps
# CLI11 in "universe" (enabled when a package has no candidate), and the write-up's packages
# (chromium, npm, cmark) are not needed to grade, so the bundle leaves website/ out.
#
# Variables: PT_AUTOGRADER_ROOT (default /autograder) is the root folder, so CI runs the same
# script under a temporary folder; PT_SKIP_PACKAGES=1 skips apt-get (a machine that has them);
# PT_JOBS (default: all cores) for the build.
set -euo pipefail
ROOT="${PT_AUTOGRADER_ROOT:-/autograder}"
SRC="$ROOT/source"
PT="$ROOT/pt"
JOBS="${PT_JOBS:-$(nproc)}"
say() { echo "setup.sh: $*" >&2; }

packages=(
  build-essential cmake ninja-build pkg-config zip
  libglm-dev libopenimageio-dev libtbb-dev libpugixml-dev libcli11-dev nlohmann-json3-dev
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libgtest-dev libgmock-dev
)
if [ "${PT_SKIP_PACKAGES:-0}" != 1 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  missing=()
  for p in "${packages[@]}"; do
    apt-cache policy "$p" 2>/dev/null | grep -q 'Candidate: [^(]' || missing+=("$p")
  done
  if [ "${#missing[@]}" -gt 0 ] && grep -qi ubuntu /etc/os-release; then
    say "no candidate for ${missing[*]}: enabling Ubuntu's universe"
    apt-get install -y -qq --no-install-recommends software-properties-common >/dev/null
    add-apt-repository -y universe >/dev/null
    apt-get update -qq
  fi
  apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
fi

[ -f "$SRC/project/CMakeLists.txt" ] || { say "no project in $SRC/project: is the bundle unpacked there?"; exit 2; }
mkdir -p "$PT/private"
# The solution copy the isolated build links the other parts from (PT_SOLUTION_DIR).
rm -rf "$PT/private/solution"
mkdir -p "$PT/private/solution"
cp -a "$SRC/project/parts" "$PT/private/solution/parts"

launcher=()
if [ "${PT_CCACHE:-0}" = 1 ] && command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths relative to the project in the cache's keys, so another root folder hits the cache.
  export CCACHE_BASEDIR="$SRC/project" CCACHE_NOHASHDIR=1
fi
say "configuring the instructor's tree, building the grader with $JOBS jobs"
# The build sits where a developer's does (project/build), so a compiler cache keyed on paths
# relative to the project serves it.
BUILD="$SRC/project/build"
cmake -S "$SRC/project" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPT_SOLUTION_DIR="$PT/private/solution" -DPT_TEST_DISCOVERY=PRE_TEST "${launcher[@]}" >/dev/null
cmake --build "$BUILD" -j "$JOBS" --target grader
# The grader puts the stubs in the part folders, then builds what grading runs (the judges, the
# complete solution's renderer from the private copy, every object the probes link) into the
# build's secret folder, and locks it and the rest away from the student's user.
"$BUILD/grader/grader" autograde-setup --root "$ROOT" --jobs "$JOBS"
say "done"
