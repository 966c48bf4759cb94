#!/usr/bin/env bash
# Proof on another platform: debootstraps a fresh root of it from its own archive (Debian's or
# Ubuntu's), puts this checkout's committed files in it, and runs there, as root, what a user of
# that platform runs; it prints what each job printed last and the ctest summary. Not part of CI
# (it downloads a system and builds everything: 10 to 40 minutes on 2 cores); its output goes in
# the notes of the change that needs it.
#
#   scripts/try-platform.sh PLATFORM [JOB...]
#
# PLATFORM: debian12 (bookworm), debian13 (trixie), ubuntu2204 (jammy: Gradescope's default image, WSL's Ubuntu) or
# ubuntu2404 (noble). The root is /var/tmp/a6-PLATFORM (kept for a re-run; $A6_TRY_ROOT replaces
# it), and each job's whole log is beside it (/var/tmp/a6-PLATFORM.JOB.log).
# JOB (default: the platform's own list, below):
#   main        the README's first command in a git checkout: scripts/install-deps.sh && scripts/main.sh
#   test        the README's second command: scripts/test.sh (the whole suite; ctest's summary)
#   gradescope  the Gradescope zip (made here by scripts/gradescope-package.sh) as Gradescope runs
#               it: setup.sh as root in /autograder/source (it installs its packages with apt),
#               then run_autograder on the solution and on the starter; they must get 113 and 0
#   student     the student release (made here by grader/release/export-student.sh) as a student
#               runs it: its scripts/install-deps.sh as root, then, as a user of their own (not
#               root) in a folder of their 0700 home, scripts/check.sh twice (each timed) and
#               scripts/test.sh; check.sh may say at most one line about the grader's sandbox
#
# Needs root, debootstrap (apt-get install debootstrap), gpg, and the platform's archive over the
# network (deb.debian.org, archive.ubuntu.com). Exit status: 0 when every job did what it must.
set -uo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
say() { printf 'try-platform: %s\n' "$*"; }
usage() { sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
[ $# -ge 1 ] || usage
platform=$1
shift
case "$platform" in
  debian12) suite=bookworm mirror=${A6_DEBIAN_MIRROR:-http://deb.debian.org/debian} default_jobs="main student" ;;
  debian13) suite=trixie mirror=${A6_DEBIAN_MIRROR:-http://deb.debian.org/debian} default_jobs="main test" ;;
  ubuntu2204) suite=jammy mirror=${A6_UBUNTU_MIRROR:-http://archive.ubuntu.com/ubuntu} default_jobs="gradescope student" ;;
  ubuntu2404) suite=noble mirror=${A6_UBUNTU_MIRROR:-http://archive.ubuntu.com/ubuntu} default_jobs="gradescope main student" ;;
  -h | --help) usage ;;
  *) say "unknown platform $platform (debian12, debian13, ubuntu2204, ubuntu2404)"; exit 2 ;;
esac
jobs="${*:-$default_jobs}"
target="${A6_TRY_ROOT:-/var/tmp/a6-$platform}"
[ "$(id -u)" -eq 0 ] || { say "run as root"; exit 2; }
command -v debootstrap >/dev/null || { say "no debootstrap: apt-get install debootstrap"; exit 2; }
start=$(date +%s)

