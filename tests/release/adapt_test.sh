#!/usr/bin/env bash
# A newcomer's clone, then an instructor's adaptations, and the suite follows (ctest
# adapt_assignment, label "instructor"). In a copy of the checkout under a folder of mode 0700
# (where a newcomer clones: /root or a home folder, which the sandbox's user cannot pass):
#
#  0. the README's main job, scripts/main.sh, from nothing (it configures and builds): it exits
#     0, the solution gets every point and the extra credit, the starter none, and no message
#     blames the submission or "the kit" for what is a folder's mode; then, by the steps of
#     docs/instructor.md's "Adapting the assignment" and nothing else, on the build it made:
#  1. the jobs' refusals: a rubric that does not add up stops before anything is graded, with its
#     line; a mistyped job is refused;
#  2. points: the cloth worth 20 points instead of 12, task 7 counted as regular points (its
#     items renamed), then `scripts/instructor.sh rubric`;
#  3. a new hidden check of task 2 with a rubric item of its own, then
#     `scripts/instructor.sh hidden-check`;
#  4. the cloth_shear scene's springs twice as stiff, then `scripts/instructor.sh rerender`.
#
# Each job must succeed and update the docs it affects (the last one finding every example and
# count already true: the docs' test would pass); re-rendering must change cloth_shear's files
# only. Then the tests an adaptation touches (the rubric, the grading of the solution, the
# golden images and replays) must pass in the copy, unchanged; and re-rendering into a folder of
# its own (`rerender --into`) must change no image.
#
#   adapt_test.sh ROOT WORK
set -uo pipefail
root="$1" work="$2"
rm -rf "$work"
mkdir -p "$work/home"
chmod 0700 "$work/home"
copy="$work/home/a6"
mkdir "$copy"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok:   $*"; }

# The copy: the checkout's files as they are now (committed or not), committed in a git
# repository of its own, so that the jobs can say what they changed.
(cd "$root" && git ls-files -z --cached --others --exclude-standard |
  xargs -0 cp --parents -t "$copy" 2>/dev/null)
(cd "$copy" && git init -q && git add -A &&
  git -c user.name=a6-test -c user.email=a6-test@localhost commit -qm "before the adaptations") ||
  { fail "the copy could not be made a git checkout"; exit 1; }
cd "$copy" || exit 1
export A6_INSTRUCTOR_OUT="$work/out"
unset A6_BUILD_DIR
if [ "$(id -u)" -eq 0 ]; then
  pass "copied $(git ls-files | wc -l) files into $copy (under a folder of mode $(stat -c %a "$work/home"))"
else
  # (Not root: the sandbox runs as this user, whom the folder's mode stops nowhere.)
  echo "note: not root, so the folder's mode 0700 tests nothing here; the rest holds as ever"
fi

# 0. The README's main job, from nothing.
before=$failures
bash scripts/main.sh >"$work/main.log" 2>&1
status=$?
[ "$status" -eq 0 ] || { grep -E '^main:|error' "$work/main.log" | head -20; fail "scripts/main.sh exited $status"; }
score_of() { grep -m1 '"score"' "$1" 2>/dev/null | tr -dc '0-9.'; }
solution=$(score_of out/solution/results.json) starter=$(score_of out/starter/results.json)
# The rubric's points and extra credit as the grader reads them (not pinned: an instructor's
# rubric has its own).
IFS=$'\t' read -r _ points _ extra < <(build/grader/a6_grade --list-items 2>/dev/null | tail -1)
awk -v s="$solution" -v p="${points:-0}" -v e="${extra:-0}" 'BEGIN { exit !(s != "" && s == p + e) }' ||
  fail "main.sh: the solution scored '$solution', not ${points:-?} + ${extra:-0} (the rubric's points and its extra credit)"
points=$(printf '%.2f' "${points:-0}") extra=$(printf '%.2f' "${extra:-0}")
[ "$starter" = "0.0" ] || fail "main.sh: the starter scored '$starter', not 0.0"
grep -q "total *$points / $points *+$extra extra credit" "$work/main.log" ||
  fail "the main job's summary does not give the solution $points / $points + $extra"
for blame in "did not compile" "the grader kit is broken" "Permission denied"; do
  if grep -q "$blame" out/solution/results.json "$work/main.log"; then
    fail "the main job's grading of the solution says '$blame'"
  fi
done
released=$(find out/student-release -type f 2>/dev/null | wc -l)
[ "$released" -gt 100 ] || fail "the student release holds $released files"
entries=$(unzip -Z1 out/gradescope/a6_autograder.zip 2>/dev/null)
grep -qx setup.sh <<<"$entries" || fail "the Gradescope zip has no setup.sh"
[ "$failures" -eq "$before" ] ||
  { echo "$((failures - before)) checks of the main job failed: the adaptations need its build"; exit 1; }
pass "the main job from nothing: solution $solution, starter $starter; release: $released files"

