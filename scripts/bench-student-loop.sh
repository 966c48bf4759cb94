#!/usr/bin/env bash
# A student's edit-build-test loop: change spring.cpp, rebuild, run task 1's tests.
#
#   scripts/bench-student-loop.sh [--runs N]      (default 5 runs of each, medians printed)
#
# In a student build of its own (a copy of starter/ in a scratch folder, -DA6_STUDENT=<it>), each
# run first changes spring.cpp's code (a new function, so no compiler cache can answer), then:
#   (a) the handout's loop: `ctest --test-dir <dir> -R Task1` (it rebuilds a6_tests, and only
#       that, before the tests: tests/CMakeLists.txt, a6_build_first);
#   (b) every target: `cmake --build <dir>` (the viewer, the golden tests, the grader's copy)
#       then the same tests;
#   (c) the baseline, in the same run: the tests alone, with nothing to rebuild.
# Prints the medians and the ratios (a)/(c), (b)/(c) and (b)/(a). Target (issue 12): the loop (a)
# in at most 2 s on the development machine, under load.
set -euo pipefail
cd "$(dirname "$0")/.."

runs=5
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift ;;
    -h | --help) sed -n '2,12p' "$0"; exit 0 ;;
    *) echo "bench-student-loop: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done

scratch=$(mktemp -d "${TMPDIR:-/tmp}/a6-bench-loop.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
cp -r starter "$scratch/mine"
build="$scratch/build"
echo "bench-student-loop: configuring and building a student build in $build (not timed)"
cmake -S . -B "$build" -G Ninja -DA6_STUDENT="$scratch/mine" -DA6_WRONG_VERSIONS=OFF \
  -DA6_BUILD_BENCH=OFF >"$scratch/configure.log" 2>&1 || { tail -20 "$scratch/configure.log"; exit 1; }
cmake --build "$build" >"$scratch/build.log" 2>&1 || { tail -20 "$scratch/build.log"; exit 1; }

# seconds <command...>: the wall time of one run (the tests fail on the starter: that is fine).
seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || true
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.4f\n", b - a }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
tests() { "$build/tests/a6_tests" --gtest_filter='Task1*' --gtest_brief=1; }

edits=0
# edit: a change to the code of spring.cpp (a new function), never the same twice.
edit() {
  edits=$((edits + 1))
  printf 'int a6BenchEdit%d() { return %d; }\n' "$edits" "$edits" >>"$scratch/mine/spring.cpp"
}

loop=() every=() base=()
for _ in $(seq "$runs"); do
  edit
  loop+=("$(seconds ctest --test-dir "$build" -R Task1)")
  edit
  every+=("$(seconds bash -c "cmake --build '$build' && '$build/tests/a6_tests' --gtest_filter='Task1*' --gtest_brief=1")")
  base+=("$(seconds tests)")
done
a=$(median "${loop[@]}") b=$(median "${every[@]}") c=$(median "${base[@]}")
printf 'bench-student-loop: medians of %d runs (linker: %s)\n' "$runs" \
  "$(grep -o 'fuse-ld=[a-z]*' "$build/build.ninja" | head -1 | cut -d= -f2 || true)"
printf '  (a) edit spring.cpp, ctest -R Task1 (rebuilds a6_tests):    %.3f s\n' "$a"
printf '  (b) edit spring.cpp, cmake --build (all), run Task1:         %.3f s\n' "$b"
printf '  (c) run Task1 alone (baseline):                              %.3f s\n' "$c"
awk -v a="$a" -v b="$b" -v c="$c" \
  'BEGIN { printf "  ratios: (a)/(c) = %.0f, (b)/(c) = %.0f, (b)/(a) = %.2f\n", a / c, b / c, b / a }'
