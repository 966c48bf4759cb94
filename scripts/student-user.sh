# A student's own user, for root's runs of the student's steps (sourced by
# tests/release/student_release_test.sh and scripts/bench-first-hour.sh; not shipped).

# free_student_uid FIRST LAST: prints the first uid in FIRST..LAST that has no account and no
# process on this machine; fails when every one is taken.
free_student_uid() {
  local uid
  for uid in $(seq "$1" "$2"); do
    getent passwd "$uid" >/dev/null || pgrep -U "$uid" >/dev/null || { echo "$uid"; return 0; }
  done
  return 1
}

# end_student_processes UID: ends every process of UID (a uid free_student_uid chose, so every one
# of its processes was started by the caller's runs as it).
end_student_processes() {
  pkill -KILL -U "$1" 2>/dev/null
  return 0
}

# run_as_student UID HOME CACHE COMMAND...: runs COMMAND as UID (its own gid, no other group),
# with HOME as its home folder and CACHE as its compiler cache.
run_as_student() {
  local uid=$1 home=$2 cache=$3
  shift 3
  setpriv --reuid="$uid" --regid="$uid" --clear-groups \
    env CCACHE_DIR="$cache" HOME="$home" USER=student LOGNAME=student "$@"
}
