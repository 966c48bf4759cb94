#!/usr/bin/env bash
# No decision reads the words of a message: the submissions we keep (below) are graded twice,
# once as usual and once with A6_REWORD_MESSAGES=1, which prefixes every message of a failed request
# with "[reworded] " (grader/probe/probe_client.h, reworded()). The score and each item's
# points and status must be the same both times, and the reworded messages must show the
# prefix (so the switch did reword them). The grader's seed and a rubric with 2-s time limits
# are the same for both.
#
#   tests/grader/reword_test.sh SOURCE_DIR A6_GRADE OUT_DIR
# Exit code: 0 when nothing changed, 1 otherwise (each difference named).
set -uo pipefail
root="$1" grade="$2" out="$3"
rm -rf "$out" && mkdir -p "$out" && chmod 755 "$out"
# The grader's rubric with every time limit cut to 2 s (the correct checks take a few hundredths
# each), so that the endless loops cost seconds, not minutes.
sed -E 's/^time_limit = [0-9.]+/time_limit = 2/' "$root/grader/rubric.toml" >"$out/rubric.toml"
# The cases: the submissions whose requests fail (they crash, throw, loop, flood, answer
# garbage or fail to start), where words were once read, each with the checks it needs. Correct
# code and the wrong versions fail no request, so nothing of theirs can be reworded: they are not
# graded here. Every case must show the prefix in its reworded report (so each one proves
# something). Each case runs the checks where its file fails: every case but one breaks
# spring.cpp, whose failures show in task 1's checks (both probes: task 3's first checks start
# the probe with the reference forces, which a static initializer's exit or abort breaks too);
# the same decisions decide every other check. The two loops run only two checks each, of task 1
# (computeForce loops) and of task 3 (the stepper asks for forces without end): each looping
# check costs its time limit twice (a time-out is run again), so their whole tasks would take
# minutes for the same decisions. wide_answer runs two of task 1 too: its computeForce answers
# 4 MiB of garbage, a second of parsing in each check, and task 3's checks never call it.
spring="Task1*:Task3TimeStepping.OneStep*"
two_of_task1="Task1Spring.AtRest*:Task1Spring.Stretched*"
cases=("exit_in_code:$spring" "segfault:$spring" "garbage_on_answer_pipe:$spring"
       "wide_answer:$two_of_task1" "huge_answer:$spring" "huge_alloc:$spring" "exception:$spring"
       "static_exit:$spring" "static_abort:$spring"
       "infinite_loop:$two_of_task1"
       "endless_forces:Task3TimeStepping.OneStep*:Task3TimeStepping.WithoutForces*")

# grade_one NAME:FILTER MODE: the fixture NAME graded into $out/MODE/NAME (only the checks of
# FILTER, when given); its scores in $out/MODE/NAME.scores.
grade_one() {
  local name=${1%%:*} filter=${1#*:} mode=$2
  mkdir -p "$out/$mode"
  A6_REWORD_MESSAGES=$([ "$mode" = reworded ] && echo 1 || echo 0) \
    "$grade" "$root/tests/grader/submissions/$name" --out "$out/$mode/$name" \
    --rubric "$out/rubric.toml" --seed 7 --jobs 1 --quiet ${filter:+--tests "$filter"} \
    >"$out/$mode/$name.log" 2>&1
  # The points only: the status of a 0-point item (a sanity check) of a submission that floods
  # or stalls its probe may change with the machine's load, its points cannot.
  jq -r '"score \(.score)", (.tests[] | "\(.number) \(.score)")' \
    "$out/$mode/$name/results.json" >"$out/$mode/$name.scores" 2>/dev/null ||
    echo "no results.json" >"$out/$mode/$name.scores"
}
export -f grade_one
export out grade root
start=$(date +%s)
for c in "${cases[@]}"; do printf '%s\0%s\0' "$c" plain "$c" reworded; done |
  xargs -0 -n 2 -P 2 bash -c 'grade_one "$0" "$1"'

changed=0
for f in "$out"/plain/*.scores; do
  name=$(basename "$f")
  if ! diff -q "$f" "$out/reworded/$name" >/dev/null; then
    echo "CHANGED by rewording: ${name%.scores}"
    diff "$f" "$out/reworded/$name" | head -10
    changed=$((changed + 1))
  fi
done
prefixed=$(grep -l '\[reworded\]' "$out"/reworded/*/results.json 2>/dev/null | wc -l)
plain_prefixed=$(grep -l '\[reworded\]' "$out"/plain/*/results.json 2>/dev/null | wc -l)
echo "${#cases[@]} submissions graded twice in $(($(date +%s) - start)) s; $changed changed;" \
  "$prefixed reworded reports show the prefix, $plain_prefixed plain ones do"
[ "$changed" -eq 0 ] || { echo "FAIL: a decision read the words of a message"; exit 1; }
for c in "${cases[@]}"; do
  grep -q '\[reworded\]' "$out/reworded/${c%%:*}/results.json" 2>/dev/null ||
    { echo "FAIL: ${c%%:*}: no message was reworded, so its case proves nothing"; exit 1; }
done
[ "$plain_prefixed" -eq 0 ] || { echo "FAIL: reports were reworded without the switch"; exit 1; }
echo "PASS: no score or item changed with every message reworded"
