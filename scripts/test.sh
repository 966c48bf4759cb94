#!/usr/bin/env bash
# The whole test suite: configure, build and run every test (the physics suite on the
# solution, the starter check, the wrong-version checks, the alternative solution).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default
cmake --build --preset default
ctest --preset default
