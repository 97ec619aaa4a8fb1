#!/usr/bin/env bash
# Builds pathtracer and bench with GCC's profile-guided optimisation, in build-pgo/ (or the tree
# named by $BUILD_DIR): an instrumented build renders the project's own scenes and traces bench's
# ray sets, then the same tree is built again from the profile those runs wrote. Training on
# scenes/ (never on the scenes it is measured on) keeps the speed it buys honest.
#
# The optimisation changes how the code is laid out and inlined, not what it computes, so the
# optimised pathtracer must render every training image to the bit as the instrumented one did:
# the script compares them (linear float .exr, with OpenImageIO's idiff) and fails on any
# difference.
#   tools/build_pgo.sh            then build-pgo/app/pathtracer, build-pgo/app/bench
set -euo pipefail
if [ $# -gt 0 ]; then
  echo "build_pgo: takes no arguments (got '$*'); the tree is \$BUILD_DIR, build-pgo by default" >&2
  exit 2
fi
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build-pgo}"
case "$build_dir" in /*) ;; *) build_dir="$PWD/$build_dir" ;; esac
profile="$build_dir/pgo-profile"
renders="$build_dir/pgo-renders"

# What the renders exercise: light sampling at many samples a light (spheres, then a mesh with
# vertex normals), deep paths through mirror and glass and through a mesh of 6,368 triangles,
# adaptive sampling, MIS and hemisphere sampling. Small images: the profile needs the proportions,
# not the pixels.
training=(
  "spheres-l16|scenes/cornell_spheres.dae -s 16 -l 16 -m 5 -r 96 72"
  "smooth-l16|scenes/cornell_smooth.dae -s 16 -l 16 -m 5 -r 96 72"
  "glass-m100|scenes/cornell_mirror_glass.dae -s 128 -l 1 -m 100 -r 64 48"
  "coil-m100|scenes/cornell_coil.dae -s 128 -l 1 -m 100 -r 64 48"
  "coil-adaptive|scenes/cornell_coil.dae -s 16 -l 8 -m 6 -a 64 0.05 -r 96 72"
  "spheres-mis|scenes/cornell_spheres.dae -s 16 -l 2 -m 6 --mis -r 64 48"
  "spheres-hemisphere|scenes/cornell_spheres.dae -s 16 -l 4 -m 2 -H -r 64 48"
)

render_all() {  # render_all SUFFIX: every training render, to $renders/NAME.SUFFIX.exr
  local entry name args
  for entry in "${training[@]}"; do
    name="${entry%%|*}"
    read -r -a args <<<"${entry#*|}"
    "$build_dir/app/pathtracer" --seed 7 "${args[@]}" -f "$renders/$name.$1.exr" >/dev/null 2>&1 ||
      { echo "build_pgo: the $1 pathtracer failed to render $name (${entry#*|})" >&2; exit 1; }
  done
}

rm -rf "$profile" "$renders"
mkdir -p "$renders"
echo "build_pgo: the instrumented build" >&2
BUILD_DIR="$build_dir" tools/build.sh -DPT_PGO=generate "-DPT_PGO_DIR=$profile" \
  --target pathtracer bench >&2
echo "build_pgo: training" >&2
render_all instrumented
"$build_dir/app/bench" rays scenes/cornell_coil.dae --wide --rounds 1 --min-seconds 0 \
  --threads 1 >/dev/null
"$build_dir/app/bench" rays scenes/cornell_spheres.dae --wide --rounds 1 --min-seconds 0 \
  --threads 1 >/dev/null
echo "build_pgo: the optimised build" >&2
# Not from the compiler cache: an object compiled from an earlier training's profile would be the
# same code, only laid out for other counts, and the speed measured would not be this profile's.
CCACHE_DISABLE=1 BUILD_DIR="$build_dir" tools/build.sh -DPT_PGO=use "-DPT_PGO_DIR=$profile" \
  --target pathtracer bench >&2
render_all optimised
for entry in "${training[@]}"; do
  name="${entry%%|*}"
  # Every channel of every pixel (colour, variance, sample count) equal; the files themselves
  # differ by the time OpenImageIO stamps them with.
  if ! idiff -q -fail 0 -failpercent 0 -warn 0 "$renders/$name.instrumented.exr" \
    "$renders/$name.optimised.exr" >/dev/null 2>&1; then
    echo "build_pgo: the optimised pathtracer renders $name differently from the instrumented" \
      "one ($renders/$name.*.exr): the optimisation changed a result, which it must not" >&2
    exit 1
  fi
done
echo "build_pgo: ${#training[@]} renders identical to the bit; $build_dir/app/pathtracer and" \
  "$build_dir/app/bench are built" >&2
