#!/usr/bin/env bash
# The class's picture as an instructor who grades on Gradescope gets it (ctest grader_insights):
# a Gradescope "Export Submissions", unzipped, of a small class, with the results.json files the
# suite's own gradings wrote (the solution, the starter, four correct alternatives, a wrong
# cloth, three wrong versions written from the handout, and a copy of one alternative with every
# local name renamed), and one submission whose results are missing. `a6_insights EXPORT
# --similarity` must
#   - name every submission and every rubric item, count the graded ones and the missing one,
#     name the wrong cloth's mistake, count each named mistake and who made it, and give a
#     check's pass rate;
#   - find the renamed copy (its pair, in every task file the copied student wrote), and no pair
#     of the independent correct solutions (the solution, float_intermediates, reordered,
#     handout_only); handout_only_2, nearly handout_only token for token, in at most one file;
#   - give a page Chromium opens from disk with its script run and no console error; its
#     screenshot is WORK/insights.png (docs/insights.png is one, by hand).
#
#   insights_test.sh SOURCE_DIR A6_INSIGHTS SCORES_OUT WORK
# SCORES_OUT: the grader_scores_* and alternative_* gradings' folder (each NAME/out/results.json).
set -uo pipefail
root="$1" insights="$2" scores="$3" work="$4"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
export="$work/export"
mkdir -p "$export"
: >"$export/submission_metadata.yml"

