#!/usr/bin/env bash
# The student release, end to end (ctest release_student, label "packaging"):
#
#   student_release_test.sh ROOT A6_GRADE WORK [GRADED_CLOTH]
#
#  1. exports it (grader/release/export-student.sh) into the student's home folder (mode 0700,
#     WORK/home, or a folder in /tmp when the checkout's folders let no other user through),
#     owned by the student: run as root, a user of their own (below) runs steps 3 and 4;
#  2. checks what is in it against the instructor guide's list and what is not, that every guide
#     and command it names is in it, and scans it for solution text on its own terms (every line
#     of solution/*.cpp of 25+ characters that the starter does not have);
#  3. follows its README from scratch: scripts/install-deps.sh (nothing to install here), then
#     the test command, scripts/test.sh, which must build and then fail clearly on the starter:
#     every task's physics tests fail, the summary says where to look and is the README's;
#  4. runs scripts/check.sh (the local check): the starter gets 0 of the public points, a
#     finished solution all of them, and a wrong cloth the same score per public rubric item as
#     the graders' grading gives it (GRADED_CLOTH: its results.json from the fairness test
#     wrong_t4_shear_with_structural_rest_length; without it, a6_grade grades the cloth here);
#  5. runs the commands of the GitHub Classroom workflow: they exist and the task steps fail on
#     the starter.
set -uo pipefail
root="$1" grade="$2" work="$3" graded_cloth="${4:-}"
rm -rf "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok:   $*"; }
start=$(date +%s)

# The student: a user of their own, not root (a uid with no account and no process here), whose
# home folder (mode 0700) holds the release. Run as root (CI), the student's steps below run as
# that user; run as a normal user, they run as that user, whoever it is.
as_student() { "$@"; }
home="$work/home"
if [ "$(id -u)" -eq 0 ]; then
  source "$root/scripts/student-user.sh"
  student=$(free_student_uid 4100 4199) ||
    { echo "FAIL: no free uid in 4100..4199 for the student"; exit 1; }
  # The student's home must be reachable by that user: under the build folder when its parents
  # let every user through, else (a checkout in root's home, mode 0700) a folder in /tmp.
  # Whatever the student's steps left running (the release's desktop test, killed by its own
  # time-out on a loaded machine, leaves its Xvfb and VNC server) ends with this test: the uid
  # had no process when it was chosen, so every process of it is this test's.
  scratch=""
  trap 'end_student_processes "$student"; [ -z "$scratch" ] || rm -rf "$scratch"' EXIT
  mkdir -p "$work"
  if ! setpriv --reuid="$student" --regid="$student" --clear-groups test -x "$work"; then
    home=$(mktemp -d /tmp/a6-student-home.XXXXXX)
    scratch=$home
  fi
  # The student's compiler cache: the machine's, like root's own (~/.cache/ccache), in a folder
  # only that uid owns, so that a second run here compiles what changed, not the release again.
  # A new one starts with links to what root's build compiled (on a fresh CI machine the release
  # would otherwise be compiled from nothing: 330 s instead of about 60);
  # scripts/bench-first-hour.sh times a fresh account's first check, with an empty cache.
  cache="/var/tmp/a6-student-ccache-$student"
  if [ ! -e "$cache" ] && [ ! -L "$cache" ]; then
    mkdir -m 0700 "$cache" && chown "$student:$student" "$cache" &&
      seed_student_cache "$student" "$cache"
  fi
  if [ -L "$cache" ] || [ ! -d "$cache" ] || [ "$(stat -c %u "$cache")" != "$student" ]; then
    cache="$home/.cache/ccache"  # another's folder, or a link: never used
  fi
  as_student() { run_as_student "$student" "$home" "$cache" "$@"; }
fi
mkdir -p "$home"
chmod 0700 "$home"
release="$home/release"
give_student() { [ -z "${student:-}" ] || chown -R "$student:$student" "$@"; }

# 1. Export.
if ! A6_GRADE="$grade" bash "$root/grader/release/export-student.sh" "$release" >"$work/export.log" 2>&1; then
  cat "$work/export.log"
  fail "the export failed"
  exit 1
fi
pass "exported: $(tail -1 "$work/export.log")"
# Unzipped by the student: their files.
give_student "$home"

