#!/usr/bin/env bash
# The example outputs in the docs, made from real runs so that they cannot drift:
#
#   scripts/docs-examples.sh            check: every example is what the programs print today
#   scripts/docs-examples.sh --update   rewrite the examples from a fresh run, and the numbers
#                                       in the facts and the table of weights below; then
#                                       exit 1 if anything is still untrue
#
# An example is a fenced block right after a marker line `<!-- example: ID -->` in README.md,
# docs/*.md or grader/release/README.md; example_ID below makes its text. The check compares
# after masking what changes from run to run (durations, memory, dates). It also checks the
# facts the prose states (counts of tests, images, checks: see check_facts), and that the
# handout's table of reference images says what the manifests say.
#
# Needs the instructors' build (build/, or $A6_BUILD_DIR) with the grader, and jq.
# Exit status: 0 all true, 1 something differs (the difference is printed), 2 bad use.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 1
root="$(pwd)"
build="$(cd "${A6_BUILD_DIR:-build}" 2>/dev/null && pwd)" || {
  echo "docs-examples: no build folder ${A6_BUILD_DIR:-build} (scripts/test.sh makes it)" >&2
  exit 2
}
mode=check
case "${1:-}" in
  "") ;;
  --update) mode=update ;;
  *) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
esac
grade="$build/grader/a6_grade"
[ -x "$grade" ] || { echo "docs-examples: no $grade (build the grader first)" >&2; exit 2; }
command -v jq >/dev/null || { echo "docs-examples: jq is missing (scripts/install-deps.sh)" >&2; exit 2; }

