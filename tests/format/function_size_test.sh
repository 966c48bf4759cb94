#!/usr/bin/env bash
# No function in the grader (grader/) or the harness it shares with the students' local tests
# (framework/harness/) is longer than 60 lines, comments and blank lines included: a function a
# newcomer reads at once (docs/architecture.md). Measured by clang-tidy's
# readability-function-size check against the build's compile_commands.json, headers included.
#
#   tests/format/function_size_test.sh SOURCE_DIR BUILD_DIR [MAX_LINES]
# Exit code: 0 none too long, 1 some are (each named with its length), 77 skipped (no
# clang-tidy, or no compile_commands.json in BUILD_DIR).
set -uo pipefail
root="$(cd "$1" && pwd)"
build="$(cd "$2" && pwd)"
max="${3:-60}"
tidy=""
for c in clang-tidy clang-tidy-14 clang-tidy-15 clang-tidy-16 clang-tidy-17 clang-tidy-18 clang-tidy-19; do
  if command -v "$c" >/dev/null; then tidy="$c"; break; fi
done
[ -n "$tidy" ] || { echo "SKIP: no clang-tidy (Debian's clang-tidy package)"; exit 77; }
[ -f "$build/compile_commands.json" ] || { echo "SKIP: no $build/compile_commands.json"; exit 77; }
cd "$root" || exit 1
# The translation units the build compiles (a file the build does not compile cannot be parsed).
mapfile -t files < <(git ls-files -- 'grader/*.cpp' 'framework/harness/*.cpp' 2>/dev/null |
  grep -v '_test\.cpp$' | while read -r f; do
    grep -q "\"file\": \"$root/$f\"" "$build/compile_commands.json" && echo "$f"
  done)
[ ${#files[@]} -gt 0 ] || { echo "SKIP: the build compiles none of grader/ or framework/harness/"; exit 77; }
config="{CheckOptions: [{key: readability-function-size.LineThreshold, value: $max}]}"
report=$(printf '%s\n' "${files[@]}" |
  xargs -P "$(nproc)" -I{} "$tidy" -p "$build" --quiet --checks='-*,readability-function-size' \
    --config="$config" --header-filter="^$root/(grader|framework/harness)/" {} 2>/dev/null)
# "FILE:LINE:COL: warning: function 'NAME' exceeds ..." then "FILE:LINE:COL: note: N lines ...".
long=$(printf '%s\n' "$report" | awk -v root="$root/" '
  / warning: function / { split($0, a, ": warning: function "); where = a[1]; sub(root, "", where)
                           name = a[2]; sub(/ exceeds.*/, "", name) }
  / note: [0-9]+ lines including/ { n = $0; sub(/.* note: /, "", n); sub(/ lines.*/, "", n)
                           if (where != "") print where ": " name " is " n " lines"; where = "" }' |
  sort -u)
if [ -n "$long" ]; then
  printf '%s\n' "$long"
  echo "FAIL: $(printf '%s\n' "$long" | wc -l) functions in grader/ and framework/harness/ are longer than $max lines; split them into named steps"
  exit 1
fi
echo "no function over $max lines in ${#files[@]} files of grader/ and framework/harness/ (headers included; $("$tidy" --version | grep -o 'version [0-9.]*'))"