# 2. Contents.
for absent in solution tests/hidden tests/golden/hidden tests/golden/replays \
              grader/reference grader/mistakes/library tests/wrong tests/grader docs/instructor.md scripts/main.sh .ci; do
  [ -e "$release/$absent" ] && fail "$absent is in the release"
done
for present in README.md scripts/install-deps.sh scripts/test.sh scripts/check.sh \
               docs/handout.md docs/viewer.md framework/viewer/main.cpp tests/support/own_models.inc \
               tests/golden/manifest.json .github/workflows/classroom.yml grader/rubric.toml; do
  [ -e "$release/$present" ] || fail "$present is missing from the release"
done
starters=$(ls "$release"/starter/*.cpp 2>/dev/null | wc -l)
[ "$starters" -eq 7 ] || fail "the release has $starters starter files, not 7"
for f in "$root"/starter/*.cpp; do
  cmp -s "$f" "$release/starter/$(basename "$f")" || fail "starter/$(basename "$f") differs from the starter"
done
pngs=$(ls "$release"/tests/golden/*.png | wc -l)
public_pngs=$(ls "$root"/tests/golden/*.png | wc -l)
[ "$pngs" -eq "$public_pngs" ] || fail "$pngs reference images in the release, $public_pngs public ones"
grep -q 'Hidden' "$release/grader/rubric.toml" && fail "the release's rubric names hidden checks"
grep -q '^total = [0-9]' "$release/grader/rubric.toml" || fail "the public rubric states no total"
pass "contents: 7 starter files, $pngs reference images, public rubric"

# Exactly the list in the instructor guide ("The student release"): each committed file its
# entries select, and the four the export writes; nothing else, and no entry that selects nothing.
before=$failures
listed=$(awk '/<!-- release-contents/ { on = 1; next } on && /^```/ { if (++fences == 2) exit; next }
              on && fences == 1' "$root/docs/instructor.md" | sed 's/#.*//' | tr -s ' \t' '\n\n' |
         grep .)
[ "$(echo "$listed" | wc -l)" -gt 20 ] || fail "the instructor guide's release list is missing"
selects() {  # selects ENTRY PATH
  case "$1" in */) [[ "$2" == "$1"* ]] ;; *) [ "$2" = "$1" ] ;; esac
}
git -C "$root" ls-files >"$work/committed"
for extra in README.md grader/rubric.toml .github/workflows/classroom.yml RELEASE; do
  echo "$extra" >>"$work/committed"
done
: >"$work/expected"
while IFS= read -r path; do
  verdict=no
  while IFS= read -r entry; do
    case "$entry" in '!'*) selects "${entry#!}" "$path" && verdict=no ;;
                     *) selects "$entry" "$path" && verdict=yes ;; esac
  done <<<"$listed"
  [ "$verdict" = yes ] && echo "$path" >>"$work/expected"
done <"$work/committed"
sort -u -o "$work/expected" "$work/expected"
(cd "$release" && find . -type f | sed 's|^\./||' | sort) >"$work/released"
while IFS= read -r path; do fail "$path is in the release but not in the guide's list"
done < <(comm -13 "$work/expected" "$work/released")
while IFS= read -r path; do fail "$path is in the guide's list but not in the release"
done < <(comm -23 "$work/expected" "$work/released")
while IFS= read -r entry; do
  grep -q . < <(while IFS= read -r path; do selects "${entry#!}" "$path" && echo "$path"; done \
                  <"$work/committed") || fail "the guide's release entry $entry selects no file"
done <<<"$listed"
[ "$failures" -eq "$before" ] &&
  pass "the release's $(wc -l <"$work/released") files are the instructor guide's list"

# No link to a guide or command the release lacks: the .md and .sh files its guides, workflow and
# container name.
before=$failures
while IFS=: read -r file target; do
  [ -e "$release/$target" ] || fail "$file names $target, which the release lacks"
done < <(cd "$release" && grep -roE --include='*.md' --include='*.yml' --include='*.json' \
           '(docs|scripts|grader|tests|framework|starter|cmake)/[A-Za-z0-9_./-]*\.(md|sh)\b' . |
         sed 's|^\./||' | sort -u)
