#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image, with the zip
# unpacked in /autograder/source (docs/instructor.md, "Gradescope"). In order:
#   1. checks the base image: Ubuntu 22.04 (Gradescope's default) or newer, or Debian 12 or
#      newer for an image of your own;
#   2. installs the packages of scripts/install-deps.sh that grading needs, with apt (those the
#      platform does not have are skipped: Ubuntu 22.04 has no toml++, and the zip carries a
#      header-only copy of it, vendor/tomlplusplus/);
#   3. builds a6_grade and its kit, and nothing else, in /autograder/source/build;
#   4. makes the grader's files unreadable to other users, except the kit student code is
#      compiled against (Docker may refuse the sandbox its mount namespace: see below);
#   5. grades the starter as a smoke check: a valid results.json with score 0, the probe started
#      (a stub passes the sanity checks), no grader error. A broken image fails here, at upload
#      time, and not on the first student's submission.
#
# For testing the package outside Gradescope:
#   A6_AUTOGRADER_ROOT=DIR   the autograder folder (default /autograder; the zip is in DIR/source)
#   A6_SKIP_APT=1            install nothing (the packages are already there); the base image is
#                            then only reported, not checked
set -euo pipefail

start=$(date +%s)

say() { printf 'setup.sh: %s\n' "$*"; }
die() {
  printf 'setup.sh: ERROR: %s\n' "$*" >&2
  exit 1
}

# Absolute and without links: the build tree's paths (kit.json) are compared with these below.
root=$(cd "${A6_AUTOGRADER_ROOT:-/autograder}" 2>/dev/null && pwd -P) ||
  die "no folder ${A6_AUTOGRADER_ROOT:-/autograder}"
src=$root/source
build=$src/build
seconds_since() { echo $(($(date +%s) - $1)); }

[ -f "$src/CMakeLists.txt" ] || die "no project in $src: the zip must be unpacked there"
say "autograder in $root; $(nproc) CPUs, $(awk '/MemTotal/ {printf "%d MiB", $2 / 1024}' /proc/meminfo) of memory"
[ -f "$src/autograder_version.txt" ] && sed 's/^/setup.sh: /' "$src/autograder_version.txt"

# 1. The base image. The grader needs CMake >= 3.22, GoogleTest >= 1.11, g++ >= 11 and toml++ 3:
# Ubuntu 22.04 (Gradescope's default) has all but toml++, which the zip brings
# (vendor/tomlplusplus/); Ubuntu 24.04 and Debian 12 and 13 have everything.
os_id="" os_version="" os_name="an unknown system (no /etc/os-release)"
if [ -r /etc/os-release ]; then
  os_id=$(. /etc/os-release && echo "${ID:-}")
  os_version=$(. /etc/os-release && echo "${VERSION_ID:-}")
  os_name=$(. /etc/os-release && echo "${PRETTY_NAME:-$ID $VERSION_ID}")
fi
at_least() { [ "$(printf '%s\n%s\n' "$1" "$2" | sort -V | head -n 1)" = "$1" ]; }
supported=0
case "$os_id" in
  ubuntu) at_least 22.04 "$os_version" && supported=1 ;;
  debian) at_least 12 "$os_version" && supported=1 ;;
esac
say "base image: $os_name"
if [ "$supported" -eq 0 ]; then
  why="its packages cannot build the grader (Ubuntu 22.04 or newer, or Debian 12 or newer, can)"
  if [ "${A6_SKIP_APT:-0}" = 1 ]; then
    say "warning: $os_name is not a supported base image ($why); A6_SKIP_APT=1, so going on"
  else
    die "this image runs $os_name, and $why.
On Gradescope: open the assignment's \"Configure Autograder\" page, choose the base image
  OS: Ubuntu, Version: 22.04 (or newer), Variant: Base
and upload the zip again. (For a Docker image of your own: Ubuntu 22.04 or 24.04, Debian 12 or 13.)"
  fi
fi

# 2. The packages: scripts/install-deps.sh's list (one list for the project), less what only the
# viewer, the benchmarks, the viewer's tests and packaging use.
if [ "${A6_SKIP_APT:-0}" = 1 ]; then
  say "A6_SKIP_APT=1: installing nothing"
