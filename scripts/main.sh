#!/usr/bin/env bash
# The main job: build, then grade the solution and the starter with the grader, as a TA grades a
# submission (a6_grade: compiled and run in the sandbox, scored by grader/rubric.toml), into
# out/solution and out/starter (results.json, report.html; the summary is printed here); then
# re-render the reference images from the solution into out/goldens and compare them with the
# committed ones in tests/golden (which are left alone). The solution must get every point; the
# starter none (that is expected: it is what students start from). Last, it exports the student
# release (out/student-release, .zip) and the Gradescope autograder zip (out/gradescope/).
set -uo pipefail
cd "$(dirname "$0")/.." || exit 1
# What the main job runs (the grader, the batch grader, the renderer); scripts/test.sh builds the rest.
cmake --preset default >/dev/null && cmake --build --preset default --target a6_main_job || exit 1

build=build
status=0
if grep -q '^A6_GRADER_BUILT:INTERNAL=OFF$' "$build/CMakeCache.txt"; then
  echo "main: no grader in $build/: toml++ 3 (libtomlplusplus-dev) is missing, and the main job" \
    "grades with it. Ubuntu 22.04 has no package of it: run the main job on Ubuntu 24.04 or" \
    "Debian 12 or 13 (README.md, \"Platforms\")." >&2
  exit 1
fi

# grade NAME FOLDER: a6_grade FOLDER into out/NAME, its summary printed.
grade() {
  echo
  echo "=== $2/ graded by a6_grade: out/$1/report.html ==="
  rm -rf "out/$1"
  "$build/grader/a6_grade" "$2" --out "out/$1" --quiet
  local code=$?
  if [ "$code" -ne 0 ]; then
    echo "main: a6_grade failed on $2/ (exit status $code; see out/$1/results.json)"
    status=1
  fi
}

grade solution solution
if grep -q '"status": "failed"' out/solution/results.json 2>/dev/null; then
  echo "main: the solution lost points (see out/solution/report.html)"
  status=1
fi
grade starter starter
if ! grep -q '^  "score": 0.0,$' out/starter/results.json 2>/dev/null; then
  echo "main: the starter earned points, which it must not (see out/starter/report.html)"
  status=1
fi

# The reference images, re-rendered from the solution beside the committed ones.
echo
render="$build/framework/render/a6_render_solution"
if [ -x "$render" ]; then
  echo "=== the reference images, re-rendered from solution/: out/goldens ==="
  rm -rf out/goldens
  # render_set FROM TO: re-render the manifest of FROM into TO, compare TO's PNGs with FROM's.
  render_set() {
    mkdir -p "$2"
    cp "$1/manifest.json" "$2/"
    if ! "$render" --goldens --golden-dir "$2" >"$2/render.log" 2>&1; then
      echo "main: rendering the reference images of $1 failed:"
      tail -5 "$2/render.log"
      status=1
      return
    fi
    local same=0 differ="" png name
    for png in "$2"/*.png; do
      name=$(basename "$png")
      if cmp -s "$png" "$1/$name"; then
        same=$((same + 1))
      else
        differ="$differ $name"
      fi
    done
    echo "$same images identical to $1${differ:+; differing:$differ}"
    if [ -n "$differ" ]; then
      echo "main: some reference images differ from $1 (another renderer? see" \
        "docs/rendering.md; ctest -L golden compares them pixel by pixel)"
      status=1
    fi
  }
  render_set tests/golden out/goldens
  [ -d tests/golden/hidden ] && render_set tests/golden/hidden out/goldens/hidden
else
  echo "(no $render: this build has no headless GL; the reference images were not re-rendered)"
fi

# What goes to students and to Gradescope, from the committed files.
echo
echo "=== the student release and the Gradescope autograder zip: out/ ==="
rm -rf out/student-release out/student-release.zip
if ! A6_GRADE="$build/grader/a6_grade" grader/release/export-student.sh out/student-release --zip; then
  echo "main: exporting the student release failed"
  status=1
fi
if ! scripts/gradescope-package.sh out/gradescope/a6_autograder.zip; then
  echo "main: building the Gradescope zip failed"
  status=1
fi
exit $status
