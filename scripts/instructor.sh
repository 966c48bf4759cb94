#!/usr/bin/env bash
# One command per instructor job, each doing all the job needs and checking the result
# (docs/instructor.md says when to use which):
#
#   scripts/instructor.sh rerender [--into DIR]
#       after changing a scene, its constants, the renderer or the palette: rebuilds the
#       renderer and the golden tests (a6_golden_programs; a6_grade with the docs' examples at the
#       end; scripts/test.sh rebuilds the rest before the suite runs), re-renders
#       every reference image from the solution into tests/golden/ and tests/golden/hidden/ (or
#       into DIR, leaving the committed ones alone), writes the reference replays the grader's
#       report plays (tests/golden/replays/, or DIR/replays), says which images changed and which
#       scene descriptions ("shows" in the manifests) to re-read, and runs the golden tests.
#   scripts/instructor.sh hidden-check
#       after adding or changing a TEST(Task<N>Hidden, ...) in tests/hidden/*_test.cpp: rebuilds
#       a6_grade and the suite, names the new checks and the rubric item each counts for, and
#       checks that the solution passes every hidden check and the starter fails them.
#   scripts/instructor.sh rubric [FILE]
#       after changing the rubric (default grader/rubric.toml): checks it against every check
#       (each problem with its line and the fix, before anything runs), then grades the
#       solution and the starter with it: full marks and nothing.
#   scripts/instructor.sh variant wrong/NAME|alternative/NAME FILE...
#       keeps whole task files (the solution's, with one mistake, or written another way) as the
#       change they make: tests/<kind>/NAME/<file>.cpp.patch, a diff against solution/<file>.cpp
#       that the build applies (cmake/A6Variants.cmake); then builds the variant's file set.
#
# Each job that changes what the docs quote (the rubric's numbers, the checks, the images) ends by
# rewriting the docs' generated examples and counts (scripts/docs-examples.sh --update), and
# lists the files it changed for you to read and commit with your own change.
#
# Exit status: 0 when the job is done and checked, 1 when a check failed, 2 for a bad command
# or a rubric that cannot be used. The build folder is build/ (the default preset), or
# $A6_BUILD_DIR; the outputs go to out/instructor/, or $A6_INSTRUCTOR_OUT.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 1
build="${A6_BUILD_DIR:-build}"
outputs="${A6_INSTRUCTOR_OUT:-out/instructor}"

usage() {
  sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0" >&2
  exit 2
}

configure() {
  [ -f "$build/CMakeCache.txt" ] || cmake --preset default -B "$build" >/dev/null
}

# Configures when needed and builds TARGET (default: everything); prints how many steps ran.
rebuild() {
  local log
  log="$(mktemp)"
  configure || return 1
  if ! cmake --build "$build" ${1:+--target "$@"} >"$log" 2>&1; then
    tail -30 "$log"
    echo "instructor: the build failed (above)"
    rm -f "$log"
    return 1
  fi
  local steps
  steps=$(grep -c '^\[[0-9]*/[0-9]*\]' "$log")
  echo "rebuilt: $steps build steps${1:+ for $*}$([ "$steps" -eq 0 ] && echo " (all up to date)")"
  rm -f "$log"
}

# The images of a manifest (name, scene, shows), one per line, tab-separated.
manifest_images() {
  jq -r '.images[] | [.name, .scene, (.shows // "")] | @tsv' "$1"
}