else
  [ "$(id -u)" -eq 0 ] || die "installing packages needs root (Gradescope runs setup.sh as root)"
  packages=()
  eval "$(sed -n '/^packages=(/,/^)/p' "$src/scripts/install-deps.sh")"
  [ "${#packages[@]}" -gt 0 ] || die "no package list found in scripts/install-deps.sh"
  not_for_grading=" git ccache mold libbenchmark-dev libglfw3-dev libimgui-dev xvfb xauth x11vnc novnc websockify fonts-dejavu-core zip unzip jq universal-ctags "
  wanted=()
  for p in "${packages[@]}"; do
    [[ $not_for_grading == *" $p "* ]] || wanted+=("$p")
  done
  t=$(date +%s)
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  # What this platform has no package of is skipped, and said (Ubuntu 22.04: toml++, which the
  # zip carries).
  available=()
  # (apt-cache's whole answer is read first: `apt-cache ... | grep -q` under pipefail fails when
  # grep stops reading early and apt-cache dies of SIGPIPE, as it did on Ubuntu 22.04.)
  for p in "${wanted[@]}"; do
    policy=$(apt-cache policy "$p" 2>/dev/null) || policy=""
    if [[ $policy =~ Candidate:\ [^\(] ]]; then
      available+=("$p")
    else
      say "no package $p on $os_name: skipped"
    fi
  done
  say "installing ${available[*]}"
  apt-get install -y -q --no-install-recommends "${available[@]}"
  say "packages installed in $(seconds_since "$t") s"
fi

# 3. a6_grade and its kit, and nothing else, with the flags of the project's default build
# (RelWithDebInfo: -O2 -g -DNDEBUG; the reference images were made with them), so that a machine
# that built the project before (the tests) reuses its compiler cache where it has ccache; the
# starter as the configured student set (there is no solution/ here).
t=$(date +%s)
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DA6_STUDENT=starter -DA6_WRONG_VERSIONS=OFF -DA6_BUILD_BENCH=OFF
cmake --build "$build" --target a6_grade --parallel "$(nproc)"
[ -x "$build/grader/a6_grade" ] && [ -f "$build/grader/kit.json" ] ||
  die "the build did not produce grader/a6_grade and grader/kit.json"
build_seconds=$(seconds_since "$t")
say "a6_grade and its kit built in $build_seconds s"

# 4. File permissions. The compiler and the probe run as a sandbox user of their own (a uid
# without an account, so "other users" below); as root, the sandbox also shows them only an
# allow-list of the machine in a private mount namespace, but Docker (Gradescope's containers)
# may refuse that namespace, and then only file permissions keep student code from
# reading the hidden tests, the reference images and models and the rubric (the run's notes say
# which protection was missing). So nothing of the tree is readable by other users except the
# kit a submission is compiled and linked against: the paths under the build tree that
# kit.json names, and the folders leading to them (enterable, not listable).
chmod -R go-rwx "$src"
chmod o+x "$root"
open_for_sandbox() {
  local path=$1
  chmod -R o+rX "$path"
  local d
  d=$(dirname "$path")
  while [ "${#d}" -ge "${#root}" ]; do
    chmod o+x "$d"
    [ "$d" = "$root" ] && break
    d=$(dirname "$d")
  done
}
while IFS= read -r path; do
  case "$path" in "$build"/*) [ -e "$path" ] && open_for_sandbox "$path" ;; esac
done < <(grep -o '"/[^"]*"' "$build/grader/kit.json" | tr -d '"' | sort -u)

# 5. The smoke check: the starter, graded as a submission is.
t=$(date +%s)
smoke=$(mktemp -d "${TMPDIR:-/tmp}/a6_setup_smoke.XXXXXX")
chmod 0755 "$smoke"
status=0
"$build/grader/a6_grade" "$src/starter" --out "$smoke/out" --quiet --jobs 1 \
  >"$smoke/log" 2>&1 || status=$?
if [ "$status" -ne 0 ] || [ ! -s "$smoke/out/results.json" ]; then
  cat "$smoke/log" >&2
  [ -f "$smoke/out/results.json" ] && cat "$smoke/out/results.json" >&2
  die "the smoke check failed: a6_grade exited with $status grading the starter (above)"
fi
if command -v python3 >/dev/null; then
  python3 - "$smoke/out/results.json" <<'EOF' || die "the smoke check failed (above)"
import json, sys

r = json.load(open(sys.argv[1]))
tests = r.get("tests") or []
extra = r.get("extra_data") or {}
problems = []
if r.get("score") != 0:
    problems.append("the starter scored %r, not 0" % r.get("score"))
if not tests:
    problems.append("results.json lists no tests")
elif not any(t.get("status") == "passed" for t in tests):
    problems.append("no item passed, not even the sanity checks a stub passes: the probe did not run")
for e in extra.get("errors") or []:
    problems.append("grader error: " + e)
for note in extra.get("notes") or []:
    print("setup.sh: note from the smoke check: " + note)
for p in problems:
    print("setup.sh: " + p, file=sys.stderr)
sys.exit(1 if problems else 0)
EOF
else
  grep -Eq '"score": 0(\.0)?,' "$smoke/out/results.json" &&
    grep -q '"status": "passed"' "$smoke/out/results.json" ||
    die "the smoke check failed: the starter did not get a score of 0 with its sanity checks passed"
fi
rm -rf "$smoke"
say "smoke check passed: the starter graded in $(seconds_since "$t") s, score 0"
say "done in $(seconds_since "$start") s"