# Inside the build folder, open to all: the sandbox's user must reach the submissions.
scratch="$(mktemp -d "$build/docs-examples.XXXXXX")"
chmod 755 "$scratch"
trap 'rm -rf "$scratch"' EXIT
docs=(README.md docs/*.md grader/release/README.md)
failures=0
fail() {
  echo "docs-examples: $*" >&2
  failures=$((failures + 1))
}

# ---- the runs the examples come from ---------------------------------------------------------

# "alice": the solution with task 1's sign wrong and a cloth.cpp that does not compile, graded
# with seed 7 from a folder where its path reads submissions/alice.
alice_graded() {
  [ -f "$scratch/graded/alice/results.json" ] && return 0
  mkdir -p "$scratch/submissions/alice"
  cp solution/*.cpp "$scratch/submissions/alice/"
  cp "$build/variants/wrong/t1_wrong_sign/spring.cpp" "$scratch/submissions/alice/"
  printf '\nint unfinished = ;\n' >>"$scratch/submissions/alice/cloth.cpp"
  (cd "$scratch" && "$grade" submissions/alice --out graded/alice --seed 7 --quiet >alice.out 2>&1)
}

# (Without the notes on the run, facts of the machine: a checkout under a folder of mode 0700,
# the sandbox protections a machine without root or namespaces cannot apply.)
example_grade_summary() {
  alice_graded
  grep -v '^  note: ' "$scratch/alice.out" | sed "s|$scratch/||g"
}

# results.json, shortened: the top level, three entries (a failed one, extra credit, one shown
# after the due date) with their outputs cut and at most two of their checks named, and two
# checks of extra_data.tests.
example_results_json() {
  alice_graded
  jq '(.tests |= [.[] | select(.number == "1.2" or .number == "1.3" or .number == "4.1")]
        | .tests[].output |= (if length > 300 then .[0:300] + "..." else . end)
        | .tests[].extra_data.checks |= (if length > 2 then .[0:2] + ["..."] else . end)
        | .extra_data.tests |= (to_entries | .[0:2] | from_entries + {"...": "..."})
        | .extra_data.notes |= [])' \
    "$scratch/graded/alice/results.json"
}

example_rubric_errors() {
  sed -e '0,/^points = 12$/s//point = 12/' -e '0,/^visibility = "visible"$/s//visibility = "secret"/' \
    grader/rubric.toml >"$scratch/rubric.toml"
  sed -i '0,/^points = 12$/s//points = 7/' "$scratch/rubric.toml"
  (cd "$scratch" && "$grade" --check-rubric --rubric rubric.toml 2>&1)
}

example_check_rubric() {
  "$grade" --check-rubric 2>&1 | sed "s|$root/||"
}

# A Gradescope export of two submissions: Jane Doe's (the solution) and Bob Smith's (alice's).
example_gradebook() {
  alice_graded
  local export="$scratch/export"
  mkdir -p "$export/submission_1001" "$export/submission_1002"
  cp solution/*.cpp "$export/submission_1001/"
  cp "$scratch"/submissions/alice/*.cpp "$export/submission_1002/"
  cat >"$export/submission_metadata.yml" <<'YAML'
submission_1001:
  :submitters:
  - :name: Jane Doe
    :email: jane@example.edu
    :sid: '1001'
submission_1002:
  :submitters:
  - :name: Smith, Bob
    :email: bob@example.edu
    :sid: '1002'
YAML
  (cd "$scratch" && "$build/grader/a6_batch" export --out batch -j 2 >batch.out 2>batch.err)
  tr -d '\r' <"$scratch/batch/gradebook.csv"  # (CSV lines end in CR LF)
}

example_batch_summary() {
  [ -f "$scratch/batch.out" ] || example_gradebook >/dev/null
  sed "s|$scratch/||g" "$scratch/batch.out"
}

# The student release's summary on the starter: its tests are the public ones, without the
# hidden checks (release_student compares this block with the release's own run).
example_student_summary() {
  "$build/tests/a6_tests_starter" --gtest_filter='-*Hidden*' 2>/dev/null |
    sed -n '/^Summary by task$/,/^A6-SUMMARY/p' | sed '$d'
}

# The first failed check of a wrong spring, as its grading wrote it (the ctest entry
# wrong_t1_wrong_sign, which ctest runs before this one; by hand, the grading is made here): the
# report leaves out the check's hint where it names the mistake, so the example ends at the
# message's last line.
example_failure_message() {
  local results="$build/tests/grader/scores_out/wrong_t1_wrong_sign/out/results.json"
  if [ ! -f "$results" ]; then
    "$build/tests/grader/a6_graded_wrong_t1_wrong_sign" --out "$scratch/t1_wrong_sign" >/dev/null
    results="$scratch/t1_wrong_sign/results.json"
  fi
  jq -r '.tests[].output' "$results" | awk '/^Task 1 \(spring.cpp\)/ { on = 1 } on && /^$/ { exit } on { print }'
}

# A diagnosis by measurement of a spring force with two mistakes, as its grading named it (the
# ctest entry wrong_c1_direction_not_normalised; by hand, the grading is made here).
example_diagnosis() {
  local name=c1_direction_not_normalised
  local results="$build/tests/grader/scores_out/wrong_$name/out/results.json"
  if [ ! -f "$results" ]; then
    "$build/tests/grader/a6_graded_wrong_$name" --out "$scratch/$name" >/dev/null
    results="$scratch/$name/results.json"
  fi
  jq -r '.extra_data.diagnoses[] | select(.task == 1) | .text' "$results" | fold -s -w 96 |
    sed 's/ *$//'
}

# ---- markers and blocks ----------------------------------------------------------------------

# What changes from one run to the next, masked for the comparison; and 12.0 read as 12 (jq 1.7,
# Debian 13's, keeps a number as written; jq 1.6 shortens it).
mask() {
  sed -E -e 's/\b([0-9]+)\.0\b/\1/g' -e 's/[0-9]+(\.[0-9]+)? s\b/N s/g' -e 's/"(execution_time|seconds|grader_peak_rss_mib|build|checks)": [0-9.]+/"\1": N/g' \
    -e 's/,[0-9]+(\.[0-9]+)?$/,N/' -e 's/,([a-z ]+),[0-9]+(\.[0-9]+)?,([a-z0-9_ ]*)$/,\1,N,\3/' -e 's/\b([0-9]+m)?[0-9]+s\b|\b[0-9]+h[0-9]+m\b/N/g'
}

# Writes FILE with each marked block's body replaced by its example's text, to stdout.
render_doc() {
  local file="$1" line id="" in_block=0
  while IFS= read -r line || [ -n "$line" ]; do
    if [ "$in_block" = 1 ]; then
      [[ "$line" == '```'* ]] && { printf '%s\n' "$line"; in_block=0; }
      continue
    fi
    printf '%s\n' "$line"
    if [[ "$line" =~ ^\<!--\ example:\ ([a-z0-9_-]+)\ --\>$ ]]; then
      id="${BASH_REMATCH[1]}"
    elif [ -n "$id" ] && [[ "$line" == '```'* ]]; then
      local fn="example_${id//-/_}"
      if declare -F "$fn" >/dev/null; then
        "$fn"
      else
        echo "docs-examples: $file: no example named $id" >&2
        echo "(no example named $id)"
      fi
      in_block=1
      id=""
    else
      id=""
    fi
  done <"$file"
}

check_examples() {
  local file n
  for file in "${docs[@]}"; do
    n=$(grep -c '^<!-- example: ' "$file")
    [ "$n" -gt 0 ] || continue
    render_doc "$file" >"$scratch/new.md"
    if [ "$mode" = update ]; then
      # (Rewritten only where more than the masked durations changed: no churn in the docs.)
      cmp -s <(mask <"$file") <(mask <"$scratch/new.md") ||
        { cp "$scratch/new.md" "$file"; echo "updated $n examples in $file"; }
    elif ! diff -u <(mask <"$file") <(mask <"$scratch/new.md") >"$scratch/diff"; then
      fail "$file: an example differs from what the programs print now (- the doc, + now;" \
        "scripts/docs-examples.sh --update rewrites it):"$'\n'"$(head -60 "$scratch/diff")"
    else
      echo "ok: $file: $n examples as the programs print them"
    fi
  done
}

# ---- facts in the prose ----------------------------------------------------------------------

# fact FILE TEMPLATE VALUE...: FILE must say TEMPLATE with each %s the value measured (a
# sentence with the true number in it, on one line), and every sentence of that form in FILE must
# have the true numbers (one stale copy beside a right one fails). --update writes the values in
# where the sentences have other numbers, unless no_update=1 (a fact of this machine, such as the
# packages it installs).
fact() {
  local file="$1" template="$2" text value stale
  shift 2
  for value in "$@"; do
    [[ "$value" =~ ^[0-9][0-9.]*$ ]] ||
      { fail "$file: \"$template\": the measured value '$value' is no number (a run above failed)"; return; }
  done
  # shellcheck disable=SC2059
  text=$(printf "$template" "$@")
  stale=$(TEMPLATE="$template" TEXT="$text" perl -ne '
      BEGIN { $re = join "[0-9][0-9.]*", map { quotemeta } split /%s/, $ENV{TEMPLATE}, -1 }
      while (/($re)/g) { print "  line $.: $1\n" if $1 ne $ENV{TEXT} }' "$file")
  if [ -z "$stale" ] && grep -qF -- "$text" "$file"; then
    echo "ok: $file says \"$text\""
  elif [ "$mode" = update ] && [ "${no_update:-0}" != 1 ] && TEMPLATE="$template" TEXT="$text" perl -i -pe '
      BEGIN { $re = join "[0-9][0-9.]*", map { quotemeta } split /%s/, $ENV{TEMPLATE}, -1 }
      $n += s/$re/$ENV{TEXT}/g; END { $? = $n ? 0 : 1 }' "$file"; then
    echo "updated: $file now says \"$text\""
  else
    fail "$file should say \"$text\" (the number is measured; fix the text)${stale:+; it says:$'\n'$stale}"
  fi
}

# restate FILE OLD NEW WHY: FILE says OLD where NEW is true; --update writes NEW instead.
restate() {
  if [ "$mode" = update ]; then
    OLD="$2" NEW="$3" perl -i -pe 's/\Q$ENV{OLD}\E\b/$ENV{NEW}/g' "$1"
    echo "updated: $1 now says \"$3\""
  else
    fail "$1 says \"$2\": $4"
  fi
}

# The rubric as a6_grade reads it (a6_grade --list-items): ITEMS, one line per item (name,
# points, checks, extra or regular, visibility), and its totals.
read_rubric() {
  local listed
  listed=$("$grade" --list-items 2>/dev/null)
  ITEMS=$(sed '$d' <<<"$listed")
  IFS=$'\t' read -r _ TOTAL CHECKS EXTRA < <(tail -1 <<<"$listed")
  "$grade" --public-rubric "$scratch/public.toml"
  IFS=$'\t' read -r _ PUBLIC_TOTAL _ PUBLIC_EXTRA < <("$grade" --list-items --rubric "$scratch/public.toml" 2>/dev/null | tail -1)
  FULL=$(awk -v t="$TOTAL" -v e="$EXTRA" 'BEGIN { print t + e }')
}

# "N (x)" as the table of weights writes an item's checks: x its points per check, to three
# decimals at most; just N for one check.
share() {
  awk -v p="$1" -v n="$2" 'BEGIN { if (n == 1) { print n; exit }
    x = sprintf("%.3f", p / n); sub(/0+$/, "", x); sub(/\.$/, "", x); print n " (" x ")" }'
}

# docs/instructor.md's table of weights ("How the weights are set"): a row for each item worth
# points, with the rubric's points and the number of checks it counts; --update rewrites the
# numbers of a row that exists (a new item needs its row, and its reason, written by hand).
check_weights() {
  local name points checks want bad=0
  while IFS=$'\t' read -r name points checks _; do
    [ "$points" = 0 ] && continue
    [ "$checks" -gt 0 ] || { fail "the rubric's item \"$name\" has points and no check"; bad=1; continue; }
    want="| $name | $points | $(share "$points" "$checks") |"
    grep -qF -- "$want" docs/instructor.md && continue
    if [ "$mode" = update ] && NAME="| $name | " WANT="$want" perl -i -pe '
        $n += s/^\Q$ENV{NAME}\E[0-9.]+ \| [0-9]+( \([0-9.]+\))? \|/$ENV{WANT}/; END { $? = $n ? 0 : 1 }' \
      docs/instructor.md; then
      echo "updated: docs/instructor.md: $want"
      continue
    fi
    fail "docs/instructor.md: the table of weights needs the row \"$want <why> |\" (the rubric's points and checks)"
    bad=1
  done <<<"$ITEMS"
  [ "$bad" = 1 ] || echo "ok: docs/instructor.md's table of weights has the rubric's points and checks"
}

check_facts() {
  local tests images hidden_images golden_tests task7
  tests=$(ctest --test-dir "$build" -N | sed -n 's/^Total Tests: //p')
  golden_tests=$(ctest --test-dir "$build" -N -L golden | sed -n 's/^Total Tests: //p')
  images=$(jq '.images | length' tests/golden/manifest.json)
  hidden_images=$(jq '.images | length' tests/golden/hidden/manifest.json)
  task7=$("$grade" --list-tests 2>/dev/null | grep -c '^Task7Implicit\.')
  read_rubric
  fact README.md "then runs the %s tests" "$tests"
  # A full score or an image count the README states anywhere is today's: "solution N" is the
  # rubric's points plus its extra credit; "N + M images" the public and the hidden images.
  fact README.md "The solution gets %s points and the extra credit" "$TOTAL"
  # (Each stated number is checked, so that one stale mention among right ones shows.)
  local stated
  for stated in $(grep -oE 'solution [0-9]+\b' README.md | awk '{ print $2 }' | sort -u); do
    [ "$stated" = "$FULL" ] || restate README.md "solution $stated" "solution $FULL" \
      "the solution's score is $FULL"
  done
  for stated in $(grep -oE '\b[0-9]+ \+ [0-9]+ images' README.md | sort -u | tr ' ' '_'); do
    [ "${stated//_/ }" = "$images + $hidden_images images" ] || restate README.md "${stated//_/ }" \
      "$images + $hidden_images images" "there are $images public and $hidden_images hidden images"
  done
  PACKAGES=$(bash scripts/install-deps.sh | sed -n 's/.*all \([0-9]*\) packages.*/\1/p')
  no_update=1 fact README.md "apt-get: the %s packages it names" "$PACKAGES"
  local release
  release=$(sed -n 's|.*export-student.sh out/\([a-z-]*\) --zip.*|\1|p' scripts/main.sh)
  fact README.md "\`out/$release.zip\`"
  fact README.md "\`unzip $release.zip && cd"
  fact grader/release/README.md "\`unzip $release.zip && cd $release\`"
  fact README.md "the quick tier, its %s tests" "$(ctest --test-dir "$build" -N -L quick | sed -n 's/^Total Tests: //p')"
  fact docs/instructor.md "the %s public images" "$images"
  fact docs/instructor.md "the %s hidden ones" "$hidden_images"
  fact docs/instructor.md "(total %s instead of %s)" "$PUBLIC_TOTAL" "$TOTAL"
  fact docs/instructor.md "all %s checks" "$CHECKS"
  fact docs/instructor.md "gives %s points and %s of extra credit" "$TOTAL" "$EXTRA"
  fact docs/instructor.md "a perfect submission with the default rubric gets %s on Gradescope" "$FULL"
  fact docs/instructor.md "In the default rubric its %s checks" "$task7"
  # "Adapting the assignment": task 7's extra credit, and the jobs its commands name.
  fact docs/instructor.md "spring Jacobians\"\`: the name is what students see) and add %s to" \
    "$(awk -F'\t' '$1 ~ /^Task 7 extra credit: / && $4 == "extra" { s += $2 } END { print s + 0 }' <<<"$ITEMS")"
  local job
  for job in $(grep -oE 'scripts/instructor\.sh [a-z-]+' docs/instructor.md | awk '{ print $2 }' | sort -u); do
    grep -qE "^  $job\) " scripts/instructor.sh ||
      fail "docs/instructor.md runs 'scripts/instructor.sh $job', which is no job of it"
  done
  fact docs/instructor.md "on the starter (0 / %s," "$PUBLIC_TOTAL"
  fact docs/instructor.md "on the solution (%s / %s + %s extra credit)" "$PUBLIC_TOTAL" "$PUBLIC_TOTAL" "$PUBLIC_EXTRA"
  fact docs/instructor.md "Give it %s points (the rubric's \`total\`" "$TOTAL"
  fact docs/instructor.md "Expect **%s** (%s points and %s of extra credit)" "$FULL" "$TOTAL" "$EXTRA"
  fact docs/instructor.md "Scores with the default rubric (%s points + %s extra credit" "$TOTAL" "$EXTRA"
  fact docs/handout.md "Its rubric holds the public checks (%s points)" "$PUBLIC_TOTAL"
  fact docs/rendering.md "holds %s reference images" "$images"
  fact docs/rendering.md "(%s ctest tests" "$golden_tests"
  check_weights
  check_costs
}

