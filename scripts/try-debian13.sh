#!/usr/bin/env bash
# Proof on Debian 13 ("trixie"): debootstraps a fresh trixie root from Debian's archive, copies
# this checkout's committed files into it (/opt/a6), runs the README's two commands there as
# root (scripts/install-deps.sh && scripts/main.sh, then scripts/test.sh) and prints the ctest
# summary. Not part of CI (it downloads a system and builds everything: about half an hour on 2
# cores); its output goes in the notes of the change that needs it.
#
#   scripts/try-debian13.sh [ROOT_DIR]      default /var/tmp/a6-trixie (kept for a re-run)
#
# Needs root, debootstrap (apt-get install debootstrap) and network access to deb.debian.org.
# Exit status: scripts/test.sh's inside the root (0 when every test passed).
set -uo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
target="${1:-/var/tmp/a6-trixie}"
mirror="${A6_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
say() { printf 'try-debian13: %s\n' "$*"; }
[ "$(id -u)" -eq 0 ] || { say "run as root"; exit 2; }
command -v debootstrap >/dev/null || { say "no debootstrap: apt-get install debootstrap"; exit 2; }

start=$(date +%s)
if [ ! -x "$target/usr/bin/apt-get" ]; then
  say "debootstrap trixie into $target (minbase)"
  debootstrap --variant=minbase trixie "$target" "$mirror" >"$target.debootstrap.log" 2>&1 ||
    { tail -20 "$target.debootstrap.log"; say "debootstrap failed"; exit 1; }
fi
say "root ready after $(($(date +%s) - start)) s: $(. "$target/etc/os-release" && echo "$PRETTY_NAME")"

# The checkout as a fresh clone would have it: the committed files, in a git repository of its own.
rm -rf "$target/opt/a6"
mkdir -p "$target/opt/a6"
(cd "$repo" && git archive --format=tar HEAD) | tar xf - -C "$target/opt/a6"
cp /etc/resolv.conf "$target/etc/resolv.conf"

# Mounts for the build's sandbox and the tests (namespaces, /proc, /dev, /sys, a tmpfs /tmp).
# The root itself is bound onto itself first: the grader's sandbox makes "/" private in its
# mount namespace, which needs "/" to be a mount point, as it is on a real system.
# The machine's /run/lock is shared with the root: graders inside and outside claim their
# sandbox uids there (grader/process.h), so they never take the same uid and end each other's
# processes.
cleanup() {
  for m in run/lock dev/pts dev proc sys tmp; do umount -l "$target/$m" 2>/dev/null; done
  umount -l "$target" 2>/dev/null
}
trap cleanup EXIT
mount --bind "$target" "$target"
mount -t proc proc "$target/proc"
mount --rbind /sys "$target/sys"
mount --rbind /dev "$target/dev"
mount -t tmpfs tmpfs "$target/tmp"
mkdir -p "$target/run/lock" /run/lock
mount --bind /run/lock "$target/run/lock"

inside() { chroot "$target" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 bash -c "$1"; }
t=$(date +%s)
inside 'apt-get update -q >/dev/null && apt-get install -y -q git >/dev/null &&
  cd /opt/a6 && git init -q && git add -A && git -c user.email=a6@localhost -c user.name=a6 commit -qm snapshot' ||
  { say "could not make the git checkout inside"; exit 1; }
say "=== scripts/install-deps.sh && scripts/main.sh ==="
inside 'cd /opt/a6 && scripts/install-deps.sh && scripts/main.sh' >"$target.main.log" 2>&1
main_status=$?
tail -25 "$target.main.log"
say "main job: exit status $main_status in $(($(date +%s) - t)) s (whole log: $target.main.log)"
t=$(date +%s)
say "=== scripts/test.sh ==="
inside 'cd /opt/a6 && scripts/test.sh' >"$target.test.log" 2>&1
test_status=$?
grep -E 'tests passed|tests failed|Total Test time|\(Failed\)|\(Timeout\)|\(Not Run\)|\*\*\*' "$target.test.log" | tail -30
grep -c 'warning:' "$target.test.log" | sed 's/^/compiler warnings: /'
say "test suite: exit status $test_status in $(($(date +%s) - t)) s (whole log: $target.test.log)"
exit "$test_status"