# ---- the root -----------------------------------------------------------------------------------
# Ubuntu's archive is checked against Ubuntu's own signing key (2018), taken from its keyring
# package and accepted only with the key's known fingerprint.
ubuntu_keyring() {
  local dir=/var/tmp/a6-ubuntu-keyring fpr=F6ECB3762474EDA9D21B7022871920D1991BC93C
  if [ ! -s "$dir/ubuntu-archive-keyring.gpg" ]; then
    mkdir -p "$dir/x" && (
      cd "$dir" &&
        curl -fsSL -o keyring.deb "$mirror/pool/main/u/ubuntu-keyring/ubuntu-keyring_2021.03.26_all.deb" &&
        dpkg-deb -x keyring.deb x &&
        cp x/usr/share/keyrings/ubuntu-archive-keyring.gpg .
    ) || { say "could not fetch Ubuntu's keyring"; return 1; }
  fi
  local keys
  keys=$(gpg --show-keys --with-colons "$dir/ubuntu-archive-keyring.gpg" 2>/dev/null)
  grep -q "^fpr:*$fpr:" <<<"$keys" ||
    { say "Ubuntu's keyring lacks the archive key $fpr"; return 1; }
  echo "$dir/ubuntu-archive-keyring.gpg"
}
if [ ! -x "$target/usr/bin/apt-get" ]; then
  say "debootstrap $suite into $target (minbase)"
  args=(--variant=minbase)
  script=()
  case "$platform" in
    ubuntu*)
      keyring=$(ubuntu_keyring) || exit 1
      args+=(--keyring="$keyring" --components=main,universe)
      # Debian 12's debootstrap predates noble; every Ubuntu suite uses the same script.
      [ -e "/usr/share/debootstrap/scripts/$suite" ] || script=(/usr/share/debootstrap/scripts/gutsy)
      ;;
  esac
  debootstrap "${args[@]}" "$suite" "$target" "$mirror" "${script[@]}" >"$target.debootstrap.log" 2>&1 ||
    { tail -20 "$target.debootstrap.log"; say "debootstrap failed"; exit 1; }
  if [ "${platform#ubuntu}" != "$platform" ]; then
    # As Ubuntu's own images have it: universe, and the updates.
    printf 'deb %s %s main universe\n' "$mirror" "$suite" "$mirror" "$suite-updates" "$mirror" "$suite-security" \
      >"$target/etc/apt/sources.list"
  fi
fi
say "root ready after $(($(date +%s) - start)) s: $(. "$target/etc/os-release" && echo "$PRETTY_NAME")"
cp /etc/resolv.conf "$target/etc/resolv.conf"

# Mounts for the build's sandbox and the tests (namespaces, /proc, /dev, /sys, a tmpfs /tmp).
# The root itself is bound onto itself first: the grader's sandbox makes "/" private in its
# mount namespace, which needs "/" to be a mount point, as it is on a real system.
# The machine's /run/lock is shared with the root: graders inside and outside claim their
# sandbox uids there (grader/sandbox/process.h), so they never take the same uid and end each
# other's
# processes.
cleanup() {
  for m in run/lock dev/pts dev proc sys tmp; do umount -l "$target/$m" 2>/dev/null; done
  umount -l "$target" 2>/dev/null
  rm -rf "$stage"
}
stage=$(mktemp -d /tmp/a6-try.XXXXXX)
trap cleanup EXIT
mount --bind "$target" "$target"
mount -t proc proc "$target/proc"
mount --rbind /sys "$target/sys"
mount --rbind /dev "$target/dev"
mount -t tmpfs tmpfs "$target/tmp"
mkdir -p "$target/run/lock" /run/lock
mount --bind /run/lock "$target/run/lock"

inside() { chroot "$target" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 bash -c "$1"; }
inside 'apt-get update -q >/dev/null && apt-get install -y -q git ca-certificates >/dev/null' ||
  { say "apt-get could not install git inside"; exit 1; }

# ---- the jobs -----------------------------------------------------------------------------------
failures=0
# run_job NAME COMMAND [any]: COMMAND inside, its output in $target.NAME.log, its last $lines
# lines shown. A non-zero exit status is a failure, unless "any" (the starter's checks fail).
run_job() {
  local t status
  t=$(date +%s)
  say "=== $1: $2 ==="
  inside "$2" >"$target.$1.log" 2>&1
  status=$?
  tail -n "${lines:-20}" "$target.$1.log"
  say "$1: exit status $status in $(($(date +%s) - t)) s (whole log: $target.$1.log)"
  [ "$status" -eq 0 ] || [ "${3:-}" = any ] || failures=$((failures + 1))
}
# A git checkout of the committed files, as a fresh clone has them.
checkout_into() {
  rm -rf "$target/$1" && mkdir -p "$target/$1"
  (cd "$repo" && git archive --format=tar HEAD) | tar xf - -C "$target/$1"
  inside "cd /$1 && git init -q && git add -A && git -c user.email=a6@localhost -c user.name=a6 commit -qm snapshot"
}