# The suite's costs (docs/test-costs.md, made by scripts/test-costs.sh from a clean run of
# .ci/run): the table has a row for each ctest entry and no other, and README.md quotes its
# totals.
check_costs() {
  local ci all suite listed
  ci=$(sed -n 's/^| `.ci\/run` in all[^|]*| \([0-9]*\) |$/\1/p' docs/test-costs.md)
  suite=$(sed -n 's/^| its tests, ctest -j2, wall clock | \([0-9.]*\) |$/\1/p' docs/test-costs.md)
  all=$(sed -n "s/^| the README's test command (scripts\/test.sh: configure, build, tests) | \([0-9]*\) |$/\1/p" \
    docs/test-costs.md)
  fact README.md "%s s for .ci/run" "$ci"
  fact README.md "%s s for scripts/test.sh" "$all"
  fact README.md "%s s for the tests" "$suite"
  fact README.md "its tests' own seconds add up to %s s" "$(ctest --test-dir "$build" -N -L quick |
    sed -n 's/^ *Test *#[0-9]*: //p' | awk 'NR == FNR { quick[$1] = 1; next }
      /^\| `/ { name = $2; gsub(/`/, "", name); if (name in quick) s += $4 } END { printf "%.0f", s }' \
      - docs/test-costs.md)"
  listed=$(sed -n 's/^| `\([^`]*\)` | [0-9.]* | [a-z]* |$/\1/p' docs/test-costs.md | sort)
  if [ "$listed" = "$(ctest --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p' | sort)" ]; then
    echo "ok: docs/test-costs.md has a row for each ctest entry"
  else
    fail "docs/test-costs.md does not list the ctest entries of this build (run .ci/run on a clean clone and scripts/test-costs.sh on its log)"
  fi
}

