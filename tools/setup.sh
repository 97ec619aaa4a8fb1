#!/usr/bin/env bash
# Installs every package the project builds, tests and documents with (Debian packages only).
# Safe to run again: apt-get skips what is already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  ccache                # a second tree of the same sources (the handout's round trip) reuses objects
  libglm-dev            # vector maths
  libopenimageio-dev openimageio-tools   # PNG/EXR output, image diffs
  libcgal-dev libgmp-dev libmpfr-dev     # exact kernel for the intersection tests
  libboost-dev          # Boost.Math distributions for the chi-square and t tests
  libgtest-dev libgmock-dev              # unit tests
  libtbb-dev            # parallel tiles
  libpugixml-dev        # COLLADA reader
  libcli11-dev          # command lines
  nlohmann-json3-dev    # bench output, manifests, grader results
  libxxhash-dev         # fingerprints of the convergence study's cached references
  libcmark-dev          # write-up Markdown
  libcpp-httplib-dev    # the viewer's web server (127.0.0.1 only)
  libembree-dev         # optional: bench rays --embree comparison only
  clang libclang-rt-dev llvm  # optional: tools/fuzz (libFuzzer, its sanitizers, llvm-cov)
  chromium              # headless browser tests of the write-up and the viewer
  # The other machines CI builds for (tools/ports/): Clang with libc++ (macOS's standard library)
  # and GoogleTest's sources to build with it; the arm64 cross compiler and qemu-user to run its
  # programs (the arm64 libraries are unpacked into the build tree, not installed).
  libc++-dev libc++abi-dev googletest
  g++-aarch64-linux-gnu qemu-user-static
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# KaTeX (offline math in the write-up) comes from the npm registry; a machine that already has
# Node.js with npm (as the CI image does) keeps it, since Debian's npm conflicts with that build.
if ! command -v npm >/dev/null 2>&1; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
# The write-up's npm packages (KaTeX; playwright-core for the browser test) at the locked versions.
website_dir="$(cd "$(dirname "$0")/../website" && pwd)"
if [ ! -f "$website_dir/node_modules/.package-lock.json" ] ||
   ! cmp -s "$website_dir/package-lock.json" "$website_dir/node_modules/.installed-lock"; then
  (cd "$website_dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null &&
   cp package-lock.json node_modules/.installed-lock)
fi
echo "setup: all packages present" >&2
