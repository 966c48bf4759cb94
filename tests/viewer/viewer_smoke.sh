#!/usr/bin/env bash
# The viewer's smoke test: runs a6_viewer on a private Xvfb display for a fixed number of
# frames, saves a screenshot, and checks it against the headless render of the same frame.
#
#   viewer_smoke.sh VIEWER CHECKER OUTDIR SCENE FRAMES WxH gui|no-gui|side-by-side [checker options...]
#
# side-by-side: --no-gui --side-by-side; the left half is checked against the headless render
# with the other integrator than the scene's default (the scene's default is implicit), the
# right half against the scene's own.
#
# Exit code: 0 pass, 1 fail, 77 skipped (no Xvfb installed).
set -u
if [ $# -lt 7 ]; then
  echo "usage: $0 VIEWER CHECKER OUTDIR SCENE FRAMES WxH gui|no-gui|side-by-side [checker options...]" >&2
  exit 2
fi
viewer=$1 checker=$2 outdir=$3 scene=$4 frames=$5 size=$6 gui=$7
shift 7

if ! command -v Xvfb >/dev/null 2>&1; then
  echo "SKIP: Xvfb is not installed (Debian: apt-get install xvfb xauth)"
  exit 77
fi

mkdir -p "$outdir"
shot="$outdir/${scene}_frame${frames}_${gui}.png"
rm -f "$shot"

# A private X server on a free display: Xvfb picks the number itself (-displayfd), so tests
# running in parallel never race for one.
displayfile="$outdir/xvfb-display-$$"
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$displayfile" 2>"$outdir/xvfb-$$.log" &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; wait $xvfb 2>/dev/null; rm -f "$displayfile" "$outdir/xvfb-$$.log"' EXIT
for _ in $(seq 100); do
  [ -s "$displayfile" ] && break
  sleep 0.1
done
if [ ! -s "$displayfile" ]; then
  echo "FAIL: Xvfb did not start:"
  cat "$outdir/xvfb-$$.log"
  exit 1
fi
export DISPLAY=":$(head -n1 "$displayfile")"

args=(--scene "$scene" --frames "$frames" --size "$size" --screenshot "$shot")
checkargs=()
if [ "$gui" = no-gui ]; then
  args+=(--no-gui)
elif [ "$gui" = side-by-side ]; then
  args+=(--no-gui --side-by-side)
else
  checkargs+=(--scene-area "$size")
fi
echo "DISPLAY=$DISPLAY $viewer ${args[*]}"
timeout 120 "$viewer" "${args[@]}"
status=$?
if [ $status -ne 0 ] || [ ! -f "$shot" ]; then
  echo "FAIL: a6_viewer exited with status $status${shot:+ (screenshot $shot)}"
  exit 1
fi

if [ "$gui" = side-by-side ]; then
  width=${size%x*} height=${size#*x}
  half=$((width / 2))
  mkdir -p "$outdir/left" "$outdir/right"
  echo "left half: symplectic Euler"
  "$checker" --scene "$scene" --frames "$frames" --screenshot "$shot" --out "$outdir/left" \
    --scene-area "${half}x$height" --view-left 0 --other-integrator "$@" || exit 1
  echo "right half: implicit Euler"
  "$checker" --scene "$scene" --frames "$frames" --screenshot "$shot" --out "$outdir/right" \
    --scene-area "$((width - half))x$height" --view-left "$half" "$@"
  exit
fi
"$checker" --scene "$scene" --frames "$frames" --screenshot "$shot" --out "$outdir" \
  "${checkargs[@]}" "$@"
