#!/usr/bin/env bash
# Clang with libc++, the C++ standard library macOS uses: the five parts' step tests and the
# pathtracer, built and the tests run. GoogleTest is built here from its sources with libc++.
# The distribution's oneTBB and pugixml are built with libstdc++; they are linked as they are
# (their interfaces pass no standard-library type, so the two libraries meet only inside them).
# OpenImageIO's interface does pass them, so there is no image module (PT_IMAGE_MODULE off): the
# parts' tests read and write no image, and a render says it cannot write one.
#   tools/ports/libcxx.sh         the tree in build-libcxx (or $BUILD_DIR)
#   GTEST_SOURCE=DIR              GoogleTest's sources (default: Debian's googletest package's)
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/ports/common.sh
dir="${BUILD_DIR:-build-libcxx}"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
gtest_source="${GTEST_SOURCE:-/usr/src/googletest}"
libcxx=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS=-stdlib=libc++
        -DCMAKE_EXE_LINKER_FLAGS=-stdlib=libc++ -DCMAKE_SHARED_LINKER_FLAGS=-stdlib=libc++
        -DCMAKE_MODULE_LINKER_FLAGS=-stdlib=libc++)

ports_stage googletest
if [ ! -f "$dir/googletest/.built" ]; then
  [ -f "$gtest_source/CMakeLists.txt" ] ||
    { echo "ports/libcxx: no GoogleTest sources in $gtest_source (set GTEST_SOURCE)" >&2; exit 1; }
  launcher=()
  if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  cmake -S "$gtest_source" -B "$dir/googletest-build" -G Ninja "${launcher[@]}" "${libcxx[@]}" \
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_INSTALL_PREFIX=$dir/googletest" >/dev/null
  cmake --build "$dir/googletest-build" -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" >/dev/null
  cmake --install "$dir/googletest-build" >/dev/null
  touch "$dir/googletest/.built"
fi

ports_stage build
ports_build "$dir" "${libcxx[@]}" "-DCMAKE_PREFIX_PATH=$dir/googletest" -DPT_IMAGE_MODULE=OFF
cmake --build "$dir" -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" --target pathtracer
# Every program is libc++'s: it needs libc++, and neither needs libstdc++ itself nor calls it.
for program in "$dir/parts/part1_step1_camera_ray_test" "$dir/app/pathtracer"; do
  if ! readelf -d "$program" | grep -q 'NEEDED.*\[libc++\.so' ||
     readelf -d "$program" | grep -q 'NEEDED.*\[libstdc++' ||
     nm -D --undefined-only "$program" | grep -q '@GLIBCXX'; then
    echo "ports/libcxx: $program is not linked with libc++ alone" >&2
    exit 1
  fi
done
ports_stage test
ports_test "$dir"
"$dir/app/pathtracer" --help >/dev/null
ports_done libcxx