# The student's first hour (scripts/bench-first-hour.sh --write: the release as a user of its own,
# an empty compiler cache): the times README.md, the release's README and the handout quote.
check_first_hour() {
  local results=tests/bench/results/first-hour.json first second task1 loop runs cores notes note
  [ -f "$results" ] || { fail "no $results (scripts/bench-first-hour.sh --write makes it)"; return; }
  IFS=$'\t' read -r first second task1 loop runs cores notes note < <(jq -r '[.first_check_s,
    .second_check_s, .first_task1_s, .loop_s, .loop_runs, .cores, .sandbox_lines, .sandbox_note]
    | @tsv' "$results")
  fact grader/release/README.md "builds the grader (%s s on a %s-core machine); later ones take %s s" \
    "$first" "$cores" "$second"
  fact grader/release/README.md "The first time it builds the test program (%s s on a %s-core machine);" \
    "$task1" "$cores"
  fact grader/release/README.md "then it rebuilds only your file (%s s in all)" "$loop"
  # The note the first check printed about the sandbox, as the README quotes its start.
  local quoted
  quoted=$(grep -o '`note: sandbox: [^`]*`' grader/release/README.md | tr -d '`' | sed 's/, \.\.\.$//')
  [ -n "$quoted" ] && [[ "$note" == "$quoted"* ]] ||
    fail "grader/release/README.md quotes the sandbox's note as \"$quoted\"; the first check printed \"$note\""
  fact docs/handout.md "task 1's tests, %s s on a %s-core machine" "$loop" "$cores"
  fact README.md "| %s s the first time (an empty compiler cache), %s s the next |" "$first" "$second"
  fact README.md "| %s s (the median of %s runs) |" "$loop" "$runs"
  fact README.md "What each command costs on the %s-core development machine" "$cores"
  # "one note says it ran without the grader's sandbox": what the first check printed.
  if [ "$notes" != 1 ] && grep -qF "and one line," grader/release/README.md; then
    fail "grader/release/README.md says one line about the sandbox; the bench's check.sh printed $notes"
  fi
}

