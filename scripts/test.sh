#!/usr/bin/env bash
# The whole test suite: configure, build and run every test with ctest. In the instructors'
# checkout: the physics suite on the solution, the starter check, the wrong versions, the
# alternative solution, images, grader and packaging. In a student release: the public tests on
# the starter (or the student's work), which fail until the tasks are done.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default
cmake --build --preset default
ctest --preset default
