#!/usr/bin/env bash
# Grades your own work before you submit it, as the grader will: each of the seven files compiled on
# its own and run in a sandbox, scored by the rubric in grader/rubric.toml, and the same report.
#
#   scripts/check.sh [FOLDER]     # FOLDER: your seven files (default: starter/)
#
# Writes out/check/report.html (open it in a browser: every check with its message, your
# pictures beside the reference images) and out/check/results.json, and prints the summary.
# In a student release the rubric holds the public checks only: the graders run hidden checks
# too, after you submit (docs/handout.md, "Checking your work").
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
folder="${1:-$root/starter}"
out="$root/out/check"
if [ ! -d "$folder" ]; then
  echo "check: $folder is not a folder (give the folder that holds your seven .cpp files)" >&2
  exit 2
fi
folder="$(cd "$folder" && pwd)"

cd "$root" || exit 1
if [ ! -f build/CMakeCache.txt ]; then
  echo "check: configuring build/ (once)"
  cmake --preset default >/dev/null || { echo "check: configuring failed (see above)" >&2; exit 1; }
fi
# Without toml++ (Ubuntu 22.04 has no package of it) the build has no grader: the public checks
# still run (scripts/test.sh: everything built, then ctest), without the point table.
if grep -q '^A6_GRADER_BUILT:INTERNAL=OFF$' build/CMakeCache.txt; then
  echo "check: this build has no grader: it needs toml++ 3 (libtomlplusplus-dev), which this" \
    "platform does not package (Ubuntu 22.04). Running the public checks (scripts/test.sh)" \
    "instead, with no point table; Ubuntu 24.04, Debian 12 or 13, or the dev container give the" \
    "whole report (README.md, \"Platforms\")." >&2
  exec "$root/scripts/test.sh"
fi
# The grader and what it needs; progress every tenth of the steps, the whole output in a log.
echo "check: building the grader in build/ (the first time a few minutes, then only what changed)"
cmake --build build --target a6_grade 2>&1 | tee build/check-build.log |
  awk '/^\[[0-9]+\/[0-9]+\]/ { split(substr($1, 2), a, "/"); tenth = int(10 * a[1] / a[2])
         if (tenth > shown) { shown = tenth; printf "check:   %d of %d build steps done\n", a[1], a[2] } }' ||
  { echo "check: building the grader failed: see build/check-build.log, or run 'cmake --build build'" >&2; exit 1; }

echo "check: grading $folder (out/check/report.html)"
rm -rf "$out"
build/grader/a6_grade "$folder" --out "$out" --quiet
status=$?
[ "$status" -eq 0 ] || echo "check: the grader failed (exit status $status): see $out/results.json" >&2
exit "$status"
