#!/usr/bin/env bash
# The main job: build, then grade the solution and the starter with the grader, as a TA grades a
# submission (a6_grade: compiled and run in the sandbox, scored by grader/rubric.toml), into
# out/solution and out/starter (results.json, report.html; the summary is printed here); then
# re-render the reference images from the solution into out/goldens and compare them with the
# committed ones in tests/golden (which are left alone). The solution must get every point; the
# starter none (that is expected: it is what students start from).
set -uo pipefail
cd "$(dirname "$0")/.." || exit 1
cmake --preset default >/dev/null && cmake --build --preset default || exit 1

build=build
status=0

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
  mkdir -p out/goldens
  cp tests/golden/manifest.json out/goldens/
  if "$render" --goldens --golden-dir out/goldens >out/goldens/render.log 2>&1; then
    same=0 differ=""
    for png in out/goldens/*.png; do
      name=$(basename "$png")
      if cmp -s "$png" "tests/golden/$name"; then
        same=$((same + 1))
      else
        differ="$differ $name"
      fi
    done
    echo "$((same)) images identical to tests/golden${differ:+; differing:$differ}"
    if [ -n "$differ" ]; then
      echo "main: some reference images differ from tests/golden (another renderer? see" \
        "docs/rendering.md; ctest -L golden compares them pixel by pixel)"
      status=1
    fi
  else
    echo "main: rendering the reference images failed:"
    tail -5 out/goldens/render.log
    status=1
  fi
else
  echo "(no $render: this build has no headless GL; the reference images were not re-rendered)"
fi
exit $status