# Counts and commands the READMEs and the handout state, against the code and the build: the
# test output's limits, the packages, the port of the desktop, a pattern said to match no test,
# and the release's commands where README.md says they are its own.
check_stated() {
  local file stated limit brief
  limit=$(sed -n 's/^set(A6_TEST_OUTPUT_LIMIT \([0-9]*\))$/\1/p' tests/CMakeLists.txt)
  brief=$(sed -n 's/.*kMaxLines = \([0-9]*\);.*/\1/p' tests/support/brief_failures.h)
  fact README.md "A failing test prints at most %s lines" "$limit"
  fact docs/handout.md "No test prints more than %s" "$limit"
  fact docs/handout.md "(%s lines at most), and names the file" "$brief"
  # (The task files counted in words, "the seven files": framework/harness/tasks.h's table.)
  local words=(no one two three four five six seven eight nine ten) count
  count=$(grep -oE '"[a-z_]+\.cpp"' framework/harness/tasks.h | wc -l)
  for file in README.md grader/release/README.md docs/handout.md; do
    for stated in $(grep -oE '\b[0-9]+ (Debian )?packages\b' "$file" | awk '{ print $1 }' | sort -u); do
      [ "$stated" = "$PACKAGES" ] || fail "$file says $stated packages; install-deps names $PACKAGES"
    done
    for stated in $(grep -oE '\b(one|two|three|four|five|six|seven|eight|nine|ten) (task |\.cpp |`\.cpp` )?files\b' "$file" |
      awk '{ print $1 }' | sort -u); do
      [ "$stated" = "${words[count]}" ] || fail "$file counts $stated files; there are ${words[count]} task files"
    done
    for stated in $(grep -oE '\bport [0-9]+|:[0-9]{4}/vnc|forwarded port [0-9]+' "$file" | grep -oE '[0-9]+' | sort -u); do
      grep -q "A6_DESKTOP_PORT:-$stated}" scripts/desktop.sh ||
        fail "$file names the port $stated; scripts/desktop.sh serves another"
    done
    for stated in $(grep -oE -- '-R Task[0-9]+`: there is no task' "$file" | grep -oE 'Task[0-9]+' | sort -u); do
      [ "$(ctest --test-dir "$build" -N -R "$stated" | sed -n 's/^Total Tests: //p')" = 0 ] ||
        fail "$file says -R $stated matches no test; it matches some"
    done
  done
  if grep -qi 'same two commands' README.md &&
    ! cmp -s <(sed -n '/^```sh/,/^```/p' README.md | sed -n 2,3p | awk '{ print $1, $2, $3 }') \
      <(sed -n '/^```sh/,/^```/p' grader/release/README.md | sed -n 2,3p | awk '{ print $1, $2, $3 }'); then
    fail "README.md says the release's README has the same two commands; they differ"
  fi
  # "at least ten times the tolerance it crosses": the margin the wrong versions' test asks for.
  stated=$(sed -n 's/.*std::atof(margin.c_str()) >= \([0-9]*\)).*/\1/p' tests/grader/scores_test.cpp)
  grep -q "at least ${words[stated]:-?} times the tolerance" README.md ||
    fail "README.md should say the wrong versions miss by at least ${words[stated]:-?} times the tolerance (tests/grader/scores_test.cpp)"
  # A section of the README a script or the build names ('README.md, "Platforms"'): both READMEs
  # have it, since the release ships those scripts with its own README.
  for stated in $(git ls-files -- scripts CMakeLists.txt cmake grader/release ':!scripts/docs-examples.sh' |
    xargs grep -ohE 'README\.md, \\?"[A-Za-z ]+\\?"' | grep -oE '"[A-Za-z ]+\\?"' | tr -d '"\\' | tr ' ' '_' | sort -u); do
    for file in README.md grader/release/README.md; do
      grep -qE "^#+ ${stated//_/ }\$" "$file" ||
        fail "$file has no section \"${stated//_/ }\", which the scripts name"
    done
  done
  echo "ok: the stated limits, packages, ports, patterns, sections and commands are the code's"
}

