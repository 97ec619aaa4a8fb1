# What every configuration of tools/ports/ does, sourced by each script: build the five parts'
# step tests (not their long stress checks, not the apps) in a tree of its own, run them, and
# say how long each stage took.
#   ports_build DIR [cmake -D options ...]   configure DIR and build the parts' tests there
#   ports_test DIR [ctest options ...]       run the parts' tests (labels part1 .. part5)
#   ports_stage NAME                         start timing a stage; ports_done prints them all

ports_started=$(date +%s)
ports_stage_name=""
ports_stage_start=0
ports_times=()

ports_stage() {
  local now
  now=$(date +%s)
  if [ -n "$ports_stage_name" ]; then ports_times+=("$ports_stage_name $((now - ports_stage_start)) s"); fi
  ports_stage_name="$1"
  ports_stage_start=$now
}

ports_done() {  # ports_done CONFIG: the stages' times, the total and the machine's load
  ports_stage ""
  echo "ports/$1: ${ports_times[*]/%/,} total $(( $(date +%s) - ports_started )) s," \
       "load $(cut -d' ' -f1-3 /proc/loadavg)"
}

# The parts' step test programs of a configured tree, by the names pt_add_part gives them
# (partN_stepK_NAME_test), the stress checks left out.
ports_part_targets() {
  cmake --build "$1" --target help | sed -n 's/^\(part[1-5]_step[0-9]*_[a-z0-9_]*_test\):.*/\1/p' |
    grep -v '_stress_test$'
}

ports_build() {
  local dir="$1"
  shift
  local launcher=()
  if command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  fi
  cmake -S . -B "$dir" -G Ninja "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release -DPT_WITH_EMBREE=OFF \
    "$@" >/dev/null
  local targets
  targets=$(ports_part_targets "$dir")
  if [ -z "$targets" ]; then
    echo "ports: $dir has no part test targets" >&2
    return 1
  fi
  # shellcheck disable=SC2086  # one target a word
  cmake --build "$dir" -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" --target $targets
}

ports_test() {  # ports_test DIR [ctest options ...]
  local dir="$1"
  shift
  ctest --test-dir "$dir" -L '^part[1-5]$' --output-on-failure -j "${JOBS:-$(getconf _NPROCESSORS_ONLN)}" \
    --no-tests=error "$@"
}