[ "$failures" -eq "$before" ] &&
  pass "every guide and command the release's guides, workflow and container name is in it"

# The scan, written differently from scan-release.sh: the solution's statements (lines ending in
# ';', 25+ characters, not comments; loop and block headers such as "for (int j = 0; j <= n; ++j) {"
# are in any grid code) that the starter lacks, matched as whole lines, blanks trimmed.
grep -hv '^[[:space:]]*//' "$root"/solution/*.cpp | sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' |
  awk 'length($0) >= 25 && /;$/' | sort -u >"$work/solution_lines"
sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' "$root"/starter/*.cpp | sort -u >"$work/starter_lines"
comm -23 "$work/solution_lines" "$work/starter_lines" >"$work/needles"
needles=$(wc -l <"$work/needles")
[ "$needles" -gt 30 ] || fail "only $needles solution lines to look for"
if hits=$(find "$release" -type f -exec grep -IlF -f "$work/needles" {} + |
           while IFS= read -r f; do
             sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' "$f" | grep -nFx -f "$work/needles" |
               sed "s|^|${f#"$release"/}:|"
           done | grep .); then
  fail "solution text in the release:"
  echo "$hits" | head -20
else
  pass "no line of the solution ($needles looked for) in $(find "$release" -type f | wc -l) files"
fi

# 3. The README's commands, from scratch.
cd "$release" || exit 1
readme_commands=$(sed -n '/^```sh/,/^```/p' README.md | head -4)
echo "$readme_commands" | grep -q 'scripts/install-deps.sh && scripts/check.sh' ||
  fail "README does not open with scripts/install-deps.sh && scripts/check.sh"
echo "$readme_commands" | grep -q '^scripts/test.sh' || fail "README's second command is not scripts/test.sh"
bash scripts/install-deps.sh >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "install-deps failed"; }
build_start=$(date +%s)
as_student bash scripts/test.sh >"$work/test.log" 2>&1
test_status=$?
echo "      scripts/test.sh: exit $test_status after $(( $(date +%s) - build_start )) s"
if ! grep -q 'Build files have been written' "$work/test.log" || ! grep -q 'tests passed' "$work/test.log"; then
  tail -30 "$work/test.log"
  fail "scripts/test.sh did not build and run the tests"
fi
[ "$test_status" -ne 0 ] || fail "scripts/test.sh passed on the starter: its tests must fail"
# The whole suite's summary (the per-task entries Task1..Task7 print one each too): the line
# with the most failing tasks.
summary=$(grep '^A6-SUMMARY' "$work/test.log" | awk '{n = 0; for (i = 2; i <= NF; i++) {
  split($i, a, ":"); if (a[3] > 0) n++ } if (n > best) { best = n; line = $0 } } END { print line }')
if [ -z "$summary" ]; then
  fail "the physics tests printed no per-task summary"
else
  for t in 1 2 3 4 5 6 7; do
    failed=$(echo "$summary" | tr ' ' '\n' | grep "^$t:" | cut -d: -f3)
    [ "${failed:-0}" -gt 0 ] || fail "task $t: no failing test on the starter ($summary)"
  done
  [ "$(grep -c 'look here' "$work/test.log")" -ge 7 ] || fail "the summary does not point at every task"
  # The README shows this summary as the student will see it.
  sed -n '/^Summary by task$/,/^A6-SUMMARY/p' "$work/test.log" | grep -B8 -Fx "$summary" |
    sed -n '/^Summary by task$/,$p' | sed '$d' >"$work/summary_seen"
  awk '/<!-- example: student-summary -->/ { on = 1; next } on && /^```/ { if (++fences == 2) exit; next }
       on && fences == 1' README.md >"$work/summary_shown"
  diff -u "$work/summary_shown" "$work/summary_seen" >"$work/summary.diff" ||
    { cat "$work/summary.diff"; fail "the README's summary (-) is not what scripts/test.sh printed (+)"; }
  pass "scripts/test.sh fails clearly on the starter: $summary"
fi
grep -q 'Failed.*physics' "$work/test.log" || grep -q 'physics.*Failed' "$work/test.log" ||
  fail "ctest does not list the physics tests as failed"
# Only the tests of the student's code fail on the starter: the physics, its images, the desktop
# view of them. A test of the framework alone (image comparison, messages, the viewer's options)
# passes whoever runs it: it must not trip over what another user's run left behind.
failed=$(sed -n '/The following tests FAILED/,$p' "$work/test.log" |
         sed -n 's/^[[:space:]]*[0-9]* - \([A-Za-z0-9_-]*\) (.*/\1/p')
