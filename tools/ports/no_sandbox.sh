#!/usr/bin/env bash
# The grader without the Linux sandbox (PT_LINUX_SANDBOX off), as a Mac or a Windows student's
# own grader runs: `grader --part N` on the complete solution must pass every step, and on the
# handout, built the same way, must build, run and score 0. In the tree tools/ports/baseline.sh
# builds (no AVX either, as on an arm64 Mac); run alone, it configures and builds that tree.
#   tools/ports/no_sandbox.sh [PART ...]   the parts to grade (default 1), in build-baseline
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/ports/common.sh
dir="${BUILD_DIR:-build-baseline}"
parts=("$@")
[ "${#parts[@]}" -gt 0 ] || parts=(1)
options=(-DPT_ISA=baseline -DPT_LINUX_SANDBOX=OFF)
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1

ports_stage build
ports_build "$dir" "${options[@]}"
cmake --build "$dir" -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" --target pathtracer grader
grep -q '^PT_LINUX_SANDBOX:BOOL=OFF$' "$dir/CMakeCache.txt" ||
  { echo "ports/no_sandbox: $dir is built with the Linux sandbox" >&2; exit 1; }

ports_stage solution
for part in "${parts[@]}"; do
  "$dir/grader/grader" --part "$part" --out "$dir/no-sandbox-grades"
done

ports_stage handout
handout="$dir/no-sandbox-handout"
rm -rf "$handout"
"$dir/grader/grader" handout "$handout" >/dev/null
# The handout built as a student builds it (its own tools/build.sh), with the same options.
(cd "$handout" && CCACHE_BASEDIR="$PWD" BUILD_DIR=build tools/build.sh "${options[@]}" \
  --target grader >/dev/null)
for part in "${parts[@]}"; do
  status=0
  "$handout/build/grader/grader" --part "$part" --out "$handout/grades" \
    --json "$handout/grades/part$part.json" >"$handout/grades-part$part.txt" 2>&1 || status=$?
  # Every step fails on the stubs (exit 1, not 2: graded, not refused) and scores nothing.
  if [ "$status" -ne 1 ] || ! grep -q '^Total: 0/' "$handout/grades-part$part.txt"; then
    tail -n 30 "$handout/grades-part$part.txt" >&2
    echo "ports/no_sandbox: the handout's part $part gave status $status, not a score of 0" >&2
    exit 1
  fi
  echo "ports/no_sandbox: the handout's part $part: $(grep '^Total:' "$handout/grades-part$part.txt")"
done
ports_done no_sandbox