# add ID NAME RESULTS FILES...: submission_ID by NAME, with the task files FILES and the
# results.json RESULTS ("" for none).
add() {
  local id=$1 name=$2 results=$3
  shift 3
  mkdir -p "$export/submission_$id"
  cp "$@" "$export/submission_$id/"
  [ -z "$results" ] || cp "$results" "$export/submission_$id/results.json"
  printf 'submission_%s:\n  :submitters:\n  - :name: %s\n    :sid: "%s"\n' "$id" "$name" "$id" \
    >>"$export/submission_metadata.yml"
}
# The wrong versions and alternatives as the build applied their patches (cmake/A6Variants.cmake).
variants="${A6_VARIANTS:?BUILD/variants, set by ctest}"
alt="$variants/alternative"
add 101 "Ada Solution" "$scores/solution/out/results.json" "$root"/solution/*.cpp
add 102 "Ben Float" "$scores/alternative_float_intermediates/out/results.json" "$alt"/float_intermediates/*.cpp
add 103 "Cai Reordered" "$scores/alternative_reordered/out/results.json" "$alt"/reordered/*.cpp
add 104 "Dee Handout" "$scores/alternative_handout_only/out/results.json" "$alt"/handout_only/*.cpp
add 109 "Eve Handout" "$scores/alternative_handout_only_2/out/results.json" "$alt"/handout_only_2/*.cpp
add 105 "Fay Starter" "$scores/starter/out/results.json" "$root"/starter/*.cpp
cloth=t4_shear_with_structural_rest_length
add 106 "Gus Cloth" "$scores/wrong_$cloth/out/results.json" "$root"/solution/*.cpp
cp "$variants/wrong/$cloth/cloth.cpp" "$export/submission_106/"
add 107 "Ivy Missing" "" "$root"/solution/spring.cpp
# Three wrong versions written from the handout (tests/wrong/b*, c*), each submitted as its one
# task file: two forget to reset the forces, one leaves the mass out of gravity.
for w in "110 Kim b3_force_not_reset" "111 Lou c3_force_not_reset" "112 Max b2_gravity_no_mass"; do
  read -r id who wrong <<<"$w"
  add "$id" "$who Wrong" "$scores/wrong_$wrong/out/results.json" "$variants"/wrong/"$wrong"/*.cpp
done
# The copy: Cai's files with every name Cai declared (variables, parameters) renamed.
mkdir -p "$work/copy"
for f in "$alt"/reordered/*.cpp; do
  names=$(grep -oP '\b(?:double|float|int|auto|bool|Vec2|std::size_t|size_t|Eigen::\w+|b2Vec2|b2Body\*|Particle&|Spring&)\s+&?\K[a-z]\w*(?=\s*[=;,()\[])' "$f" |
          sort -u)
  cp "$f" "$work/copy/"
  for n in $names; do
    perl -pi -e "s/(?<![.\\w>])\\b$n\\b/renamed_$n/g" "$work/copy/$(basename "$f")"
  done
done
diff -q "$alt/reordered/spring.cpp" "$work/copy/spring.cpp" >/dev/null && fail "the copy renamed nothing"
add 108 "Hal Copy" "$scores/alternative_reordered/out/results.json" "$work"/copy/*.cpp

"$insights" "$export" --similarity --out "$work/insights.html" >"$work/insights.log" 2>&1 ||
  { cat "$work/insights.log"; fail "a6_insights failed"; }
page="$work/insights.html"
[ -s "$page" ] || { echo "FAIL: no page"; exit 1; }

# Every submission, every rubric item, the counts, the mistake, the missing results.
for name in "Ada Solution" "Ben Float" "Cai Reordered" "Dee Handout" "Eve Handout" "Fay Starter" \
            "Gus Cloth" "Ivy Missing" "Hal Copy" "Kim Wrong" "Lou Wrong" "Max Wrong"; do
  grep -qF "<td>$name</td>" "$page" || fail "the page does not list $name"
done
while IFS= read -r item; do
  grep -qF -- "$item" "$page" || fail "the page does not name the rubric item '$item'"
done < <(jq -r '.tests[].name | sub(" \\([0-9]+/[0-9]+ checks?\\)$"; "")' "$scores/solution/out/results.json")
grep -qF "12 submissions, 11 with a grade" "$page" || fail "the page does not count 12 submissions, 11 graded"
grep -qF "1 of 12 exported submissions hold no results.json" "$page" || fail "the missing results are not said"
grep -qF "<code>$cloth</code>" "$page" || fail "the wrong cloth's mistake is not named"
# Each named mistake with how many made it and who: its row's cells are the id, the task, the
# count, the example message and who.
for want in "t3_forces_not_reset:3:2:Kim Wrong, Lou Wrong" "t2_gravity_without_mass:2:1:Max Wrong"; do
  IFS=: read -r id task count who <<<"$want"
  cells=$(grep -oP "<tr><td><code>$id</code></td>.*?</tr>" "$page" | head -1 |
    sed -E 's|<td[^>]*>|\n|g; s|</td>||g; s|</?(tr\|code)>||g' | tail -n +2)
  [ "$(sed -n 2p <<<"$cells")" = "$task" ] && [ "$(sed -n 3p <<<"$cells")" = "$count" ] &&
    [ "$(sed -n 5p <<<"$cells")" = "$who" ] ||
    fail "the mistake $id (task $task) is not named for $count: $who; its row: ${cells:-none}"
done
# A check's pass rate: free fall, failed by the two who forgot to reset the forces and
# by the starter.
reset_row=$(grep -oP '<tr[^>]*><td><code>Task3TimeStepping.FreeFallMatchesTheDiscreteSum</code></td>.*?</tr>' "$page")
grep -qF '>8 of 11</td>' <<<"$reset_row" || fail "free fall is not passed by 8 of 11: $reset_row"

# Similarity: the copy's pairs, and no other.
pairs=$(grep -oP '<div class="pair"><p><b>\K[^<]*</b> and <b>[^<]*(?=</b>)' "$page" | sed 's|</b> and <b>| + |' | sort -u)
echo "pairs above the threshold:"
sed 's/^/  /' <<<"${pairs:-(none)}"
# Exactly these (docs/instructor.md says so): the copy, and the two near-identical handout
# solutions; no pair of the solution and the alternatives written apart from it, nor the wrong
# cloth with the solution it copies (in a class that writes that code alike).
[ "$pairs" = "Cai Reordered + Hal Copy"$'\n'"Dee Handout + Eve Handout" ] ||
  fail "the pairs are not the renamed copy and the two handout solutions alone"
grep -q 'sim_c++ (Debian' "$page" || fail "the page does not name the tool that compared"
copied=$(grep -c '<b>Cai Reordered</b> and <b>Hal Copy</b>' "$page")
[ "$copied" -eq 7 ] || fail "the copy was found in $copied task files, not all 7"
# The two solutions helper sessions wrote from the handout alone are nearly the same token for
# token (docs/instructor.md says in how many task files they are listed: this many).
twins=$(grep -c '<b>Dee Handout</b> and <b>Eve Handout</b>' "$page")
echo "the copy found in $copied task files; the handout twins listed in $twins"
[ "$twins" -eq 1 ] || fail "the two handout solutions listed in $twins task files (docs/instructor.md says one)"

# Chromium: the page opens from disk, its script runs (it marks the body), no console error.
if command -v chromium >/dev/null; then
  timeout 120 chromium --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0 \
    --dump-dom "file://$page" >"$work/dom.html" 2>"$work/chromium.log"
  grep -q 'data-sorted-ready="1"' "$work/dom.html" || fail "the page's script did not run in Chromium"
  if grep -qE 'CONSOLE|Uncaught' "$work/chromium.log"; then
    fail "Chromium's console: $(grep -E 'CONSOLE|Uncaught' "$work/chromium.log" | head -3)"
  fi
  timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --window-size=1280,2400 --screenshot="$work/insights.png" "file://$page" >/dev/null 2>&1
  [ -s "$work/insights.png" ] || fail "Chromium wrote no screenshot"
else
  echo "note: no chromium: the page was not opened"
fi

[ "$failures" -eq 0 ] || { echo "$failures insights checks failed"; exit 1; }
echo "insights: every check passed ($page)"