# rerender_set FROM TO: renders FROM's manifest into TO (FROM itself when they are the same);
# prints the images that changed, and returns 1 when rendering failed.
rerender_set() {
  local from="$1" to="$2" saved
  saved="$(mktemp -d)"
  cp "$from"/*.png "$saved/" 2>/dev/null
  mkdir -p "$to"
  [ "$from" -ef "$to" ] || cp "$from/manifest.json" "$to/"
  if ! "$build/framework/render/a6_render_solution" --goldens --golden-dir "$to" >"$saved/render.log" 2>&1; then
    tail -5 "$saved/render.log"
    echo "instructor: rendering $from failed"
    rm -rf "$saved"
    return 1
  fi
  local changed=0 total=0 name scene shows
  while IFS=$'\t' read -r name scene shows; do
    total=$((total + 1))
    if ! cmp -s "$to/$name.png" "$saved/$name.png"; then
      changed=$((changed + 1))
      echo "  changed: $name.png ($scene): re-read its description: \"$shows\""
    fi
  done < <(manifest_images "$from/manifest.json")
  echo "$from: $total images rendered into $to, $changed changed"
  rm -rf "$saved"
}

# Scenes whose source changed since the last commit, while their manifest entries did not.
stale_descriptions() {
  local changed
  changed="$(git diff --name-only HEAD -- framework/scenes framework/render 2>/dev/null)"
  [ -n "$changed" ] || return 0
  if git diff --quiet HEAD -- tests/golden/manifest.json tests/golden/hidden/manifest.json 2>/dev/null; then
    echo "note: these changed since the last commit, the manifests' descriptions did not:"
    sed 's/^/  /' <<<"$changed"
    echo "  re-read the \"shows\" and \"hint\" of their images (and docs/handout.md's scene table)"
  fi
}

# grade_both OUT ARGS...: a6_grade grades solution/ and starter/ into OUT/solution and
# OUT/starter (their output in OUT/solution.log and OUT/starter.log) with ARGS; 1, and the end
# of its output, when it could not grade one of them.
grade_both() {
  local out="$1" who
  shift
  rm -rf "$out"
  mkdir -p "$out"
  for who in solution starter; do
    if ! "$build/grader/a6_grade" "$who" --out "$out/$who" --quiet "$@" >"$out/$who.log" 2>&1; then
      tail -5 "$out/$who.log"
      echo "instructor: a6_grade could not grade $who/ (see $out/$who.log)"
      return 1
    fi
  done
}

# Every file that differs from the last commit (tracked and changed or deleted, or new), one
# "PATH<TAB>HASH" line each ("gone" for a deleted one): what a job changed is what differs
# between two of these.
worktree_state() {
  local file
  git ls-files -m -o --exclude-standard -z -- . ':!out' ':!build' 2>/dev/null |
    while IFS= read -r -d '' file; do
      printf '%s\t%s\n' "$file" "$(git hash-object -- "$file" 2>/dev/null || echo gone)"
    done
}

# changed_since STATE: the files a job changed since STATE (worktree_state's), one per line:
# changed, new, or put back as committed.
changed_since() {
  awk -F'\t' 'NR == FNR { if ($0 != "") before[$1] = $2; next }
    { after[$1] = $2; if (before[$1] != $2) print $1 }
    END { for (p in before) if (!(p in after)) print p }' <(printf '%s\n' "$1") <(worktree_state) |
    LC_ALL=C sort
}

# say_changed STATE: names what the job changed, for the TA to read and commit.
say_changed() {
  local changed
  changed="$(changed_since "$1")"
  if [ -z "$changed" ]; then
    echo "files this job changed: none"
  else
    echo "files this job changed (read the diff, then commit them with your change):"
    sed 's/^/  /' <<<"$changed"
  fi
}

# update_docs: rebuilds what scripts/docs-examples.sh runs, rewrites the docs' examples and
# counts from it, then checks them all; 1 when something is still untrue (a new rubric item's
# row in the table of weights, a cost a clean CI run must measure: the check says which).
update_docs() {
  echo "=== the docs' examples and counts ==="
  rebuild a6_grade a6_batch a6_tests_starter a6_graded_wrong_t1_wrong_sign >/dev/null || return 1
  local log="$build/instructor-docs.log"
  # One run: --update rewrites what it can, then fails on what is still untrue.
  if ! A6_BUILD_DIR="$build" bash scripts/docs-examples.sh --update >"$log" 2>&1; then
    grep -E '^updated' "$log"
    grep -E '^docs-examples: ' "$log" | head -20
    echo "instructor: some docs are still untrue (above; whole log: $log)"
    return 1
  fi
  grep -E '^updated' "$log" || echo "every example and count was already true"
  echo "the docs' examples and counts are true"
}

# keep_unchanged_replays NEW COMMITTED: moves NEW's replays into COMMITTED, except where the
# committed file already holds the same run (the same frames and packed positions, energies
# within 1e-9): that file stays as it is, byte for byte, so that re-rendering leaves the
# replays of untouched scenes alone.
keep_unchanged_replays() {
  local new="$1" committed="$2" file name kept=0 written=0
  mkdir -p "$committed"
  for file in "$new"/*.json; do
    name="$(basename "$file")"
    if [ -f "$committed/$name" ] && jq -e -n --slurpfile a "$committed/$name" --slurpfile b "$file" '
        def abs: if . < 0 then -. else . end;
        def close: (.[0] - .[1] | abs) <= 0.000000001 * (1 + (.[0] | abs));
        ($a[0] | del(.energy)) == ($b[0] | del(.energy))
        and ($a[0].energy | length) == ($b[0].energy | length)
        and ([$a[0].energy, $b[0].energy] | transpose
             | all(.[0] as $x | .[1] as $y | ($x | length) == ($y | length)
                   and ([$x, $y] | transpose | all(close))))' \
      >/dev/null 2>&1; then
      kept=$((kept + 1))
    else
      cp "$file" "$committed/$name"
      written=$((written + 1))
    fi
  done
  echo "reference replays: $((kept + written)) scenes, $written written to $committed, $kept the same run as committed (left as they were)"
}

job_rerender() {
  local into=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --into) into="${2:?--into needs a folder}"; shift 2 ;;
      *) usage ;;
    esac
  done
  command -v jq >/dev/null || { echo "instructor: jq is missing (scripts/install-deps.sh)"; return 1; }
  local state
  state="$(worktree_state)"
  echo "=== 1. rebuild the renderer and the golden tests ==="
  rebuild a6_golden_programs || return 1
  [ -x "$build/framework/render/a6_render_solution" ] ||
    { echo "instructor: no a6_render_solution in $build (no headless GL?)"; return 1; }
  echo "=== 2. re-render the reference images from the solution ==="
  local status=0
  rerender_set tests/golden "${into:-tests/golden}" || status=1
  if [ -d tests/golden/hidden ]; then
    rerender_set tests/golden/hidden "${into:-tests/golden}/hidden" || status=1
  fi
  local fresh="$build/instructor-replays"
  rm -rf "$fresh"
  if ! "$build/framework/render/a6_render_solution" --replays \
    --out "$fresh" >"$build/instructor-replays.log" 2>&1; then
    tail -5 "$build/instructor-replays.log"
    echo "instructor: the reference replays could not be written"
    status=1
  else
    keep_unchanged_replays "$fresh" "${into:-tests/golden}/replays"
  fi
  [ -n "$into" ] || stale_descriptions
  if [ -n "$into" ]; then
    echo "=== 3. (--into: the committed images were left alone; nothing to test) ==="
    return "$status"
  fi
  echo "=== 3. the golden tests against the new images ==="
  if ctest --test-dir "$build" -L golden --output-on-failure >"$build/instructor-golden.log" 2>&1; then
    grep -E 'tests passed|tests failed' "$build/instructor-golden.log"
  else
    grep -E 'tests passed|tests failed|\*\*\*Failed|Failed  ' "$build/instructor-golden.log" | head -20
    echo "instructor: golden tests failed (whole log: $build/instructor-golden.log)"
    status=1
  fi
  update_docs || status=1
  say_changed "$state"
  echo "next: look at each changed image, then commit; scripts/main.sh re-exports the student" \
    "release and the Gradescope zip"
  return "$status"
}

# The hidden checks the last commit declares (TEST(Task<N>Hidden, Name) in tests/hidden/), as
# Suite.Name, sorted: what "new" is measured against, whatever was built in between.
committed_hidden_checks() {
  git ls-tree -r --name-only HEAD -- tests/hidden 2>/dev/null | grep '_test\.cpp$' |
    while read -r file; do git show "HEAD:$file"; done |
    sed -n 's/^TEST(\(Task[0-9]Hidden\), *\([A-Za-z0-9_]*\)).*/\1.\2/p' | LC_ALL=C sort
}

