#!/usr/bin/env bash
# Proof that the dev container works as a student meets it: this checkout's committed files are
# opened in it with the Dev Containers CLI (@devcontainers/cli: what VS Code's "Reopen in
# Container" and Codespaces run), which creates the container from .devcontainer/ and runs its
# commands (install-deps and the build, then the desktop); then the viewer is started in it on
# the desktop's display, and headless Chromium opens the noVNC page on port 6080 until its
# screenshot shows the viewer's window (checked against the headless renderer, as the ctest
# viewer_desktop_in_browser does). Prints the time from "open" to the viewer seen in the browser.
# Not part of CI: it needs Docker, and builds the project from nothing in the container.
#
#   scripts/try-devcontainer.sh
#
# Needs: a running Docker daemon with the image debian:12 (pulled, or `docker import`ed from a
# debootstrapped bookworm where Docker Hub cannot be reached), the CLI (npm install -g
# @devcontainers/cli), chromium, and this checkout's build/ (its a6_viewer_check).
# A6_DEVCONTAINER_HOST_NETWORK=1 puts the container on the host's network (a Docker daemon
# without a bridge, as on the project's build machine): port 6080 is then the host's, and the
# container reaches the package archive through the host; otherwise port 6080 is published.
# The workspace is /var/tmp/a6-devcontainer-ws (new each run); the logs are beside it. The
# container is removed at the end (A6_DEVCONTAINER_KEEP=1 keeps it).
set -uo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
ws=/var/tmp/a6-devcontainer-ws
say() { printf 'try-devcontainer: %s\n' "$*"; }
for c in docker devcontainer chromium; do
  command -v "$c" >/dev/null || { say "no $c (see the comment at the top)"; exit 2; }
done
docker info >/dev/null 2>&1 || { say "the Docker daemon does not answer"; exit 2; }
checker="$repo/build/tests/viewer/a6_viewer_check"
[ -x "$checker" ] || { say "no $checker: build this checkout first (cmake --build build)"; exit 2; }

# The workspace: the committed files, as a fresh clone has them.
docker ps -aq --filter "label=devcontainer.local_folder=$ws" | xargs -r docker rm -f >/dev/null
rm -rf "$ws" && mkdir -p "$ws"
(cd "$repo" && git archive --format=tar HEAD) | tar xf - -C "$ws"
(cd "$ws" && git init -q && git add -A && git -c user.email=a6@localhost -c user.name=a6 commit -qm snapshot)

# The container's settings, as committed, plus how to reach it here.
config="$ws.devcontainer.json"
if [ "${A6_DEVCONTAINER_HOST_NETWORK:-0}" = 1 ]; then
  run_args='"runArgs": ["--network=host"],'
else
  run_args='"runArgs": ["-p", "6080:6080"],'
fi
sed "s|^  \"image\": |  $run_args\n  \"image\": |" "$ws/.devcontainer/devcontainer.json" >"$config"

# The container is removed at the end (its desktop and viewer would keep a core busy), unless
# A6_DEVCONTAINER_KEEP=1.
remove_container() {
  [ "${A6_DEVCONTAINER_KEEP:-0}" = 1 ] ||
    docker ps -aq --filter "label=devcontainer.local_folder=$ws" | xargs -r docker rm -f >/dev/null
}
trap remove_container EXIT

start=$(date +%s.%N)
since() { echo "$(date +%s.%N) - $start" | bc | cut -d. -f1; }
say "opening $ws in the dev container (devcontainer up)"
devcontainer up --workspace-folder "$ws" --override-config "$config" >"$ws.up.log" 2>&1
status=$?
grep -E 'install-deps:|desktop:|outcome' "$ws.up.log" | sed 's/^/  /' | tail -8
[ "$status" -eq 0 ] || { tail -20 "$ws.up.log"; say "devcontainer up failed (exit status $status)"; exit 1; }
say "container up, built and its desktop started after $(since) s"

# What a student does next (README: "then, in a terminal"): the viewer on the desktop.
devcontainer exec --workspace-folder "$ws" --override-config "$config" bash -c \
  'nohup ./build/framework/viewer/a6_viewer --scene cloth_shear --paused --size 800x600 >/tmp/viewer.log 2>&1 &' \
  >"$ws.exec.log" 2>&1 || { cat "$ws.exec.log"; say "could not start the viewer"; exit 1; }
out="$ws.check"
rm -rf "$out" && mkdir -p "$out"
for attempt in $(seq 15); do
  sleep 2
  rm -f "$out/browser.png"
  timeout 90 chromium --headless --no-sandbox --disable-gpu --window-size=1280,800 \
    --virtual-time-budget=15000 --screenshot="$out/browser.png" \
    "http://localhost:6080/vnc.html?autoconnect=true&quality=9" >"$out/chromium.log" 2>&1
  if [ -s "$out/browser.png" ] &&
    "$checker" --scene cloth_shear --frames 0 --screenshot "$out/browser.png" --scene-area 800x600 \
      --lossy --tolerance 40 --max-fraction 0.05 --out "$out" >"$out/check.log" 2>&1; then
    cat "$out/check.log"
    say "the viewer seen in the browser $(since) s after \"open in a dev container\" (attempt $attempt): $out/browser.png"
    exit 0
  fi
done
cat "$out/check.log" 2>/dev/null
say "FAILED: the browser never showed the viewer (last screenshot: $out/browser.png)"
exit 1
