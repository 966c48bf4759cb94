#!/usr/bin/env bash
# The main job: build, then run the physics suite on the solution and on the starter and print
# a per-task summary of each. The solution must pass everything; the starter fails every task
# (that is expected: it is what students start from).
set -uo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null && cmake --build --preset default || exit 1

status=0
echo
echo "=== solution/ ==="
./build/tests/a6_tests --gtest_brief=1 | sed -n '/^Summary by task/,$p' | grep -v '^A6-SUMMARY'
[ "${PIPESTATUS[0]}" -eq 0 ] || { echo "main: the solution failed tests"; status=1; }
echo
echo "=== starter/ (expected to fail every task) ==="
./build/tests/a6_tests_starter --gtest_brief=1 | sed -n '/^Summary by task/,$p' | grep -v '^A6-SUMMARY'
[ "${PIPESTATUS[0]}" -ne 0 ] || { echo "main: the starter passed everything, which it must not"; status=1; }
exit $status