# The handout's table of reference images: each row's text is its manifest entry's "shows".
check_handout_images() {
  local name shows bad=0
  while IFS=$'\t' read -r name shows; do
    if ! grep -qF -- "\`$name\`" docs/handout.md; then
      fail "docs/handout.md: no row for the reference image $name"
      bad=1
    elif ! grep -qF -- "$shows" < <(grep -F -- "\`$name\`" docs/handout.md); then
      fail "docs/handout.md: the row of $name does not say what tests/golden/manifest.json says: \"$shows\""
      bad=1
    fi
  done < <(jq -r '.images[] | [.name, .shows] | @tsv' tests/golden/manifest.json)
  [ "$bad" = 1 ] || echo "ok: docs/handout.md describes every reference image as the manifest does"
}

# Words that went stale once: the task files are seven (framework/harness/tasks.h), and no
# doc, comment or message may say six (the bench results record what was measured then).
check_words() {
  local stale
  stale=$(git ls-files -z -- . ':!tests/wrong' ':!tests/bench/results' ':!docs/test-costs.md' 2>/dev/null |
    xargs -0 grep -nIiE '\bsix (task |student |\.cpp |`\.cpp` )?(files|objects|tasks)\b|\ball six\b' 2>/dev/null)
  if [ -n "$stale" ]; then
    fail "these count the task files or the tasks as six; there are seven:"$'\n'"$stale"
  else
    echo "ok: nothing counts the task files as six"
  fi
}

