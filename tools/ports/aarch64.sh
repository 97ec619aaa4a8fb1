#!/usr/bin/env bash
# aarch64, 64-bit Arm (an Apple Silicon Mac's Linux container, an arm64 laptop): the five parts'
# step tests cross-compiled with Debian's cross compiler (cmake/aarch64-linux-gnu.cmake) against
# Debian's arm64 packages unpacked into a sysroot, and run under qemu-user (all but the exhaustive
# sweeps, below). No image module (OpenImageIO's arm64 packages bring many more) and no grader
# run: the parts' tests read and write no image, and the grader is the x86-64 configurations' to
# check.
#   tools/ports/aarch64.sh        the tree in build-aarch64 (or $BUILD_DIR), its sysroot inside
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/ports/common.sh
dir="${BUILD_DIR:-build-aarch64}"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
sysroot="$dir/sysroot"

# The arm64 packages the parts' tests build and run with, with the libraries they load. Only the
# tree's own apt state is used (its lists, no dpkg database): the machine's packages and its
# architectures stay as they are.
packages=(
  libc6 libstdc++6 libgcc-s1
  libtbb-dev libtbb12 libtbbmalloc2 libtbbbind-2-5 libhwloc15
  libpugixml-dev libpugixml1v5
  libgtest-dev libgmock-dev
  libcgal-dev libgmp-dev libgmp10 libgmpxx4ldbl libmpfr-dev libmpfr6 libboost1.74-dev
  libglm-dev libcli11-dev nlohmann-json3-dev libxxhash-dev libxxhash0
)
ports_stage sysroot
if [ ! -f "$sysroot/.packages" ] || [ "$(cat "$sysroot/.packages")" != "${packages[*]}" ]; then
  apt_dir="$dir/apt"
  rm -rf "$sysroot" "$apt_dir"
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/debs" "$sysroot"
  apt_options=(-o APT::Architecture=arm64 -o APT::Architectures::=arm64
               -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
               -o Dir::State::status=/dev/null -o Debug::NoLocking=1)
  apt-get "${apt_options[@]}" -qq update
  (cd "$apt_dir/debs" && apt-get "${apt_options[@]}" -qq download "${packages[@]}" 2>/dev/null)
  for deb in "$apt_dir"/debs/*.deb; do dpkg-deb -x "$deb" "$sysroot"; done
  echo "${packages[*]}" >"$sysroot/.packages"
fi

ports_stage build
ports_build "$dir" --toolchain cmake/aarch64-linux-gnu.cmake "-DPT_AARCH64_SYSROOT=$sysroot" \
  -DPT_IMAGE_MODULE=OFF
readelf -h "$dir/parts/part1_step1_camera_ray_test" | grep -q 'AArch64' ||
  { echo "ports/aarch64: the tests are not arm64 programs" >&2; exit 1; }
# Under emulation the exhaustive sweeps run far slower than on the machine (long double is 128
# bits in software on aarch64, and exact arithmetic is GMP's): random and adversarial rays
# against exact arithmetic, the BVH over every course scene, the estimators' long means, each
# about a second or more of x86-64 time, would take hours. They run natively in the other
# configurations; here every other step test runs.
sweeps='triangle[.](random|adversarial)_rays|sphere[.]roots_match_long_double|watertight[.]no_'
sweeps+='|ray_box[.]never_loses|traversal[.](flat_boxes|all_centroids|clustered|duplicates_tie'
sweeps+='|matches_brute_force|image_equals|cbbunny)|hemisphere[.]sphere_under'
sweeps+='|bounces[.](enclosure|sphere_under)|russian_roulette[.]keeps'
sweeps+='|mis[.](direct_light|sees_the_panels)|adaptive_loop[.]heavy_tailed'
ports_stage test
ports_test "$dir" -E "$sweeps"
ports_done aarch64
