#!/usr/bin/env bash
# The desktop in the browser (scripts/desktop.sh) for real: it starts, the viewer opens on its
# display (paused at frame 0), headless Chromium opens the noVNC page, and its screenshot must
# show the viewer's window: the scene as the headless renderer draws it (within what the VNC
# link's JPEG changes) and the control panel beside it.
#
#   tests/viewer/desktop_test.sh SOURCE_DIR VIEWER CHECKER OUT_DIR
# Exit code: 0 pass, 1 fail, 77 skipped (Xvfb, x11vnc, noVNC/websockify or Chromium missing).
set -uo pipefail
root="$1" viewer="$2" checker="$3" out="$4"
for c in Xvfb x11vnc websockify chromium python3; do
  command -v "$c" >/dev/null || { echo "SKIP: $c is not installed (scripts/install-deps.sh)"; exit 77; }
done
[ -d /usr/share/novnc ] || { echo "SKIP: noVNC is not installed (scripts/install-deps.sh)"; exit 77; }
rm -rf "$out" && mkdir -p "$out"

# A display, and its VNC and web ports, that nobody uses (a server left by another run may still
# hold a port after its display is gone).
taken() { (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
display=""
for n in $(seq 70 99); do
  [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ] || taken $((5900 + n)) ||
    taken $((16000 + n)) || { display=":$n"; break; }
done
[ -n "$display" ] || { echo "FAIL: no free X display in :70..:99"; exit 1; }
port=$((16000 + ${display#:}))
export A6_DESKTOP_DISPLAY="$display" A6_DESKTOP_PORT="$port" A6_DESKTOP_STATE="$out/desktop"
cleanup() {
  [ -n "${viewer_pid:-}" ] && kill "$viewer_pid" 2>/dev/null
  [ -n "${hold_pid:-}" ] && kill "$hold_pid" 2>/dev/null
  bash "$root/scripts/desktop.sh" stop >/dev/null
}
trap cleanup EXIT
# Killed outright (ctest's time-out on a loaded machine), this script runs no trap, and the
# desktop's servers, no children of it any more, would outlive it: a watcher outside its process
# tree stops them once this shell is gone.
setsid -f bash -c 'while kill -0 "$1" 2>/dev/null; do sleep 1; done
  bash "$2/scripts/desktop.sh" stop >/dev/null 2>&1' _ "$$" "$root"

start=$(date +%s.%N)
bash "$root/scripts/desktop.sh" start || { echo "FAIL: the desktop did not start"; exit 1; }
DISPLAY="$display" "$viewer" --scene cloth_shear --paused --size 800x600 >"$out/viewer.log" 2>&1 &
viewer_pid=$!
# The viewer's window is up when xwininfo... (not installed everywhere): give it a few seconds.
sleep 3
kill -0 "$viewer_pid" 2>/dev/null || { cat "$out/viewer.log"; echo "FAIL: the viewer exited"; exit 1; }
# Chromium's virtual time does not wait for the VNC connection, only for pending requests: the
# noVNC page is shown in a frame of a page that holds one request for 10 s of real time
# (hold_page.py), so that noVNC connects and draws before the shot. Should it still say
# "Connecting...", the page is shot again until the check passes, up to 8 times (a failed check
# is printed each time).
hold_port=$((port + 1000))
python3 "$(dirname "$0")/hold_page.py" "$hold_port" \
  "http://localhost:$port/vnc.html?autoconnect=true&quality=9" 10 >"$out/hold.log" 2>&1 &
hold_pid=$!
for _ in $(seq 100); do (exec 3<>"/dev/tcp/127.0.0.1/$hold_port") 2>/dev/null && break; sleep 0.1; done
for attempt in 1 2 3 4 5 6 7 8; do
  rm -f "$out/browser.png"
  timeout 90 chromium --headless --no-sandbox --disable-gpu --window-size=1280,800 \
    --virtual-time-budget=15000 --screenshot="$out/browser.png" \
    "http://127.0.0.1:$hold_port/" >"$out/chromium.log" 2>&1
  [ -s "$out/browser.png" ] || { tail -5 "$out/chromium.log"; echo "FAIL: Chromium wrote no screenshot"; exit 1; }
  # The window sits at the display's top-left corner (no window manager): the scene area is its
  # first 800x600 pixels, the panel right of it.
  "$checker" --scene cloth_shear --frames 0 --screenshot "$out/browser.png" --scene-area 800x600 \
    --lossy --tolerance 40 --max-fraction 0.05 --out "$out" >"$out/check.log" 2>&1
  status=$?
  if [ "$status" -eq 0 ]; then
    cat "$out/check.log"
    echo "the viewer seen in the browser at attempt $attempt," \
      "$(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s after the desktop's start: $out/browser.png"
    exit 0
  fi
  # A blank headless reference (the starter draws nothing) fails every screenshot: no retry.
  [ "$status" -ne 3 ] || { cat "$out/check.log"; echo "FAIL: nothing to see: the code draws nothing"; exit 1; }
  echo "attempt $attempt: $(grep -m1 FAIL "$out/check.log")"
  sleep 2
done
cat "$out/check.log"
echo "FAIL: the browser never showed the viewer (last screenshot: $out/browser.png)"
exit 1
