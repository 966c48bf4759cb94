#!/usr/bin/env bash
# How long grading one submission takes, against what an instructor would otherwise script.
#
#   scripts/bench-grader.sh [BUILD] [--write]      (BUILD: a configured build tree; default build)
#
#   (a) a6_grade on the solution's seven files, with the framework and the grader's kit prebuilt
#       (median of 3); also with no checks at all (--tests '-*': intake, per-file compiles, link,
#       the probe's start-up check, the report), to split the time;
#   (b) a fresh CMake configure + build of the a6_tests target for the same seven files
#       (-DA6_STUDENT=<a copy of solution/>, no wrong versions, no benchmarks, no grader), then
#       `ctest -R physics`: median of 3, or one run when it takes over a minute.
# Prints both and their ratio; --write also records them in tests/bench/results/grader.json.
# Targets (tests/bench/README.md): (a) under 15 s, and at least 5 times faster than (b).
set -euo pipefail
cd "$(dirname "$0")/.."

build=build
write=0
for arg in "$@"; do
  case "$arg" in
    --write) write=1 ;;
    -h | --help)
      sed -n '2,13p' "$0"
      exit 0
      ;;
    *) build=$arg ;;
  esac
done
grader="$build/grader/a6_grade"
if [ ! -d "$build" ]; then
  echo "bench-grader: no build tree '$build' (cmake -S . -B $build -G Ninja first)" >&2
  exit 2
fi
echo "bench-grader: building a6_grade and its kit in $build (not timed)"
cmake --build "$build" --target a6_grade a6_grader_kit >/dev/null

scratch=$(mktemp -d "${TMPDIR:-/tmp}/a6-bench-grader.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
# As root a6_grade compiles and runs as nobody, who must be able to enter its output folder (or it
# grades in a scratch folder of its own, which is not what we want to time).
chmod 755 "$scratch"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
json_list() { local IFS=,; echo "[$*]"; }

# (a) a6_grade, three times, and three times with no checks.
grade_runs=()
build_only_runs=()
for i in 1 2 3; do
  t0=$(now)
  "$grader" solution --out "$scratch/grade-$i" --quiet >/dev/null
  t1=$(now)
  grade_runs+=("$(elapsed "$t0" "$t1")")
  score=$(sed -n 's/^  "score": \([0-9.]*\),$/\1/p' "$scratch/grade-$i/results.json")
  echo "  a6_grade solution: ${grade_runs[-1]} s (score $score)"
  if grep -q '"status": "failed"' "$scratch/grade-$i/results.json"; then
    echo "bench-grader: the solution did not pass every check; see $scratch/grade-$i/report.html" >&2
    trap - EXIT
    exit 1
  fi
  t0=$(now)
  "$grader" solution --out "$scratch/build-only-$i" --quiet --tests '-*' >/dev/null
  t1=$(now)
  build_only_runs+=("$(elapsed "$t0" "$t1")")
  echo "  a6_grade solution --tests '-*' (no checks): ${build_only_runs[-1]} s"
done
grade_median=$(median "${grade_runs[@]}")
build_only_median=$(median "${build_only_runs[@]}")

# (b) a fresh configure + build of a6_tests + the physics suite, as an instructor would script.
cp -r solution "$scratch/student"
fresh_runs=()
for i in 1 2 3; do
  rm -rf "$scratch/fresh"
  t0=$(now)
  cmake -S . -B "$scratch/fresh" -G Ninja -DA6_STUDENT="$scratch/student" \
    -DA6_WRONG_VERSIONS=OFF -DA6_BUILD_BENCH=OFF -DA6_BUILD_GRADER=OFF >/dev/null
  cmake --build "$scratch/fresh" --target a6_tests >/dev/null
  ctest --test-dir "$scratch/fresh" -R physics --output-on-failure >/dev/null
  t1=$(now)
  fresh_runs+=("$(elapsed "$t0" "$t1")")
  echo "  fresh configure + build a6_tests + ctest -R physics: ${fresh_runs[-1]} s"
  if awk -v s="${fresh_runs[-1]}" 'BEGIN { exit !(s > 60) }'; then break; fi
done
rm -rf "$scratch/fresh"
fresh_median=$(median "${fresh_runs[@]}")

ratio=$(awk -v f="$fresh_median" -v g="$grade_median" 'BEGIN { printf "%.1f", f / g }')
under15=$(awk -v g="$grade_median" 'BEGIN { print (g < 15) ? "true" : "false" }')
fivefold=$(awk -v r="$ratio" 'BEGIN { print (r >= 5) ? "true" : "false" }')

echo
echo "grading one submission with a6_grade (median of ${#grade_runs[@]}): $grade_median s" \
  "(of which intake, compiles, link, start-up check and report: $build_only_median s)"
echo "a fresh CMake build and the physics suite (median of ${#fresh_runs[@]}): $fresh_median s"
echo "ratio: a6_grade is ${ratio}x faster"
echo "targets: under 15 s per submission: $under15; at least 5x faster: $fivefold"

if [ "$write" = 1 ]; then
  cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
  compiler=$(c++ --version | head -1)
  out=tests/bench/results/grader.json
  cat >"$out" <<EOF
{
  "what": "seconds to grade the solution with a6_grade (framework and kit prebuilt) vs. a fresh CMake configure + build of a6_tests + ctest -R physics for the same seven files (scripts/bench-grader.sh)",
  "date": "$(date -u +%Y-%m-%dT%H:%M:%SZ)",
  "machine": {"nproc": $(nproc), "cpu": "$cpu", "compiler": "$compiler"},
  "a6_grade": {"runs": $(json_list "${grade_runs[@]}"), "median": $grade_median},
  "a6_grade_without_checks": {"runs": $(json_list "${build_only_runs[@]}"), "median": $build_only_median},
  "fresh_build_and_physics": {"runs": $(json_list "${fresh_runs[@]}"), "median": $fresh_median},
  "ratio": $ratio,
  "targets": {"under_15_s": $under15, "at_least_5x": $fivefold}
}
EOF
  echo "written: $out"
fi