# job NAME ARGS...: runs scripts/instructor.sh ARGS into $work/NAME.log; its exit status.
job() {
  local name="$1"
  shift
  bash scripts/instructor.sh "$@" >"$work/$name.log" 2>&1
}
# says LOG TEXT: the job's log holds TEXT.
says() { grep -qF -- "$2" "$work/$1.log" || fail "$1: the job did not say \"$2\" (log: $work/$1.log)"; }
# lists LOG FILE: the job's list of the files it changed names FILE.
lists() {
  grep -qx -- "  $2" < <(sed -n '/^files this job changed/,/^[^ ]/p' "$work/$1.log") ||
    fail "$1: the job's list of changed files lacks $2 (log: $work/$1.log)"
}
# step_passed BEFORE TEXT: "ok" TEXT when no check failed since the failure count BEFORE.
step_passed() { [ "$failures" -ne "$1" ] || pass "$2"; }
# One rubric item's line (after its name line) set to a value: set_in_item NAME KEY VALUE; or
# deleted: set_in_item NAME KEY "".
set_in_item() {
  NAME="$1" KEY="$2" VALUE="$3" perl -0pi -e '
    s{(name = "\Q$ENV{NAME}\E"\n(?:(?!\[\[item\]\]).*\n)*?)\Q$ENV{KEY}\E = .*\n}
     {$1 . ($ENV{VALUE} eq "" ? "" : "$ENV{KEY} = $ENV{VALUE}\n")}e or die "no $ENV{KEY} in $ENV{NAME}\n"' \
    grader/rubric.toml
}
total() { sed -n 's/^total = \([0-9.]*\).*/\1/p' grader/rubric.toml; }
set_total() { sed -i "s/^total = [0-9.]*/total = $1/" grader/rubric.toml; }
# rename_item OLD NEW: in the rubric and in the guide's table of weights (its step says so).
rename_item() {
  OLD="$1" NEW="$2" perl -pi -e 's/^name = "\Q$ENV{OLD}\E"/name = "$ENV{NEW}"/' grader/rubric.toml
  OLD="$1" NEW="$2" perl -pi -e 's/^\| \Q$ENV{OLD}\E \|/| $ENV{NEW} |/' docs/instructor.md
}

# 1. Refusals ------------------------------------------------------------------------------------
printf 'total = 100\n[[item]]\nname = "all"\ntests = "*"\npoints = 90\n' >"$work/short.toml"
before=$failures
A6_INSTRUCTOR_OUT="$work/short" job short rubric "$work/short.toml"
status=$?
[ "$status" -eq 2 ] || fail "a rubric that does not add up: exit status $status, not 2"
says short "short.toml:1: total = 100 but the items' points add up to 90"
[ ! -e "$work/short" ] || fail "the rubric that does not add up graded something"
job mistyped rerendr
status=$?
[ "$status" -eq 2 ] || fail "a mistyped job: exit status $status, not 2"
says mistyped "scripts/instructor.sh rerender"
step_passed "$before" "refusals: a rubric that does not add up stops at once, with its line; a mistyped job"

