// The process layer under the sandbox, a6_grade and a6_batch: what runs, waiting for one child
// with a deadline, ending strays, ending every process of a sandbox user, and claiming a sandbox
// user for one grading.
//
// Takes: pids and uids. Gives: facts read from /proc, and processes ended.
//
// Design note: reap only what you own.
// A grader that is a child subreaper inherits whatever its sandboxed children leave behind. It
// must reap those strays, but never with waitpid(-1): that also reaps a child another part of
// the grader is about to wait for (a6_batch hung forever on an a6_grade reaped that way). Every
// wait here names its pid.
//
// Design note: a sandbox user per grading.
// RLIMIT_NPROC counts every process of a user machine-wide, and a process that escaped its
// sandbox (a new session, a name with a newline that a line-by-line /proc reader skips) can go
// on killing whatever else runs as its user. So each grading claims a user of its own: a uid
// without an account, held by a lock file for the whole grading, and every process of that uid
// is ended before it is used and when the grading ends. Processes are found by their uid, read
// from /proc/PID/status (where names are escaped), never by their name or parent.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace a6::grader::process {

/// Seconds of the steady clock since `t` (every stage's timings).
inline double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// One process, as /proc/PID/status describes it.
struct Info {
  pid_t pid = 0;
  pid_t ppid = 0;
  uid_t realUid = 0;
  uid_t effectiveUid = 0;
  char state = '?';         ///< R, S, D, Z (zombie), ...
  int threads = 0;          ///< Threads:
  int seccompMode = -1;     ///< Seccomp: 0 none, 1 strict, 2 filter; -1 not shown
  int seccompFilters = -1;  ///< Seccomp_filters: (Linux 5.9+); -1 not shown
  bool noNewPrivs = false;  ///< NoNewPrivs: 1
};

/// The process `pid`, or nothing when it is gone (or /proc cannot be read).
std::optional<Info> describe(pid_t pid);

/// Every process this process can see.
std::vector<Info> all();

/// Waits for our child `pid` for at most `seconds` (0: only looks). Returns its wait status once
/// it has ended (and is reaped); nothing while it runs. A pid that is not (or no longer) our child
/// gives `vanished` = true and no status.
std::optional<int> waitFor(pid_t pid, double seconds, bool* vanished = nullptr);

/// Kills our children that are not in `keep` (with their process groups, when they lead one) and
/// reaps each of them by its pid; repeats while new ones appear (up to a bound). Returns how many
/// were ended.
int endStrayChildren(const std::vector<pid_t>& keep);

/// Ends every process whose real or effective uid is `uid` (never uid 0), found in /proc by
/// uid whatever it is named: each is stopped (a stopped process cannot fork), then killed,
/// through a pidfd so that a reused pid is never hit; repeated until /proc shows none alive or
/// `seconds` pass. Zombies that are our children are reaped. Returns "" when none is left, else
/// why not.
std::string endProcessesOf(uid_t uid, double seconds = 5);

/// A sandbox user held for one grading (see the design note): released, and its processes ended,
/// when destroyed.
class UidClaim {
 public:
  UidClaim() = default;
  ~UidClaim();
  UidClaim(UidClaim&& other) noexcept;
  UidClaim& operator=(UidClaim&& other) noexcept;
  UidClaim(const UidClaim&) = delete;
  UidClaim& operator=(const UidClaim&) = delete;

  bool held() const { return fd_ >= 0; }
  uid_t uid() const { return uid_; }

 private:
  friend UidClaim claimUid(std::optional<uid_t>, std::string&);
  int fd_ = -1;
  uid_t uid_ = 0;
};

/// Claims a sandbox user for one grading: `wanted` when given (waits up to a minute while
/// another grading holds it), else the first free uid below nobody's (65533, 65532, ...) that
/// has no account and no other grading's lock. Ends every process of it before returning, and
/// checks that a process can run as it. Not held (with `error`) when not root or when no uid
/// works.
UidClaim claimUid(std::optional<uid_t> wanted, std::string& error);

}  // namespace a6::grader::process
