#!/usr/bin/env bash
# The autograder's setup: Gradescope runs it once, as root, when it builds the image, with this
# bundle unpacked in $ROOT/source. It installs what grading needs, builds the instructor's
# tree's grader once, then `grader autograde-setup` records what grading trusts (the student
# files, their stubs, a copy of the grader and of the solution) where the student's code cannot
# read it, takes the solution out of the tree and builds what grading runs.
#
# Target: Ubuntu 22.04 "jammy", Gradescope's default base image; it also runs on Debian 12
# "bookworm", the project's own machines, where CI runs it on an empty root (tools/fresh_root).
# The packages are the project's one list's "grading" lines (project/tools/packages.list),
# installed by the project's own tools/setup.sh, which names any package the system lacks. The
# write-up's packages (chromium, npm, cmark) are not needed to grade: the bundle leaves website/ out.
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

[ -f "$SRC/project/CMakeLists.txt" ] || { say "no project in $SRC/project: is the bundle unpacked there?"; exit 2; }
if [ "${PT_SKIP_PACKAGES:-0}" != 1 ]; then
  say "installing the grading packages of project/tools/packages.list"
  bash "$SRC/project/tools/setup.sh" --for grading || {
    say "the packages could not be installed (the lines above say which and why)"
    exit 1
  }
fi

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
# relative to the project serves it. The solution-only speed layers (the wide BVH, the light
# batches) are not built: nothing compiled from a solution-only source exists on the grading
# machine, and every render is the handout's renderer with the parts it grades.
BUILD="$SRC/project/build"
cmake -S "$SRC/project" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPT_SOLUTION_DIR="$PT/private/solution" -DPT_TEST_DISCOVERY=PRE_TEST \
  -DPT_WIDE_BVH=OFF -DPT_FAST_LIGHTS=OFF "${launcher[@]}" >/dev/null
cmake --build "$BUILD" -j "$JOBS" --target grader
# The grader puts the stubs in the part folders, then builds what grading runs (the judges, the
# complete solution's renderer from the private copy, every object the probes link) into the
# build's secret folder, and locks it and the rest away from the student's user.
"$BUILD/grader/grader" autograde-setup --root "$ROOT" --jobs "$JOBS"
say "done"