# 2. Points and extra credit ---------------------------------------------------------------------
total=$(total)
# What the adaptation adds to the total, from the rubric as it stands: the cloth raised to 20,
# and task 7's extra credit made regular (the guide's "add N to `total`").
listed=$(build/grader/a6_grade --list-items 2>/dev/null)
raise=$(awk -F'\t' '$1 == "Task 4: cloth" { r += 20 - $2 }
  $1 ~ /^Task 7 extra credit: / && $4 == "extra" { r += $2 } END { print r + 0 }' <<<"$listed")
[[ "$raise" =~ ^[0-9]+$ ]] || fail "the rise of the total is '$raise', no whole number"
set_in_item "Task 4: cloth" points 20
for item in "spring Jacobians" "the implicit step"; do
  set_in_item "Task 7 extra credit: $item" extra_credit ""
  rename_item "Task 7 extra credit: $item" "Task 7: $item"
done
set_total $((total + raise))
before=$failures
if job rubric rubric; then
  says rubric "$((total + raise)).00 / $((total + raise)).00"
  says rubric "the starter scores 0"
  says rubric "the docs' examples and counts are true"
  for file in README.md docs/handout.md docs/instructor.md; do lists rubric "$file"; done
  step_passed "$before" "points: the cloth worth 20, task 7 regular; the rubric job graded, updated and listed the docs"
else
  fail "the rubric job failed:"$'\n'"$(tail -30 "$work/rubric.log")"
fi

# 3. A new hidden check with its own item -------------------------------------------------------
cat >>tests/hidden/hidden_test.cpp <<'CPP'

namespace a6::test {
namespace {

// Added by an instructor: drag on random velocities alone.
TEST(Task2Hidden, DragOpposesRandomVelocities) {
  Draw draw;
  for (int k = 0; k < 50; ++k) {
    harness::ForcesRequest r;
    r.particle.m = draw.uniform(0.01, 5);
    r.particle.v = draw.vec(4);
    r.env.drag = draw.uniform(0.1, 2);
    const harness::ForcesResult result = student().ask(r);
    A6_ASSERT_RAN(result);
    ASSERT_VEC_NEAR(result.drag, Vec2(-r.env.drag * r.particle.v),
                    relativeTo(r.env.drag * r.particle.v.norm()))
        << "input: v=" << str(r.particle.v) << ", k_d=" << r.env.drag << draw.seed()
        << hint("drag is -k_d v");
  }
}

}  // namespace
}  // namespace a6::test
CPP
NAME="Task 2: hidden checks (random particles and environments)" perl -0pi -e '
  s{(\[\[item\]\]\nname = "\Q$ENV{NAME}\E")}
   {[[item]]\nname = "Task 2: hidden drag check"\ntask = 2\ntests = "Task2Hidden.DragOpposesRandomVelocities"\npoints = 2\nvisibility = "after_due_date"\n\n$1} or die' \
  grader/rubric.toml
set_total $((total + raise + 2))
perl -pi -e 'print "| Task 2: hidden drag check | 2 | 1 | drag alone on random velocities |\n"
  if /^\| Task 2: hidden checks \(random particles/' docs/instructor.md
before=$failures
if job hidden hidden-check; then
  says hidden "new since the last commit: Task2Hidden.DragOpposesRandomVelocities"
  says hidden "Task2Hidden.DragOpposesRandomVelocities  ->  Task 2: hidden drag check"
  says hidden "the starter fails every one"
  says hidden "the docs' examples and counts are true"
  lists hidden docs/instructor.md  # "all N checks"
  step_passed "$before" "a hidden check: named as new, counted by its item, solution passes, starter fails"
else
  fail "the hidden-check job failed:"$'\n'"$(tail -30 "$work/hidden.log")"
fi

# 4. A scene's constant --------------------------------------------------------------------------
perl -0pi -e 's{("cloth_shear".*?)clothParams\(true, false\)}
  {$1\[\] { SceneParams p = clothParams(true, false); p.ks *= 2; return p; }()}s or die' \
  framework/scenes/mass_spring_scenes.cpp
git add -A && git -c user.name=a6-test -c user.email=a6-test@localhost commit -qm "adaptations 1 and 2, the scene's source"
before=$failures
scenes=$(find tests/golden/replays -name '*.json' | wc -l)
if job rerender rerender; then
  says rerender "changed: cloth_shear"
  says rerender "1 written to tests/golden/replays, $((scenes - 1)) the same run as committed"
  # The docs the first two jobs rewrote, compared afresh: what the docs' test, docs_examples,
  # compares.
  says rerender "every example and count was already true"
  changed=$(git status --porcelain -- tests/golden | awk '{ print $2 }')
  others=$(grep -v 'cloth_shear' <<<"$changed")
  [ -n "$changed" ] || fail "re-rendering changed no file of tests/golden"
  [ -z "$others" ] || fail "re-rendering changed files of untouched scenes:"$'\n'"$others"
  grep -q 'replays/cloth_shear.json' <<<"$changed" || fail "the cloth_shear replay was not written"
  for file in $changed; do lists rerender "$file"; done
  step_passed "$before" "a scene: re-rendered, only cloth_shear's files changed: $(tr '\n' ' ' <<<"$changed")"
else
  fail "the rerender job failed:"$'\n'"$(tail -30 "$work/rerender.log")"
fi

# The tests an adaptation touches, unchanged, in the copy: the golden tests (re-rendering built
# them), the rubric's and the grading's tests on the new rubric. (The scores tests' program links
# every wrong version's grader, the slowest build of all: the rubric job above graded the
# solution and the starter with the new rubric already. The docs' test, docs_examples, would
# compare what the last job's docs step compared on these same files, above.)
if ctest --preset default --no-tests=error -L golden >"$work/golden.log" 2>&1 &&
  cmake --build --preset default --target a6_grade_test a6_rubric_test >"$work/tests_build.log" 2>&1 &&
  ctest --preset default --no-tests=error -R '^(grader_rubric|grader_grade_.*)$' >"$work/tests.log" 2>&1; then
  pass "the affected tests pass: $(grep -h 'tests passed' "$work/golden.log" "$work/tests.log" | tr '\n' ' ')"
else
  fail "tests failed after the adaptations:"$'\n'"$(grep -h -E 'tests passed|\(Failed\)|Timeout' "$work/golden.log" "$work/tests.log")"
fi

# 5. Re-rendering into a folder of its own: every image as the copy holds it now.
before=$failures
golden_state=$(git status --porcelain -- tests/golden)
if job into rerender --into "$work/goldens"; then
  says into "images rendered into $work/goldens, 0 changed"
  says into "images rendered into $work/goldens/hidden, 0 changed"
  [ "$(git status --porcelain -- tests/golden)" = "$golden_state" ] || fail "rerender --into changed tests/golden"
  step_passed "$before" "re-rendering into a folder of its own: every image as the copy holds it"
else
  fail "rerender --into failed:"$'\n'"$(tail -30 "$work/into.log")"
fi

[ "$failures" -eq 0 ] || { echo "$failures checks failed"; exit 1; }
echo "the main job, the adaptations and the suite after them: all true"
