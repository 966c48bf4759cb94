#!/usr/bin/env bash
# The suite's costs as data: each ctest entry's seconds, from the log of one clean run of
# .ci/run (what CI runs: the build, the README's test command, the sanitizer suite), as the
# markdown table docs/test-costs.md. README.md quotes its totals; scripts/docs-examples.sh
# checks that the quotes match the table.
#
#   bash .ci/run 2>&1 | tee ci.log
#   scripts/test-costs.sh ci.log "2026-11-27, a clean clone, idle" >docs/test-costs.md
#
# Takes the log and a line saying when and how it was measured; writes the table to stdout.
set -euo pipefail
log="$1" how="$2"

# "  12/164 Test  #33: name ......   Passed    1.23 sec": the first ctest run's entries (the
# README's test command); the sanitizer run follows its first "Total Test time".
entries() {
  awk '/Total Test time \(real\)/ { exit }
       / Test +#[0-9]+: / { sub(/.* Test +#[0-9]+: /, ""); name = $1
                            for (i = 2; i <= NF; ++i) if ($i == "sec") secs = $(i - 1)
                            status = ($0 ~ /Passed/) ? "passed" : ($0 ~ /Skipped|Not Run/) ? "skipped" : "failed"
                            print secs "\t" name "\t" status }' "$log" | sort -t$'\t' -k1,1 -rn
}
wall() { printf '%.0f' "$(grep -m"$1" 'Total Test time (real)' "$log" | tail -1 | tr -dc '0-9.')"; }

rows="$(entries)"
[ -n "$rows" ] || { echo "test-costs: no ctest entry in $log" >&2; exit 1; }
count=$(wc -l <<<"$rows")
sum=$(awk -F'\t' '{ s += $1 } END { printf "%.0f", s }' <<<"$rows")
ci=$(grep -m1 '^ci: done in' "$log" | tr -dc '0-9' || true)
commit=$(sed -n 's/^ci: commit //p' "$log" | head -1 || true)
suite_all=$(grep -m1 "^ci: the README's test command" "$log" | sed 's/.*done in //' | tr -dc '0-9' || true)

echo "# What each test costs"
echo
echo "<!-- made by scripts/test-costs.sh from a log of .ci/run; do not edit by hand -->"
echo "Measured: $how; commit ${commit:-unknown}."
echo
echo "| | seconds |"
echo "|---|---|"
echo "| \`.ci/run\` in all (install, build, tests, sanitizer build and tests) | ${ci:-?} |"
echo "| the README's test command (scripts/test.sh: configure, build, tests) | ${suite_all:-?} |"
echo "| its tests, ctest -j2, wall clock | $(wall 1) |"
echo "| the same, the $count entries' own seconds added up | $sum |"
echo "| the sanitizer suite, ctest -j2, wall clock | $(wall 2) |"
echo
echo "| test | seconds | result |"
echo "|---|---:|---|"
awk -F'\t' '{ printf "| `%s` | %s | %s |\n", $2, $1, $3 }' <<<"$rows"