check_examples
check_words

# grader/DESIGN.md's diagram names the grader's folders as they are: its column of folders (from
# the 17th character of a line, as "  1. intake     intake/") holds every folder of grader/ that
# git knows, and nothing else.
check_design_folders() {
  local diagram named known folder bad=0
  diagram=$(awk '/^```/ { n++; next } n == 1' grader/DESIGN.md)
  named=$(sed -nE 's|^  .{14}([A-Za-z0-9_.-]+)/( .*)?$|\1|p' <<<"$diagram" | sort -u)
  known=$(git ls-files grader | awk -F/ 'NF > 2 { print $2 }' | sort -u)
  if [ -z "$known" ] || [ -z "$named" ]; then
    fail "grader/DESIGN.md's diagram or git's list of grader/ is empty (not a checkout?)"
    return
  fi
  for folder in $known; do
    grep -qx -- "$folder" <<<"$named" ||
      { fail "grader/DESIGN.md's diagram does not name the folder grader/$folder/"; bad=1; }
  done
  for folder in $named; do
    grep -qx -- "$folder" <<<"$known" ||
      { fail "grader/DESIGN.md's diagram names grader/$folder/, which git does not know"; bad=1; }
  done
  [ "$bad" = 1 ] || echo "ok: grader/DESIGN.md's diagram names the $(wc -w <<<"$named") folders of grader/"
}
check_design_folders

