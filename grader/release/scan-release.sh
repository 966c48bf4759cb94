#!/usr/bin/env bash
# Scans a student release for graders' material:
#
#   grader/release/scan-release.sh ROOT DEST
#
# ROOT is the instructors' checkout, DEST the release. Fails (exit 1), naming file and line, when
# DEST holds
#   - a graders' path: solution/, tests/hidden/, tests/golden/hidden/, tests/golden/replays/,
#     grader/reference/ (the reference physics), grader/mistakes/library/ (the known mistakes);
#   - a line of code of the solution, the hidden checks, the mistakes or the reference physics:
#     every line of those files that is not a comment, is at least 25 characters long (shorter
#     ones, such as "return f;", are in any C++ file) and is not also in the public code
#     (starter/ and framework/; for all but the solution, the public tests too), compared with
#     leading and trailing blanks trimmed. A line of the solution in a public test is refused;
#   - a hidden reference image, by content (sha256), under any name;
#   - in a test's source, a helper that computes the answer: a function whose name says it
#     gives the expected or correct value (expectedTotal, correctStep, answerFor, ...). Public
#     tests compare with numbers computed by hand or with properties, never with a second copy
#     of the task's formula (docs/instructor.md, "The student release").
set -euo pipefail
root="$1" dest="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
found=0

for path in solution tests/hidden tests/golden/hidden tests/golden/replays \
            grader/reference grader/mistakes/library; do
  if [ -e "$dest/$path" ]; then
    echo "scan: $path is in the release" >&2
    found=1
  fi
done
while IFS= read -r -d '' file; do
  echo "scan: ${file#"$dest"/} is in the release (a graders' file name)" >&2
  found=1
done < <(find "$dest" \( -name physics.inc -o -name hidden_test.cpp \) -print0)

trimmed() { sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' "$@"; }

# The secret lines, less the public ones: the solution's less what the starter and the framework
# hold (a public test holds none of them: a line of the solution in a test is the answer); the
# hidden checks', the library of known mistakes' and the reference physics' less the public
# tests' too (they share their helpers and the harness's names).
shopt -s nullglob
answers=("$root"/solution/*.cpp)
hidden_checks=("$root"/tests/hidden/* "$root"/grader/mistakes/library/{,measured/}*.{h,cpp}
  "$root"/grader/reference/*.{inc,h,cpp})
# (Every test file outside the graders' folders: the library of known mistakes shares plain loops
# with the scene tests, say.)
mapfile -t public_tests < <(find "$root/tests" \( -path "$root/tests/hidden" -o -path "$root/tests/wrong" \
  -o -path "$root/tests/alternative" \) -prune -o -type f \( -name '*.cpp' -o -name '*.h' \) -print)
code_lines() { trimmed "$@" | grep -v -e '^//' -e '^/\*' -e '^\*' | awk 'length($0) >= 25' | sort -u; }
# (The grader's own code is public too, all but the library of known mistakes.)
{ trimmed "$root"/starter/*; find "$root/framework" -type f \( -name '*.h' -o -name '*.cpp' \) \
    -exec sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' {} +
  find "$root/grader" -path "$root/grader/mistakes/library" -prune -o -type f \
    \( -name '*.h' -o -name '*.cpp' \) -exec sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' {} +
} | sort -u >"$work/public"
trimmed "${public_tests[@]}" | sort -u | sort -u - "$work/public" >"$work/public_and_tests"
{
  code_lines "${answers[@]}" | comm -23 - "$work/public"
  [ "${#hidden_checks[@]}" -eq 0 ] || code_lines "${hidden_checks[@]}" | comm -23 - "$work/public_and_tests"
} | sort -u >"$work/lines"
if [ ! -s "$work/lines" ]; then
  echo "scan: no secret lines to look for (is $root the instructors' checkout?)" >&2
  exit 1
fi

# One grep over every text file finds those holding a secret line anywhere in a line (a
# superset); only they are compared line by line, trimmed.
while IFS= read -r -d '' file; do
  if hits="$(trimmed "$file" | grep -nFx -f "$work/lines")"; then
    while IFS= read -r hit; do
      echo "scan: ${file#"$dest"/}:${hit%%:*}: solution text: ${hit#*:}" >&2
    done <<<"$hits"
    found=1
  fi
done < <(find "$dest" -type f -print0 | xargs -0 -r grep -IlZF -f "$work/lines" -- 2>/dev/null)

# Helpers that compute the answer, by their name: a definition (not a call) of a function or a
# lambda named expected..., correct..., answer..., solution..., oracle..., ideal... (any case) in
# a test's source. A name is all this rule sees: a formula written inline, under another name,
# passes it (docs/instructor.md, "The student release", says what the review must catch).
answer_name='([Ee]xpected|[Cc]orrect|[Aa]nswer|[Ss]olution|[Oo]racle|[Ii]deal)([A-Z_][A-Za-z0-9_]*)?'
answer_helper="^[[:space:]]*([A-Za-z_][A-Za-z0-9_:<>,]*[[:space:]&*]+)+${answer_name}[[:space:]]*\\([^;]*\$|\\bauto[[:space:]]+${answer_name}[[:space:]]*=[[:space:]]*\\["
while IFS= read -r -d '' file; do
  if hits="$(grep -nE "$answer_helper" "$file")"; then
    while IFS= read -r hit; do
      echo "scan: ${file#"$dest"/}:${hit%%:*}: a helper that computes the answer (public tests compare with numbers computed by hand or with properties): ${hit#*:}" >&2
    done <<<"$hits"
    found=1
  fi
done < <(find "$dest" -path "$dest/tests/*" -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.inc' \) -print0)

# Hidden images, by content.
for png in "$root"/tests/golden/hidden/*.png; do
  sha256sum "$png" | cut -d' ' -f1
done | sort -u >"$work/hidden_png"
if [ -s "$work/hidden_png" ]; then
  while IFS= read -r -d '' png; do
    if grep -qx "$(sha256sum "$png" | cut -d' ' -f1)" "$work/hidden_png"; then
      echo "scan: ${png#"$dest"/} is a hidden reference image" >&2
      found=1
    fi
  done < <(find "$dest" -type f -name '*.png' -print0)
fi

if [ "$found" -eq 0 ]; then
  echo "scan: $(wc -l <"$work/lines") secret lines and $(wc -l <"$work/hidden_png") hidden images looked for in $(find "$dest" -type f | wc -l) files: none found"
fi
exit "$found"
