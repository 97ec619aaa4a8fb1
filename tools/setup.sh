#!/usr/bin/env bash
# Installs the packages of one set-up from tools/packages.list (Debian 12 or Ubuntu 22.04, with
# apt-get), then, where the tree has the write-up, its npm packages.
#   tools/setup.sh                   every package the list holds (in a handout: the student's)
#   tools/setup.sh --for SETUP       one set-up's: student, grading or developer
#   tools/setup.sh --list [SETUP]    print the packages, install nothing
# Safe to run again: what is installed is skipped. A package the system's sources do not have is
# named, with the line of the list that asks for it, and the set-up stops with status 1.
set -euo pipefail
tools_dir="$(cd "$(dirname "$0")" && pwd)"
list_file="$tools_dir/packages.list"
say() { echo "setup: $*" >&2; }

setup=""
list_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --for) setup="${2:-}"; shift 2 || { say "--for needs a set-up"; exit 2; } ;;
    --list) list_only=1; shift; if [ $# -gt 0 ]; then setup="$1"; shift; fi ;;
    *) say "unknown argument '$1' (tools/setup.sh [--for SETUP] [--list [SETUP]])"; exit 2 ;;
  esac
done
case "$setup" in
  "" | student | grading | developer) ;;
  *) say "unknown set-up '$setup': student, grading or developer"; exit 2 ;;
esac
[ -f "$list_file" ] || { say "$list_file: missing (the package list)"; exit 2; }

# The list's packages for the set-up: a line's second field names the set-ups that install it.
packages=()
while read -r name setups _why; do
  case "$name" in "" | "#"*) continue ;; esac
  if [ -z "$setup" ] || [[ ",$setups," == *",all,"* ]] || [[ ",$setups," == *",$setup,"* ]]; then
    packages+=("$name")
  fi
done < "$list_file"
if [ "$list_only" = 1 ]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

# Each reads the whole answer before matching: grep -q on a pipe would stop its writer early,
# and pipefail would take that for a failure.
installed() { [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null)" == *"install ok installed"* ]]; }
has_candidate() { [[ "$(apt-cache policy "$1" 2>/dev/null)" =~ Candidate:\ [^\(] ]]; }

missing=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
if [ "${#missing[@]}" -gt 0 ]; then
  say "installing ${missing[*]}"
  $SUDO apt-get update -qq
  absent=()
  for p in "${missing[@]}"; do has_candidate "$p" || absent+=("$p"); done
  if [ "${#absent[@]}" -gt 0 ] && grep -qi '^ID=ubuntu' /etc/os-release 2>/dev/null; then
    # Ubuntu 22.04 keeps many of the libraries (OpenImageIO, oneTBB, CGAL, CLI11, GoogleTest) in
    # "universe" (docs/setup.md).
    say "no candidate for ${absent[*]}: enabling Ubuntu's universe"
    $SUDO apt-get install -y -qq --no-install-recommends software-properties-common >/dev/null
    $SUDO add-apt-repository -y universe >/dev/null
    $SUDO apt-get update -qq
    absent=()
    for p in "${missing[@]}"; do has_candidate "$p" || absent+=("$p"); done
  fi
  if [ "${#absent[@]}" -gt 0 ]; then
    for p in "${absent[@]}"; do
      say "package '$p' is not in this system's package sources ($(. /etc/os-release && echo "$PRETTY_NAME")); $list_file asks for it:"
      grep -E "^$p[[:space:]]" "$list_file" | sed 's/^/  /' >&2
    done
    exit 1
  fi
  # apt-get's own words stay whole when it fails, so the log says which package and why.
  log="$(mktemp)"
  if ! $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" >"$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    say "apt-get could not install: ${missing[*]} (its output is above)"
    exit 1
  fi
  rm -f "$log"
  for p in "${missing[@]}"; do
    installed "$p" || { say "package '$p' was not installed by apt-get"; exit 1; }
  done
fi

# The write-up (website/) takes KaTeX, and playwright-core for its browser test, from the npm
# registry; the grading image has no website/ and needs neither.
website_dir="$tools_dir/../website"
if [ "$setup" != grading ] && [ -f "$website_dir/package-lock.json" ]; then
  # A machine that already has Node.js with npm (as the CI image does) keeps it, since Debian's
  # npm conflicts with that build.
  if ! command -v npm >/dev/null 2>&1; then
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
  fi
  if [ ! -f "$website_dir/node_modules/.package-lock.json" ] ||
     ! cmp -s "$website_dir/package-lock.json" "$website_dir/node_modules/.installed-lock"; then
    (cd "$website_dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null &&
     cp package-lock.json node_modules/.installed-lock)
  fi
fi
say "all packages present${setup:+ for the $setup set-up}"
