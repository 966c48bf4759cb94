#!/usr/bin/env bash
# Where libOSMesa is missing (Mesa 25.1 and later have none), the same binaries take EGL by
# themselves and the reference images still match: libOSMesa is hidden in a private mount
# namespace, then the render command must say it drew with EGL and the golden tests must pass.
#
#   tests/golden/without_osmesa_test.sh RENDER_COMMAND GOLDEN_TESTS SCRATCH_DIR
# Exit 77 (skipped) without root or unshare, or where libOSMesa is not installed anyway.
set -uo pipefail
render="$1" golden="$2" scratch="$3"
[ "$(id -u)" -eq 0 ] && command -v unshare >/dev/null || { echo "skipped: needs root and unshare"; exit 77; }
mapfile -t libraries < <(find /usr/lib /lib -name 'libOSMesa.so*' -type f 2>/dev/null)
[ "${#libraries[@]}" -gt 0 ] || { echo "skipped: no libOSMesa here to hide"; exit 77; }
rm -rf "$scratch" && mkdir -p "$scratch"
LIBRARIES="${libraries[*]}" RENDER="$render" GOLDEN="$golden" SCRATCH="$scratch" \
  unshare --mount --propagation private bash -c '
    for f in $LIBRARIES; do mount --bind /dev/null "$f" || exit 1; done
    echo "hidden: $LIBRARIES"
    "$RENDER" --scene pendulum --frames 0 --out "$SCRATCH" >"$SCRATCH/render.log" 2>&1
    cat "$SCRATCH/render.log"
    grep -q ", egl: " "$SCRATCH/render.log" || { echo "FAIL: the render command did not take EGL"; exit 1; }
    "$GOLDEN" --gtest_brief=1 >"$SCRATCH/golden.log" 2>&1 || { tail -40 "$SCRATCH/golden.log"; echo "FAIL: the golden tests on EGL"; exit 1; }
    tail -3 "$SCRATCH/golden.log"
  '