unexpected=$(grep -vxE 'physics|Task[1-7]|golden|viewer_desktop_in_browser' <<<"$failed")
[ -z "$unexpected" ] || fail "tests of the framework alone failed on the starter: $(tr '\n' ' ' <<<"$unexpected")"
# The desktop test stops at its first look when the code draws nothing (no retry can pass).
grep -q 'the code draws nothing' "$work/test.log" && ! grep -q '^attempt [0-9]' "$work/test.log" ||
  fail "the desktop test did not stop at once on the starter's blank scene"

# The starter files' "Done when" commands: `ctest -R Task1` (the README's form: with the preset)
# runs task 1's checks, only those, and fails on the starter, printing at most 200 lines; the
# same from the build folder; a pattern that matches no test fails too.
as_student ctest --preset default -R Task1 --output-on-failure >"$work/task1.log" 2>&1 &&
  fail "ctest --preset default -R Task1 passed on the starter"
grep -q 'Task1Spring\.' "$work/task1.log" || fail "ctest -R Task1 ran no task-1 check"
! grep -q 'Task2Forces\.' "$work/task1.log" || fail "ctest -R Task1 ran task 2's checks too"
[ "$(wc -l <"$work/task1.log")" -le 230 ] ||
  fail "ctest -R Task1 printed $(wc -l <"$work/task1.log") lines on the starter"
(cd build && as_student ctest -R Task1 >"$work/task1_in_build.log" 2>&1) &&
  fail "ctest -R Task1 in build/ passed on the starter"
grep -q 'Task1 .*Failed' "$work/task1_in_build.log" || fail "ctest -R Task1 in build/ ran no Task1"
# The README's own example of a pattern that matches no test.
nomatch=$(sed -n 's/.*a pattern that matches no test (`-R \([A-Za-z0-9]*\)`.*/\1/p' README.md)
[ -n "$nomatch" ] || fail "the README names no pattern that matches no test"
as_student ctest --preset default -R "${nomatch:-NoSuchTest}" >"$work/none.log" 2>&1 &&
  fail "ctest --preset default -R ${nomatch:-NoSuchTest} passed: a run that matches no test must fail"
pass "ctest -R Task1 runs task 1's checks and fails on the starter; no match fails"

# 4. The local check.
score_of() { grep -m1 '"score"' "$1" | tr -dc '0-9.'; }
as_student bash scripts/check.sh >"$work/check_starter.log" 2>&1 || { cat "$work/check_starter.log"; fail "scripts/check.sh failed on the starter"; }
[ -s out/check/report.html ] || fail "no out/check/report.html"
[ "$(score_of out/check/results.json)" = "0.0" ] ||
  fail "the starter scored $(score_of out/check/results.json) in the local check"
# The public rubric's points and extra credit, as the release's own grader reads them (an
# instructor's rubric has its own: the test reads them, it does not pin them).
IFS=$'\t' read -r _ points _ extra < <(build/grader/a6_grade --list-items --rubric grader/rubric.toml 2>&1 | tail -1)
[ -n "$points" ] || fail "a6_grade --list-items on the public rubric gives no total"
points=$(printf '%.2f' "${points:-0}") extra=$(printf '%.2f' "${extra:-0}")
grep -q "total *0.00 / $points" "$work/check_starter.log" ||
  fail "check.sh's summary does not say 0 / $points"
# As a normal user, one line says the code ran without the grader's sandbox, with no advice.
unsandboxed=$(grep -c 'not running as root' "$work/check_starter.log")
[ "$unsandboxed" -le 1 ] || fail "check.sh printed $unsandboxed lines about not running as root"
! grep -q 'chmod' "$work/check_starter.log" || fail "check.sh advises a chmod"
pass "scripts/check.sh on the starter: 0 / $points, report.html written, $unsandboxed line on root"

