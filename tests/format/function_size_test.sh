#!/usr/bin/env bash
# No function in the grader (grader/) or the harness it shares with the students' local tests
# (framework/harness/) is longer than 60 lines, from its first line to its closing brace, comments
# and blank lines included: a function a newcomer reads at once (docs/architecture.md). A lambda
# counts as a function of its own, and inside the function that holds it. Measured by Universal
# Ctags (Debian's universal-ctags), which gives each definition's first and last line without
# compiling anything.
#
#   tests/format/function_size_test.sh SOURCE_DIR WORK_DIR [MAX_LINES]
# WORK_DIR takes the canary file below. Exit code: 0 none too long, 1 some are (each named with
# its length) or the measure failed its canary, 77 skipped (no Universal Ctags).
set -uo pipefail
root="$(cd "$1" && pwd)"
work="$2"
max="${3:-60}"
command -v ctags >/dev/null && ctags --version 2>/dev/null | grep -q '^Universal Ctags' ||
  { echo "SKIP: no Universal Ctags (Debian's universal-ctags package)"; exit 77; }

# FILE... -> "FILE:LINE: NAME is N lines" for each definition longer than $max lines.
too_long() {
  ctags --languages=C++ --language-force=C++ --kinds-C++=f --fields=+ne -o - "$@" 2>/dev/null |
    awk -F'\t' -v max="$max" '{
      line = ""; end = ""; scope = ""
      for (i = 4; i <= NF; i++) {
        if ($i ~ /^line:/) line = substr($i, 6)
        else if ($i ~ /^end:/) end = substr($i, 5)
        else if ($i ~ /^function:/) scope = substr($i, 10)
      }
      name = $1
      if (name ~ /^__anon/) { sub(/.*::/, "", scope); name = "a lambda in " scope }
      if (end != "" && end - line + 1 > max) print $2 ":" line ": " name " is " end - line + 1 " lines"
    }' | sort -u
}

# The canary: a function one line too long, and one as long as allowed, must give exactly one
# finding; a ctags that measured nothing would otherwise pass everything.
mkdir -p "$work" || exit 1
canary="$work/function_size_canary.cpp"
{
  echo "namespace a {"
  for name in tooLong justRight; do
    echo "int $name(int x) {"
    lines=$((max - 2)); [ "$name" = tooLong ] && lines=$((max - 1))
    for ((i = 0; i < lines; i++)); do echo "  x += $i;"; done
    echo "}"
  done
  echo "}"
} >"$canary"
found=$(too_long "$canary")
if [ "$found" != "$canary:2: tooLong is $((max + 1)) lines" ]; then
  echo "FAIL: the measure is broken: a function of $((max + 1)) lines and one of $max gave:"
  echo "${found:-(nothing)}"
  exit 1
fi

cd "$root" || exit 1
mapfile -t files < <(git ls-files -- 'grader/*.cpp' 'grader/*.h' 'framework/harness/*.cpp' \
  'framework/harness/*.h' | grep -v '_test\.cpp$')
[ ${#files[@]} -gt 0 ] || { echo "FAIL: no files in grader/ or framework/harness/"; exit 1; }
long=$(too_long "${files[@]}")
if [ -n "$long" ]; then
  printf '%s\n' "$long"
  echo "FAIL: $(printf '%s\n' "$long" | wc -l) functions in grader/ and framework/harness/ are longer than $max lines; split them into named steps"
  exit 1
fi
echo "no function over $max lines in ${#files[@]} files of grader/ and framework/harness/ ($(ctags --version | head -1 | cut -d, -f1))"
