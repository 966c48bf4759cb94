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

# seed_student_cache UID CACHE: when CACHE (the student's compiler cache, owned by UID) is empty,
# fills it with hard links to the caller's own cached objects, so that the student's first build
# of the release compiles only what the caller's build did not. The linked files stay the
# caller's (mode 0644: UID reads them and cannot change them, so nothing UID does reaches the
# caller's cache); the folders become UID's, so that its ccache adds, replaces and removes
# entries of its own. The caller's counters, configuration and inode cache are not linked.
# Does nothing when the caller has no cache or it lies on another file system.
seed_student_cache() {
  local uid=$1 cache=$2 from
  from=$(ccache --get-config=cache_dir 2>/dev/null) || return 0
  [ -d "$from" ] && [ -d "$cache" ] && [ -z "$(ls -A "$cache")" ] || return 0
  # Root's own builds may add and remove entries meanwhile, so that some links fail: an entry
  # missed is compiled again, nothing worse (on another file system every link fails).
  cp -al "$from/." "$cache/" 2>/dev/null
  find "$cache" -type f \( -name stats -o -name ccache.conf -o -name 'inode-cache*' \
    -o -name '*.lock' -o -path "$cache/tmp/*" \) -delete
  find "$cache" -type d -exec chown "$uid:$uid" {} +
  chmod 0700 "$cache"
  return 0
}
