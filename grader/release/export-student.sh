#!/usr/bin/env bash
# Exports the student release: what students receive, and nothing of the graders'.
#
#   grader/release/export-student.sh DEST [--zip]
#
# DEST (a new or empty folder) receives the committed files (`git ls-files`) that
# grader/release/contents.txt lists: the framework, the starter, the public tests and their
# reference images, the grader for the local check, the student's guides and commands; with:
#   README.md                        grader/release/README.md (the students' two commands)
#   grader/rubric.toml               the public rubric (a6_grade --public-rubric: no hidden items)
#   .github/workflows/classroom.yml  grader/release/classroom.yml (GitHub Classroom)
#   RELEASE                          the commit it was exported from
# Nothing untracked or built travels. The graders' material (the solution, the hidden checks and
# images, the reference replays and force models, the known mistakes, the wrong versions, the
# grader's tests, the instructors' guide) fails the export if the list brings it in; last, the
# export is scanned for solution text (scan-release.sh): a hit fails the export, naming the file
# and line.
#
# --zip also writes DEST.zip (for the course page). A6_GRADE names the a6_grade binary that writes
# the public rubric (default: build/grader/a6_grade, built if missing).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"

dest="" zip=0
for arg in "$@"; do
  case "$arg" in
    --zip) zip=1 ;;
    -h | --help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "export-student: unknown option $arg" >&2; exit 2 ;;
    *) [ -z "$dest" ] || { echo "export-student: one DEST only" >&2; exit 2; }; dest="$arg" ;;
  esac
done
[ -n "$dest" ] || { echo "usage: grader/release/export-student.sh DEST [--zip]" >&2; exit 2; }
if [ -e "$dest" ] && [ -n "$(ls -A "$dest" 2>/dev/null)" ]; then
  echo "export-student: $dest exists and is not empty: give a new folder" >&2
  exit 2
fi
top=$(git -C "$root" rev-parse --show-toplevel 2>/dev/null) ||
  { echo "export-student: $root is not a git checkout (the release is taken from git)" >&2; exit 1; }
# A copy inside another checkout would list that checkout's files under it (the build folder's).
[ "$(cd "$top" && pwd -P)" = "$(cd "$root" && pwd -P)" ] ||
  { echo "export-student: $root is not a git checkout itself but lies inside $top (the release is taken from git)" >&2; exit 1; }

# What the release holds: grader/release/contents.txt (folders end in /, "!" takes out).
mapfile -t entries < <(sed -e 's/#.*//' -e 's/[[:space:]]*$//' "$here/contents.txt" | grep -v '^$')
matches() {  # matches ENTRY PATH: the entry (without its "!") names the path or a folder above it
  local entry="$1" path="$2"
  if [[ "$entry" == */ ]]; then [[ "$path" == "$entry"* ]]; else [[ "$path" == "$entry" ]]; fi
}
in_release() {  # the last entry that matches a path decides
  local path="$1" entry verdict=1
  for entry in "${entries[@]}"; do
    if [[ "$entry" == '!'* ]]; then matches "${entry#!}" "$path" && verdict=1
    else matches "$entry" "$path" && verdict=0; fi
  done
  return "$verdict"
}
# The graders' material: never released, whatever contents.txt says (a wrong entry there fails
# the export instead of shipping it).
never=(solution/ tests/hidden/ tests/golden/hidden/ tests/golden/replays/
       grader/reference/ tests/reference/ tests/wrong/ tests/alternative/ tests/grader/
       grader/mistakes/library/ docs/instructor.md .ci/)

# The public rubric, from the graders' rubric.
grade="${A6_GRADE:-$root/build/grader/a6_grade}"
if [ ! -x "$grade" ]; then
  echo "export-student: $grade is missing: building it in $root/build, for the public rubric" \
    "(about 2 minutes the first time; A6_GRADE=/path/to/a6_grade uses another)"
  (cd "$root" && { [ -f build/CMakeCache.txt ] || cmake --preset default >/dev/null; } &&
    cmake --build build --target a6_grade >/dev/null)
fi
mkdir -p "$dest"
dest="$(cd "$dest" && pwd)"
"$grade" --rubric "$root/grader/rubric.toml" --public-rubric "$dest/rubric.public.toml"

count=0
while IFS= read -r -d '' path; do
  in_release "$path" || continue
  for x in "${never[@]}"; do
    if matches "$x" "$path"; then
      echo "export-student: grader/release/contents.txt brings in $path, graders' material" >&2
      exit 1
    fi
  done
  [ -e "$root/$path" ] || continue  # deleted in the working tree, not yet committed
  mkdir -p "$dest/$(dirname "$path")"
  cp -p "$root/$path" "$dest/$path"
  count=$((count + 1))
done < <(git -C "$root" ls-files -z)

mkdir -p "$dest/grader" "$dest/.github/workflows"
mv "$dest/rubric.public.toml" "$dest/grader/rubric.toml"
cp "$here/README.md" "$dest/README.md"
cp "$here/classroom.yml" "$dest/.github/workflows/classroom.yml"
printf 'Assignment 6 student release, exported %s from commit %s\n' \
  "$(date -u +%Y-%m-%d)" "$(git -C "$root" rev-parse --short HEAD)" >"$dest/RELEASE"

if ! bash "$here/scan-release.sh" "$root" "$dest"; then
  echo "export-student: the export in $dest holds graders' material (above): not released" >&2
  exit 1
fi
echo "export-student: $((count + 4)) files in $dest (no solution, no hidden checks or images)"

if [ "$zip" -eq 1 ]; then
  rm -f "$dest.zip"
  (cd "$(dirname "$dest")" && zip -qr "$dest.zip" "$(basename "$dest")")
  echo "export-student: $dest.zip"
fi
