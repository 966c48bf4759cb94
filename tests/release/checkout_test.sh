#!/usr/bin/env bash
# The main job from a checkout in a folder of mode 0700, as root (ctest main_job_from_checkout_0700,
# label "packaging"): where a newcomer clones the project, /root or a home folder, the sandbox's
# user cannot pass that folder, and the grader must still give it what it needs.
#
#   checkout_test.sh ROOT WORK
#
#  1. copies the checkout ROOT (its files that git tracks or would track; everything when ROOT
#     is no git checkout) into WORK/home/a6, WORK/home being of mode 0700;
#  2. runs the README's main job there, scripts/main.sh (a whole build: with ccache the compiler
#     answers from the cache of ROOT's build);
#  3. checks: it exits 0; the solution gets every point and the extra credit, the starter none;
#     no message blames the submission or "the kit" for what is a folder's mode.
# Exits 77 (ctest: skipped) when not root: the sandbox then runs as the same user and the folder's
# mode stops nobody.
set -uo pipefail
root="$1" work="$2"
if [ "$(id -u)" -ne 0 ]; then
  echo "checkout test: not root, so there is no sandbox user for the folder's mode to stop: skipped"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/home"
chmod 0700 "$work/home"
checkout="$work/home/a6"
mkdir "$checkout"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok:   $*"; }
start=$(date +%s)

# 1. The copy: a git checkout of its own (the release and the Gradescope zip are taken from git),
# holding the files as they are now, committed or not.
if git -C "$root" rev-parse --git-dir >/dev/null 2>&1; then
  (cd "$root" && git ls-files -z --cached --others --exclude-standard |
    xargs -0 cp --parents -t "$checkout" 2>/dev/null)
else
  tar -C "$root" --exclude=./build --exclude='./build-*' --exclude=./out -cf - . |
    tar -C "$checkout" -xf -
fi
(cd "$checkout" && git init -q && git add -A &&
  git -c user.name=a6-test -c user.email=a6-test@localhost commit -qm "the checkout test's copy") ||
  fail "the copy could not be made a git checkout"
[ -x "$checkout/scripts/main.sh" ] || { fail "the copy has no scripts/main.sh"; exit 1; }
pass "copied $(git -C "$checkout" ls-files | wc -l) files into $checkout (under a folder of mode $(stat -c %a "$work/home"))"

# 2. The main job.
cd "$checkout" || exit 1
bash scripts/main.sh >"$work/main.log" 2>&1
status=$?
echo "      scripts/main.sh: exit $status after $(( $(date +%s) - start )) s (log: $work/main.log)"

# 3. What it said and wrote.
[ "$status" -eq 0 ] || { grep -E '^main:|error' "$work/main.log" | head -20; fail "scripts/main.sh exited $status"; }
score_of() { grep -m1 '"score"' "$1" 2>/dev/null | tr -dc '0-9.'; }
solution=$(score_of out/solution/results.json) starter=$(score_of out/starter/results.json)
# The rubric's points and extra credit as the grader reads them (not pinned: an instructor's
# rubric has its own).
IFS=$'\t' read -r _ points _ extra < <(build/grader/a6_grade --list-items 2>/dev/null | tail -1)
awk -v s="$solution" -v p="${points:-0}" -v e="${extra:-0}" 'BEGIN { exit !(s != "" && s == p + e) }' ||
  fail "the solution scored '$solution', not ${points:-?} + ${extra:-0} (the rubric's points and its extra credit)"
points=$(printf '%.2f' "${points:-0}") extra=$(printf '%.2f' "${extra:-0}")
[ "$starter" = "0.0" ] || fail "the starter scored '$starter', not 0.0"
grep -q "total *$points / $points *+$extra extra credit" "$work/main.log" ||
  fail "the main job's summary does not give the solution $points / $points + $extra"
for blame in "did not compile" "the grader kit is broken" "Permission denied"; do
  if grep -q "$blame" out/solution/results.json "$work/main.log"; then
    fail "the solution's grading says '$blame'"
  fi
done
released=$(find out/student-release -type f 2>/dev/null | wc -l)
[ "$released" -gt 100 ] || fail "the student release holds $released files"
entries=$(unzip -Z1 out/gradescope/a6_autograder.zip 2>/dev/null)
grep -qx setup.sh <<<"$entries" || fail "the Gradescope zip has no setup.sh"
pass "from a checkout under a 0700 folder: solution $solution, starter $starter; release: $released files"

echo "checkout test: $failures failure(s) in $(( $(date +%s) - start )) s"
[ "$failures" -eq 0 ]
