#!/usr/bin/env bash
# An instructor adapts the assignment, and the suite follows (ctest adapt_assignment, label
# "instructor"). In a copy of the checkout, three adaptations, each by the steps of
# docs/instructor.md's "Adapting the assignment" and nothing else:
#
#  1. points: the cloth worth 20 points instead of 12, task 7 counted as regular points (its
#     items renamed), then `scripts/instructor.sh rubric`;
#  2. a new hidden check of task 2 with a rubric item of its own, then
#     `scripts/instructor.sh hidden-check`;
#  3. the cloth_shear scene's springs twice as stiff, then `scripts/instructor.sh rerender`.
#
# Each job must succeed and update the docs it affects; re-rendering must change cloth_shear's
# files only. Then the tests an adaptation touches (the rubric, the grading of the solution, the
# golden images and replays, the docs) must pass in the copy, unchanged.
#
#   adapt_test.sh ROOT WORK
set -uo pipefail
root="$1" work="$2"
rm -rf "$work"
mkdir -p "$work"
copy="$work/a6"
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
# Configured only: each job builds what it needs, as it would in a fresh checkout (the last one,
# re-rendering, builds everything).
if ! cmake --preset default >"$work/configure.log" 2>&1; then
  tail -20 "$work/configure.log"
  fail "the copy cannot be configured"
  exit 1
fi
pass "the copy is configured"

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
  sed -n '/^files this job changed/,/^[^ ]/p' "$work/$1.log" | grep -qx -- "  $2" ||
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

# 1. Points and extra credit ---------------------------------------------------------------------
total=$(total)
set_in_item "Task 4: cloth" points 20
for item in "spring Jacobians" "the implicit step"; do
  set_in_item "Task 7 extra credit: $item" extra_credit ""
  rename_item "Task 7 extra credit: $item" "Task 7: $item"
done
set_total $((total + 8 + 10))
before=$failures
if job rubric rubric; then
  says rubric "$((total + 18)).00 / $((total + 18)).00"
  says rubric "the starter scores 0"
  says rubric "the docs' examples and counts are true"
  for file in README.md docs/handout.md docs/instructor.md; do lists rubric "$file"; done
  step_passed "$before" "points: the cloth worth 20, task 7 regular; the rubric job graded, updated and listed the docs"
else
  fail "the rubric job failed:"$'\n'"$(tail -30 "$work/rubric.log")"
fi

# 2. A new hidden check with its own item -------------------------------------------------------
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
set_total $((total + 20))
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

# 3. A scene's constant --------------------------------------------------------------------------
perl -0pi -e 's{("cloth_shear".*?)clothParams\(true, false\)}
  {$1\[\] { SceneParams p = clothParams(true, false); p.ks *= 2; return p; }()}s or die' \
  framework/scenes/mass_spring_scenes.cpp
git add -A && git -c user.name=a6-test -c user.email=a6-test@localhost commit -qm "adaptations 1 and 2, the scene's source"
before=$failures
scenes=$(find tests/golden/replays -name '*.json' | wc -l)
if job rerender rerender; then
  says rerender "changed: cloth_shear"
  says rerender "1 written to tests/golden/replays, $((scenes - 1)) the same run as committed"
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
# them), the rubric's and the grading's tests on the new rubric, the docs. (The scores tests'
# program links every wrong version's grader, the slowest build of all: the rubric job above
# graded the solution and the starter with the new rubric already; the docs' example of a wrong
# spring is the grading its update_docs made, not that test's.)
if ctest --preset default --no-tests=error -L golden >"$work/golden.log" 2>&1 &&
  cmake --build --preset default --target a6_grade_test a6_rubric_test >"$work/tests_build.log" 2>&1 &&
  ctest --preset default --no-tests=error -R '^(grader_rubric|grader_grade_.*|docs_examples)$' \
    -FS graded_t1_wrong_sign >"$work/tests.log" 2>&1; then
  pass "the affected tests pass: $(grep -h 'tests passed' "$work/golden.log" "$work/tests.log" | tr '\n' ' ')"
else
  fail "tests failed after the adaptations:"$'\n'"$(grep -h -E 'tests passed|\(Failed\)|Timeout' "$work/golden.log" "$work/tests.log")"
fi

[ "$failures" -eq 0 ] || { echo "$failures adaptation checks failed"; exit 1; }
echo "the three adaptations and the suite after them: all true"