mkdir -p "$home/finished"
cp "$root"/solution/*.cpp "$home/finished/"
give_student "$home/finished"
as_student bash scripts/check.sh "$home/finished" >"$work/check_solution.log" 2>&1
grep -q "total *$points / $points *+$extra extra credit" "$work/check_solution.log" ||
  { tail -5 "$work/check_solution.log"; fail "a finished submission does not get $points / $points + $extra in the local check"; }
pass "scripts/check.sh on a finished submission: $(grep -m1 'total ' "$work/check_solution.log" | tr -s ' ')"

# A wrong cloth: the local check and the graders' a6_grade agree item by item on the public items.
mkdir -p "$home/wrong"
cp "$root"/solution/*.cpp "$home/wrong/"
cp "${A6_VARIANTS:?BUILD/variants, set by ctest}"/wrong/t4_shear_with_structural_rest_length/cloth.cpp \
  "$home/wrong/"
give_student "$home/wrong"
as_student bash scripts/check.sh "$home/wrong" >"$work/check_wrong.log" 2>&1
cp out/check/results.json "$work/local.json"
# The graders' grading of the same files: the one the fairness tests made (wrong_<name>), or
# a6_grade's here when the test runs without it.
if [ -f "$graded_cloth" ]; then
  mkdir -p "$work/graders" && cp "$graded_cloth" "$work/graders/results.json"
else
  "$grade" "$home/wrong" --out "$work/graders" --quiet >"$work/graders.log" 2>&1
fi
# The score of the results.json test whose name starts with "$2 (" (a6_grade writes one field
# per line; the name comes before the score).
item_score() {
  awk -v want="\"name\": \"$2 (" 'index($0, want) { found = 1 }
    found && /"score":/ { gsub(/[^0-9.]/, ""); print; exit }' "$1"
}
for name in "Task 4: cloth" "Task 4: sanity checks" "Task 1: spring force" "Task 3: time stepping"; do
  l=$(item_score "$work/local.json" "$name")
  g=$(item_score "$work/graders/results.json" "$name")
  [ -n "$l" ] && [ "$l" = "$g" ] || fail "item '$name': local check '$l', grader '$g'"
done
lost=$(item_score "$work/local.json" "Task 4: cloth")
cloth=$(build/grader/a6_grade --list-items --rubric grader/rubric.toml 2>&1 |
  awk -F'\t' '$1 == "Task 4: cloth" { print $2; exit }')
[ -n "$cloth" ] || fail "the public rubric has no item 'Task 4: cloth'"
awk -v got="$lost" -v worth="$cloth" 'BEGIN { exit !(got != "" && got + 0 < worth + 0) }' ||
  fail "the wrong cloth lost no point in the local check ($lost of $cloth)"
pass "a wrong cloth: local check and grader agree on the public items (Task 4: cloth $lost / $cloth)"

# 5. The GitHub Classroom workflow's commands.
workflow=.github/workflows/classroom.yml
grep -q 'container: debian:12' "$workflow" || fail "the workflow does not run in Debian 12"
step=0
while IFS= read -r cmd; do
  step=$((step + 1))
  case "$cmd" in
    *install-deps*) continue ;;  # done above
  esac
  bash -c "$cmd" >"$work/workflow_$step.log" 2>&1
  status=$?
  case "$cmd" in
    *a6_tests*)
      [ "$status" -ne 0 ] && [ "$status" -ne 127 ] && grep -q 'FAILED' "$work/workflow_$step.log" ||
        fail "workflow step '$cmd': exit $status, expected failing tests on the starter" ;;
    *"-L golden"*)
      [ "$status" -ne 0 ] || fail "workflow step '$cmd' passed on the starter" ;;
    *)
      [ "$status" -eq 0 ] || { tail -5 "$work/workflow_$step.log"; fail "workflow step '$cmd': exit $status"; } ;;
  esac
done < <(sed -n 's/^ *run: //p' "$workflow")
[ "$step" -ge 9 ] || fail "the workflow has $step run steps, expected one per task and more"
pass "the workflow's $step commands run in the release (task steps fail on the starter)"

echo "student release test: $failures failure(s) in $(( $(date +%s) - start )) s"
[ "$failures" -eq 0 ]
