#!/usr/bin/env bash
# The instructor's commands (scripts/instructor.sh) as a TA runs them, on this build: each job
# does its work and checks it, and a broken rubric stops it before anything is graded.
#
#   tests/release/instructor_test.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR
set -uo pipefail
root="$1" build="$2" scratch="$3"
export A6_BUILD_DIR="$build" A6_INSTRUCTOR_OUT="$scratch/out"
rm -rf "$scratch"
mkdir -p "$scratch"
failures=0
# check WHAT WANT_STATUS TEXT... -- ARGS...: runs scripts/instructor.sh ARGS, checks its exit
# status and that its output holds each TEXT.
check() {
  local what="$1" want="$2" out status
  shift 2
  local texts=()
  while [ "$1" != "--" ]; do texts+=("$1"); shift; done
  shift
  out="$(bash "$root/scripts/instructor.sh" "$@" 2>&1)"
  status=$?
  if [ "$status" -ne "$want" ]; then
    echo "FAIL: $what: exit status $status, not $want:"$'\n'"$out" >&2
    failures=$((failures + 1))
    return
  fi
  for text in "${texts[@]}"; do
    if ! grep -qF -- "$text" <<<"$out"; then
      echo "FAIL: $what: no '$text' in:"$'\n'"$out" >&2
      failures=$((failures + 1))
      return
    fi
  done
  echo "ok: $what"
}

# The rubric's points as the grader reads them (an instructor's rubric has its own: not pinned).
IFS=$'\t' read -r _ points _ < <("$build/grader/a6_grade" --list-items --rubric "$root/grader/rubric.toml" 2>/dev/null | tail -1)
points=$(printf '%.2f' "${points:-0}")
check "the default rubric is valid, full marks and nothing" 0 \
  "valid: " "total  " "$points / $points" "the starter scores 0" -- rubric
printf 'total = 100\n[[item]]\nname = "all"\ntests = "*"\npoints = 90\n' >"$scratch/short.toml"
A6_INSTRUCTOR_OUT="$scratch/short" check "a rubric that does not add up stops at once, with its line" 2 \
  "short.toml:1: total = 100 but the items' points add up to 90" -- rubric "$scratch/short.toml"
[ ! -e "$scratch/short" ] || { echo "FAIL: the short rubric graded something" >&2; failures=$((failures + 1)); }
check "the hidden checks: the solution passes them, the starter fails them" 0 \
  "Task1Hidden." "the solution passes all" "the starter fails every one" -- hidden-check
check "re-rendering into a folder of its own: every image as committed" 0 \
  "tests/golden: " "images rendered into $scratch/goldens, 0 changed" \
  "tests/golden/hidden: " "images rendered into $scratch/goldens/hidden, 0 changed" \
  -- rerender --into "$scratch/goldens"
check "a mistyped job is refused" 2 "scripts/instructor.sh rerender" -- rerendr

[ "$failures" -eq 0 ] || { echo "$failures instructor checks failed" >&2; exit 1; }
echo "every instructor check passed"
