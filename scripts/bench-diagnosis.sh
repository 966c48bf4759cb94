#!/usr/bin/env bash
# The diagnosis's cost (issue 55): every kept wrong version graded by two builds of a6_grade in
# turns (the old one first for one version, the new one first for the next), so that the
# machine's load falls on both alike; prints the median wall time of each build's gradings and
# their ratio, and writes them as JSON.
#
#   scripts/bench-diagnosis.sh OLD_BUILD NEW_BUILD [OUT.json]
#     OLD_BUILD, NEW_BUILD: build folders, each with grader/a6_grade (e.g. a worktree of the
#     commit before the diagnosis, built with `cmake --build --preset default --target a6_grade`)
#     The wrong versions' files come from NEW_BUILD/variants/wrong/ (cmake/A6Variants.cmake).
# Exit status: 0 when the new build's median is at most 1.2 times the old one's, 1 otherwise,
# 2 for a bad command.
set -uo pipefail
[ $# -ge 2 ] || { sed -n '2,12p' "$0"; exit 2; }
old=$(realpath "$1") new=$(realpath "$2") out="${3:-}"
cd "$(dirname "$0")/.." || exit 2
for b in "$old" "$new"; do
  [ -x "$b/grader/a6_grade" ] || { echo "bench-diagnosis: no $b/grader/a6_grade"; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# NAME BUILD -> the grading's wall seconds (a6_grade's own exit status is not the point here).
grade() {
  local start end
  start=$(date +%s.%N)
  "$2/grader/a6_grade" "$work/sub/$1" --out "$work/out" --quiet >/dev/null 2>&1
  end=$(date +%s.%N)
  rm -rf "$work/out"
  echo "$end - $start" | bc
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

: >"$work/old.txt"
: >"$work/new.txt"
turn=0
for dir in "$new"/variants/wrong/*/; do
  name=$(basename "$dir")
  mkdir -p "$work/sub/$name"
  cp solution/*.cpp "$work/sub/$name/"
  cp "$dir"/*.cpp "$work/sub/$name/"
  if [ $((turn % 2)) = 0 ]; then
    grade "$name" "$old" >>"$work/old.txt"
    grade "$name" "$new" >>"$work/new.txt"
  else
    grade "$name" "$new" >>"$work/new.txt"
    grade "$name" "$old" >>"$work/old.txt"
  fi
  turn=$((turn + 1))
done
[ "$turn" -gt 0 ] || { echo "bench-diagnosis: no wrong versions under $new/variants/wrong"; exit 2; }
old_median=$(median <"$work/old.txt")
new_median=$(median <"$work/new.txt")
ratio=$(echo "scale=3; $new_median / $old_median" | bc)
echo "bench-diagnosis: $turn wrong versions; median grading $old_median s (old), $new_median s (new); ratio $ratio (target at most 1.2)"
if [ -n "$out" ]; then
  printf '{"what": "%s", "date": "%s", "nproc": %s, "versions": %s, "old_median_s": %s, "new_median_s": %s, "ratio": %s}\n' \
    "median wall time of a6_grade over the kept wrong versions, two builds in turns (scripts/bench-diagnosis.sh)" \
    "$(date -u +%FT%TZ)" "$(nproc)" "$turn" "$old_median" "$new_median" "$ratio" >"$out"
fi
[ "$(echo "$ratio <= 1.2" | bc)" = 1 ]
