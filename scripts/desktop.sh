#!/usr/bin/env bash
# A desktop in the browser, for the viewer where there is no screen (a dev container, Codespaces,
# a server): a virtual X display (Xvfb), a VNC server on it (x11vnc) and noVNC served by
# websockify, all Debian packages (scripts/install-deps.sh). One command:
#
#   scripts/desktop.sh [start|stop|status]     default start
#
# then open http://localhost:6080/vnc.html?autoconnect=true (in a dev container or Codespaces,
# the forwarded port 6080) and start the viewer with DISPLAY=:1, for example
#   DISPLAY=:1 ./build/framework/viewer/a6_viewer --scene cloth_shear
# $A6_DESKTOP_DISPLAY (default :1), $A6_DESKTOP_PORT (default 6080) and $A6_DESKTOP_SIZE (default
# 1280x800) change the defaults. Processes and logs: /tmp/a6-desktop/ (or $A6_DESKTOP_STATE).
set -uo pipefail
display="${A6_DESKTOP_DISPLAY:-:1}"
port="${A6_DESKTOP_PORT:-6080}"
size="${A6_DESKTOP_SIZE:-1280x800}"
state="${A6_DESKTOP_STATE:-/tmp/a6-desktop}"
vnc_port=$((5900 + ${display#:}))
say() { printf 'desktop: %s\n' "$*"; }

running() { [ -f "$state/$1.pid" ] && kill -0 "$(cat "$state/$1.pid")" 2>/dev/null; }

# Ends each server: SIGTERM, then SIGKILL after 3 s (an x11vnc whose display went first can
# ignore SIGTERM, and would hold its port for the next desktop).
stop() {
  local p pid i
  for p in websockify x11vnc xvfb; do
    if running "$p"; then
      pid="$(cat "$state/$p.pid")"
      kill "$pid" 2>/dev/null
      for i in $(seq 30); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
      kill -9 "$pid" 2>/dev/null
    fi
    rm -f "$state/$p.pid"
  done
  say "stopped"
}

# Whether something already listens on a TCP port on localhost.
listening() { (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }

status() {
  local p all=0
  for p in xvfb x11vnc websockify; do
    if running "$p"; then say "$p running (pid $(cat "$state/$p.pid"))"; else say "$p not running"; all=1; fi
  done
  return "$all"
}

# Waits up to 10 s for a TCP port on localhost to accept connections.
wait_port() {
  local i
  for i in $(seq 100); do
    listening "$1" && return 0
    sleep 0.1
  done
  return 1
}

start() {
  local missing=()
  for c in Xvfb x11vnc websockify; do command -v "$c" >/dev/null || missing+=("$c"); done
  [ -d /usr/share/novnc ] || missing+=("noVNC (/usr/share/novnc)")
  if [ ${#missing[@]} -gt 0 ]; then
    say "missing: ${missing[*]} (scripts/install-deps.sh installs xvfb, x11vnc, novnc, websockify)"
    return 1
  fi
  mkdir -p "$state"
  if status >/dev/null; then
    say "already running: http://localhost:$port/vnc.html?autoconnect=true (DISPLAY=$display)"
    return 0
  fi
  stop >/dev/null
  local i
  # Another program on a port would answer for ours, and the browser would show its screen.
  for i in "$vnc_port" "$port"; do
    if listening "$i"; then
      say "port $i is taken by another program: choose another display or port"
      return 1
    fi
  done
  Xvfb "$display" -screen 0 "${size}x24" -nolisten tcp >"$state/xvfb.log" 2>&1 &
  echo $! >"$state/xvfb.pid"
  for i in $(seq 50); do [ -e "/tmp/.X11-unix/X${display#:}" ] && break; sleep 0.1; done
  x11vnc -display "$display" -forever -shared -nopw -localhost -rfbport "$vnc_port" -quiet \
    >"$state/x11vnc.log" 2>&1 &
  echo $! >"$state/x11vnc.pid"
  wait_port "$vnc_port" || { say "x11vnc did not start (see $state/x11vnc.log)"; stop >/dev/null; return 1; }
  websockify --web /usr/share/novnc "$port" "localhost:$vnc_port" >"$state/websockify.log" 2>&1 &
  echo $! >"$state/websockify.pid"
  wait_port "$port" || { say "websockify did not start (see $state/websockify.log)"; stop >/dev/null; return 1; }
  say "running: open http://localhost:$port/vnc.html?autoconnect=true"
  say "then, in a terminal: DISPLAY=$display ./build/framework/viewer/a6_viewer --scene cloth_shear"
}

case "${1:-start}" in
  start) start ;;
  stop) stop ;;
  status) status ;;
  *) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0" >&2; exit 2 ;;
esac