for job in $jobs; do
  case "$job" in
    main)
      checkout_into opt/a6 || { say "no checkout"; exit 1; }
      lines=25 run_job main 'cd /opt/a6 && scripts/install-deps.sh && scripts/main.sh'
      ;;
    test)
      [ -d "$target/opt/a6/.git" ] || checkout_into opt/a6 || { say "no checkout"; exit 1; }
      run_job test 'cd /opt/a6 && scripts/install-deps.sh >/dev/null && scripts/test.sh'
      grep -E 'tests passed|tests failed|Total Test time|\(Failed\)|\(Timeout\)|\(Not Run\)' "$target.test.log" | tail -30
      grep -c 'warning:' "$target.test.log" | sed 's/^/try-platform: compiler warnings: /'
      ;;
    gradescope)
      bash "$repo/scripts/gradescope-package.sh" "$stage/a6_autograder.zip" >"$stage/package.log" 2>&1 ||
        { tail "$stage/package.log"; say "the zip could not be made"; exit 1; }
      rm -rf "$target/autograder" && mkdir -p "$target/autograder/source"
      inside 'apt-get install -y -q unzip >/dev/null' && cp "$stage/a6_autograder.zip" "$target/tmp/" &&
        inside 'cd /autograder/source && unzip -q /tmp/a6_autograder.zip && cp run_autograder /autograder/' ||
        { say "could not unpack the zip inside"; exit 1; }
      lines=6 run_job gradescope-setup 'bash /autograder/source/setup.sh'
      for who in solution starter; do
        rm -rf "$target/autograder/submission" "$target/autograder/results"
        mkdir -p "$target/autograder/submission" "$target/autograder/results"
        cp "$repo/$who"/*.cpp "$target/autograder/submission/"
        lines=4 run_job "gradescope-$who" 'cd /autograder && ./run_autograder'
        cp "$target/autograder/results/results.json" "$target.gradescope-$who.json" 2>/dev/null
      done
      solution=$(jq -r .score "$target.gradescope-solution.json" 2>/dev/null)
      starter=$(jq -r .score "$target.gradescope-starter.json" 2>/dev/null)
      say "Gradescope zip on $suite: solution $solution, starter $starter"
      [ "$solution" = 113 ] && { [ "$starter" = 0 ] || [ "$starter" = 0.0 ]; } ||
        { say "FAILED: the solution must get 113 and the starter 0"; failures=$((failures + 1)); }
      ;;
    student)
      [ -x "$repo/build/grader/a6_grade" ] || { say "student: build a6_grade here first (cmake --build build --target a6_grade)"; exit 1; }
      A6_GRADE="$repo/build/grader/a6_grade" bash "$repo/grader/release/export-student.sh" "$stage/release" \
        >"$stage/export.log" 2>&1 || { tail "$stage/export.log"; say "the release could not be exported"; exit 1; }
      # The student's own user and home (0700), the release unzipped there by them.
      inside 'id student >/dev/null 2>&1 || useradd -m -s /bin/bash student' ||
        { say "no user could be made inside"; exit 1; }
      rm -rf "$target/home/student/a6" && cp -a "$stage/release" "$target/home/student/a6"
      inside 'chown -R student:student /home/student && chmod 0700 /home/student'
      # install-deps as root (the README's sudo step); then everything as the student. The starter
      # fails its checks: check.sh and test.sh must run to the end and say so.
      lines=12 run_job student-deps 'cd /home/student/a6 && scripts/install-deps.sh'
      as_student='runuser -u student -- env -i HOME=/home/student PATH=/usr/bin:/bin LANG=C.UTF-8'
      lines=12 run_job student-check "cd /home/student/a6 && $as_student scripts/check.sh" any
      lines=3 run_job student-check-again "cd /home/student/a6 && $as_student scripts/check.sh" any
      lines=12 run_job student-test "cd /home/student/a6 && $as_student scripts/test.sh" any
      sandbox_lines=$(grep -ci 'sandbox' "$target.student-check.log")
      say "student: check.sh's lines about the sandbox: $sandbox_lines"
      [ "$sandbox_lines" -le 1 ] || { say "FAILED: more than one line about the sandbox"; failures=$((failures + 1)); }
      for part in check test; do
        grep -q 'Task 1' "$target.student-$part.log" ||
          { say "FAILED: student $part: no summary by task"; failures=$((failures + 1)); }
        grep -qE ': error: |CMake Error' "$target.student-$part.log" &&
          { say "FAILED: student $part: a build error"; failures=$((failures + 1)); }
      done
      ;;
    *) say "unknown job $job (main, test, gradescope, student)"; exit 2 ;;
  esac
done
say "$platform: $jobs: $failures failure(s), $(($(date +%s) - start)) s in all"
[ "$failures" -eq 0 ]