# Every time and memory limit the docs state is the grader's own (a6_grade --list-limits, from
# grader/common/limits.h): a limit changed there and not in the prose fails here.
check_limits() {
  local listed
  listed=$("$grade" --list-limits 2>/dev/null)
  [ -n "$listed" ] || { fail "a6_grade --list-limits printed nothing"; return; }
  limit() { awk -v key="$1" '$1 == key { print $2 }' <<<"$listed"; }
  local i=docs/instructor.md
  fact $i "in seconds (default %s). Checks after it" "$(limit time_budget)"
  fact $i "(%s by default)." "$(limit time_budget)"
  fact $i "(default %s; \`a6_grade\`'s own \`--time-budget\` is %s s)" "$(limit batch_timeout)" "$(limit time_budget)"
  fact $i "Each compile may take %s s," "$(limit compile_time)"
  fact $i "and the whole build %s s" "$(limit build_budget)"
  fact $i "bounded in time (%s s" "$(limit build_budget)"
  fact $i "and %s s a file)." "$(limit compile_time)"
  fact $i "the build budget (%s s, plus %s s for a link)" "$(limit build_budget)" "$(limit link_allowance)"
  fact $i "plus %s s for the grader's own work" "$(limit own_work)"
  fact $i "\`--time-budget\`, %s s a scene and %s s for all at most" "$(limit replay_time)" "$(limit replays_time)"
  fact $i "within %s s. Code that runs before" "$(limit startup_time)"
  fact $i "a CPU-time limit (%s s) and a memory limit (%s MiB)" "$(limit probe_cpu)" "$(limit probe_memory)"
  fact $i "gives the student's code %s s over all checks (\`--time-budget %s\`" \
    "$(limit gradescope_time_budget)" "$(limit gradescope_time_budget)"
  fact $i "and stops \`a6_grade\` after %s s" "$(limit gradescope_time_limit)"
  fact $i "is limited to %s MiB of address space" "$(limit probe_memory)"
  fact $i "at up to 60 step counts, within %s s)" "$(limit replay_time)"
  fact $i "so with the default %s s limits" "$(limit check_time_limit)"
  fact $i "(the %s MiB address-space limit)" "$(limit probe_memory)"
  fact $i "outside (0, %s], missing" "$(limit max_check_time_limit)"
  fact docs/handout.md "once the replays' %s s are spent" "$(limit replays_time)"
}
check_limits
check_facts
check_handout_images
check_first_hour
check_stated
[ "$failures" -eq 0 ] || { echo "docs-examples: $failures problems" >&2; exit 1; }
echo "docs-examples: all true"
