#!/usr/bin/env bash
# No function in the grader (grader/), the framework (framework/) or the tests (tests/) is longer
# than 60 lines, from its first line to its closing brace, comments and blank lines included: a
# function a newcomer reads at once (docs/architecture.md). A test's body (TEST, TEST_F, TEST_P)
# counts as a function: a longer test becomes two, or gets named helper steps. A lambda counts as
# a function of its own, and inside the function that holds it. The students' files copied whole
# as test fixtures are not ours to split (the exclusions below). Measured by Universal Ctags
# (Debian's universal-ctags), which gives each definition's first and last line without compiling
# anything. No file in grader/ is longer than 700 lines.
#
#   tests/format/function_size_test.sh SOURCE_DIR WORK_DIR [MAX_LINES]
# WORK_DIR takes the canary file below. Exit code: 0 none too long, 1 some are (each named with
# its length) or the measure failed its canary, 77 skipped (no Universal Ctags).
set -uo pipefail
root="$(cd "$1" && pwd)"
work="$2"
max="${3:-60}"
source "$(dirname "$0")/find_ctags.sh"  # $ctags, or skipped
ctags() { command "$ctags" "$@"; }

# FILE... -> "FILE:LINE: NAME is N lines" for each definition longer than $max lines.
too_long() {
  { tagged_too_long "$@"; untagged_too_long "$@"; } | sort -u -t: -k1,1 -k2,2n
}

# What ctags measures: each function definition's first and last line.
tagged_too_long() {
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
    }'
}

# What ctags 5.9 leaves out: a template whose return type is one of its parameters
# (`template <typename R, typename B>` then `R f(B b) {`) gets no tag at all. Each definition
# after a template line that starts no tag is measured here, from its first line to the brace
# that closes its first one (braces in comments, characters and strings aside).
untagged_too_long() {
  ctags --languages=C++ --language-force=C++ --kinds-C++='*' --fields=+n -o - "$@" 2>/dev/null |
    awk -F'\t' '{ for (i = 4; i <= NF; i++) if ($i ~ /^line:/) print $2 ":" substr($i, 6) }' \
    >"$work/tag_starts"
  awk -v max="$max" '
    FILENAME == ARGV[1] { tagged[$0] = 1; next }
    FNR == 1 { pending = 0; depth = -1 }
    pending && depth < 0 && !tagged[FILENAME ":" FNR] && !tagged[FILENAME ":" (FNR - 1)] &&
      $0 !~ /;[ \t]*$/ { first = FNR; head = $0; depth = 0 }
    { pending = 0 }
    /^[ \t]*template[ \t]*</ && depth < 0 { pending = 1 }
    depth >= 0 {
      line = $0
      gsub(/\/\/.*/, "", line); gsub(/"([^"\\]|\\.)*"/, "", line); gsub(/'\''([^'\''\\]|\\.)*'\''/, "", line)
      opened = gsub(/\{/, "{", line); closed = gsub(/\}/, "}", line)
      depth += opened - closed; if (opened > 0) seen = 1
      if (seen && depth <= 0) {
        name = head; sub(/\(.*/, "", name); sub(/.*[ \t*&]/, "", name)
        if (FNR - first + 1 > max) print FILENAME ":" first ": " name " is " FNR - first + 1 " lines"
        depth = -1; seen = 0
      }
    }' "$work/tag_starts" "$@"
}

# The canary: a function one line too long, a template of the shape ctags leaves out one line
# too long, and a function as long as allowed must give exactly the first two.
mkdir -p "$work" || exit 1
canary="$work/function_size_canary.cpp"
body() { for ((i = 0; i < $1; i++)); do echo "  x += $i;  // {"; done; }
{
  echo "namespace a {"
  echo "int tooLong(int x) {"; body $((max - 1)); echo "}"
  echo "template <typename R, typename B>"; echo "R tooLongTemplate(B x) {"; body $((max - 1)); echo "}"
  echo "int justRight(int x) {"; body $((max - 2)); echo "}"
  echo "}"
} >"$canary"
found=$(too_long "$canary")
expected="$canary:2: tooLong is $((max + 1)) lines
$canary:$((max + 4)): tooLongTemplate is $((max + 1)) lines"
if [ "$found" != "$expected" ]; then
  echo "FAIL: the measure is broken: two functions of $((max + 1)) lines and one of $max gave:"
  echo "${found:-(nothing)}"
  exit 1
fi

cd "$root" || exit 1
# Left out: whole copies of a student's files, fixtures that mirror what a student hands in
# (tests/wrong/: one mistake each; tests/alternative/: other correct ways to write the tasks;
# tests/grader/submissions/: the grader's hostile and broken hand-ins; tests/grader/fixtures/
# probe_hostile/: a misbehaving spring.cpp for the probe). Each is a student set (a6_student_set).
excluded='^tests/(wrong|alternative|grader/submissions|grader/fixtures/probe_hostile)/'
mapfile -t files < <(git ls-files -- 'grader/*.cpp' 'grader/*.h' 'framework/*.cpp' 'framework/*.h' \
  'tests/*.cpp' 'tests/*.h' | grep -Ev "$excluded")
[ ${#files[@]} -gt 0 ] || { echo "FAIL: no files in grader/, framework/ or tests/"; exit 1; }
long=$(too_long "${files[@]}")
if [ -n "$long" ]; then
  printf '%s\n' "$long"
  echo "FAIL: $(printf '%s\n' "$long" | wc -l) functions in grader/, framework/ and tests/ are longer than $max lines; split them into named steps"
  exit 1
fi
# And no file of grader/ over 700 lines (a file holds one concern: grader/DESIGN.md).
big=$(git ls-files -z -- 'grader/*.cpp' 'grader/*.h' 'grader/*.cmake' | xargs -0 wc -l |
  awk '$2 != "total" && $1 > 700 { print $2 " is " $1 " lines" }')
if [ -n "$big" ]; then
  printf '%s\n' "$big"
  echo "FAIL: files in grader/ over 700 lines; split them by concern"
  exit 1
fi
echo "no function over $max lines in ${#files[@]} files of grader/, framework/ and tests/ (student-file fixtures aside), no file of grader/ over 700 lines ($(ctags --version | head -1 | cut -d, -f1))"