job_hidden_check() {
  [ $# -eq 0 ] || usage
  local before after state
  state="$(worktree_state)"
  before="$(mktemp)" after="$(mktemp)"
  committed_hidden_checks >"$before"
  echo "=== 1. rebuild a6_grade and the suite with tests/hidden/ ==="
  # Configured again: the hidden folder's *_test.cpp files are found when configuring.
  configure && cmake "$build" >/dev/null || return 1
  rebuild a6_grade a6_tests || return 1
  "$build/grader/a6_grade" --list-tests 2>/dev/null | grep -E '^Task[0-9]Hidden\.' | LC_ALL=C sort >"$after"
  echo "=== 2. the hidden checks and their rubric items ==="
  local added
  added="$(LC_ALL=C comm -13 <(cut -f1 "$before") <(cut -f1 "$after"))"
  echo "$(wc -l <"$after") hidden checks; new since the last commit: ${added:-none}"
  sed 's/\t/  ->  /; s/^/  /' "$after"
  local status=0
  if grep -q $'\t-$' "$after"; then
    echo "instructor: a hidden check above counts for no rubric item: add a glob to an item" \
      "of grader/rubric.toml (scripts/instructor.sh rubric checks it)"
    status=1
  fi
  rm -f "$before" "$after"
  echo "=== 3. the solution must pass them, the starter fail them ==="
  local out="$outputs/hidden-check"
  grade_both "$out" --tests '*Hidden*' || return 1
  if [ "$(jq '.extra_data.tests | length' "$out/solution/results.json")" -eq 0 ]; then
    echo "instructor: no hidden check ran"
    return 1
  fi
  local failed passed
  failed="$(jq -r '.extra_data.tests | to_entries[] | select(.value != "passed") | .key' "$out/solution/results.json")"
  passed="$(jq -r '.extra_data.tests | to_entries[] | select(.value == "passed") | .key' "$out/starter/results.json")"
  if [ -n "$failed" ]; then
    echo "instructor: the solution fails these hidden checks (see $out/solution/report.html):"
    sed 's/^/  /' <<<"$failed"
    status=1
  else
    echo "the solution passes all $(jq '.extra_data.tests | length' "$out/solution/results.json")" \
      "hidden checks and images"
  fi
  if [ -n "$passed" ]; then
    echo "instructor: the starter passes these hidden checks, so they test nothing:"
    sed 's/^/  /' <<<"$passed"
    status=1
  else
    echo "the starter fails every one"
  fi
  update_docs || status=1
  say_changed "$state"
  return "$status"
}

job_rubric() {
  [ $# -le 1 ] || usage
  local rubric="${1:-grader/rubric.toml}" state
  state="$(worktree_state)"
  echo "=== 1. the rubric against every check ==="
  rebuild a6_grade >/dev/null || return 1
  "$build/grader/a6_grade" --check-rubric --rubric "$rubric" || return 2
  echo "=== 2. the solution and the starter graded with it ==="
  local out="$outputs/rubric" status=0
  grade_both "$out" --rubric "$rubric" || return 1
  sed -n '1,/^  total/p' "$out/solution.log"
  # Full marks: every item passed, and the score is the total plus every item's extra credit.
  if ! jq -e '(.tests | length > 0) and ([.tests[] | select(.status != "passed")] | length == 0)
              and (.score == .extra_data.max_score + .extra_data.extra_credit)' \
    "$out/solution/results.json" >/dev/null; then
    echo "instructor: the solution does not get full marks with this rubric (see $out/solution/report.html)"
    status=1
  fi
  local starter
  starter="$(jq '.score' "$out/starter/results.json")"
  echo "the starter scores $starter"
  if [ "$starter" != "0" ] && [ "$starter" != "0.0" ]; then
    echo "instructor: the starter earns points with this rubric"
    status=1
  fi
  if [ "$rubric" -ef grader/rubric.toml ]; then
    update_docs || status=1  # the docs quote the default rubric's numbers
    say_changed "$state"
  else
    echo "note: a6_grade uses grader/rubric.toml unless given --rubric: copy $rubric there to make" \
      "it the default (then this job updates the docs' numbers too)"
  fi
  echo "next: scripts/main.sh re-exports the student release (its public rubric) and the Gradescope zip"
  return "$status"
}

# variant KIND/NAME FILE...: each FILE kept as its patch of the solution.
job_variant() {
  local where="${1:-}" f name kind patch
  case "$where" in wrong/?* | alternative/?*) shift ;; *) usage ;; esac
  [ $# -ge 1 ] || usage
  kind="${where%%/*}" name="${where#*/}"
  mkdir -p "tests/$where"
  for f in "$@"; do
    [ -f "solution/$(basename "$f")" ] || { echo "instructor: $f is no task file"; return 2; }
    patch="tests/$where/$(basename "$f").patch"
    if diff -u --label "solution/$(basename "$f")" --label "tests/$where/$(basename "$f")" \
      "solution/$(basename "$f")" "$f" >"$patch"; then
      rm -f "$patch"
      echo "instructor: $f is the solution's text: nothing to keep"
      return 1
    fi
    echo "kept: $patch ($(grep -c '^[-+][^-+]' "$patch") lines changed)"
    [ "$(dirname "$f")" -ef "tests/$where" ] && rm -f "$f"  # the whole file: its patch now
  done
  if [ "$kind" = wrong ] && [ ! -f "tests/$where/EXPECT" ]; then
    echo "next: write tests/$where/EXPECT (fail: <task>, and mistake: <id> if the library names it)"
    return 0
  fi
  local set="${kind/alternative/alt}_$name"
  rebuild "a6_graded_$set" a6_scores_test || return 1  # its one grading (tests/grader/)
  echo "next: ctest --test-dir $build -R '^${kind}_$name\$' grades it"
}

[ $# -ge 1 ] || usage
job="$1"
shift
case "$job" in
  rerender) job_rerender "$@" ;;
  hidden-check) job_hidden_check "$@" ;;
  rubric) job_rubric "$@" ;;
  variant) job_variant "$@" ;;
  -h | --help) usage ;;
  *) usage ;;
esac
