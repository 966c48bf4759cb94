#!/usr/bin/env bash
# What the grader gives every submission we keep, in one folder, to compare a change of the
# grader's code against: results.json of the solution, the starter, every wrong version
# (tests/wrong) and every correct alternative (tests/alternative), as the build applied their
# patches, and every hostile submission (tests/grader/submissions), graded with one seed, less
# what changes from run to run (times, memory). Two folders compare with `diff -r`; nothing should differ after a refactoring.
#
#   scripts/grader-baseline.sh OUT_DIR [BUILD_DIR]     (BUILD_DIR default: build)
#
# Each grading gets --time-budget $A6_BASELINE_BUDGET (default 20 s), so that the endless loops
# end soon; the cases that depend on where a time limit falls are named in the output.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?usage: scripts/grader-baseline.sh OUT_DIR [BUILD_DIR]}"
build="${2:-$root/build}"
grade="$build/grader/a6_grade"
[ -x "$grade" ] || { echo "grader-baseline: no $grade (cmake --build $build --target a6_grade)" >&2; exit 2; }
mkdir -p "$out"
cases=("$root/solution" "$root/starter")
# The wrong versions and alternatives as the build applied their patches (cmake/A6Variants.cmake).
for d in "$build"/variants/wrong/*/ "$build"/variants/alternative/*/ "$root"/tests/grader/submissions/*/; do
  cases+=("${d%/}")
done
start=$(date +%s)
for c in "${cases[@]}"; do
  name=$(realpath --relative-to="$root" "$c" | sed -E "s|^.*variants/|tests/|" | tr '/' '_')
  work=$(mktemp -d)
  chmod 755 "$work"
  "$grade" "$c" --out "$work/r" --seed 12345 --time-budget "${A6_BASELINE_BUDGET:-20}" --quiet \
    >"$work/log" 2>&1
  status=$?
  if [ -f "$work/r/results.json" ]; then
    jq --arg status "$status" 'del(.execution_time, .extra_data.seconds, .extra_data.seconds_by_stage,
      .extra_data.grader_peak_rss_mib)
      | .a6_grade_exit_status = $status' "$work/r/results.json" |
      sed -E "s|$work|WORK|g; s|/tmp/[A-Za-z0-9_.-]+|TMP|g; s|ran out of time: [0-9.]+ s|ran out of time: N s|g" \
        >"$out/$name.json"
  else
    echo "{\"a6_grade_exit_status\": \"$status\", \"results\": \"none\"}" >"$out/$name.json"
  fi
  printf '%-60s exit %s score %s\n' "$name" "$status" "$(jq -r '.score // "-"' "$out/$name.json")"
  rm -rf "$work"
done
echo "grader-baseline: ${#cases[@]} submissions in $(($(date +%s) - start)) s: $out"
