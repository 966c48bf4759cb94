// The process layer under the sandbox, a6_grade and a6_batch: waiting for one child with a
// deadline, ending strays and a sandbox user's processes, claiming a sandbox user.
//
// Design notes. Reap only what you own: a child subreaper never reaps with waitpid(-1), which
// also takes a child another part of the grader waits for (a6_batch hung on an a6_grade reaped
// that way); every wait names its pid.
// A grading ends only what it started: other graders may share the machine's uids, so each
// sandboxed command has its own pid namespace and nothing searches the machine for processes to
// kill; only where pid namespaces are refused are a sandbox user's processes ended by uid.
// A sandbox user per grading, unused machine-wide: RLIMIT_NPROC counts a user's processes
// machine-wide, and file access is per user, so each grading claims a random uid far above any
// account (1e6 to 2e9 where every uid is mapped), with no account, no process in /proc and a
// lock file; graders that see neither (two containers) collide with a chance of about 1 in 2e9.
// Processes are found by the uid in /proc/PID/status (where names are escaped, so a process's
// name cannot fake the line), never by name or parent.
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
/// The time point `seconds` after `t` (deadlines).
inline std::chrono::steady_clock::time_point secondsAfter(std::chrono::steady_clock::time_point t,
                                                          double seconds) {
  return t + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                 std::chrono::duration<double>(seconds));
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
  pid_t nsPid = 0;          ///< its pid in its own (innermost) pid namespace (NSpid:)
};

/// The process `pid`, or nothing when it is gone (or /proc cannot be read).
std::optional<Info> describe(pid_t pid);

/// Every process this process can see.
std::vector<Info> all();

/// Waits up to `seconds` (0: only looks) for our child `pid`: its wait status once reaped,
/// nothing while it runs; `vanished` when it is not (or no longer) our child.
std::optional<int> waitFor(pid_t pid, double seconds, bool* vanished = nullptr);

/// Kills our children not in `keep` (and the groups they lead) and reaps each by its pid, while
/// new ones appear (up to a bound). Returns how many were ended.
int endStrayChildren(const std::vector<pid_t>& keep);

/// Whether sandboxed children get a pid namespace each (root, and the kernel allows it: tried
/// once, and false from the first sandbox refused one). When false, strays are ended by uid.
bool pidNamespaces();
/// A sandbox could not get its pid namespace (sandbox.cpp): from now on pidNamespaces() is false.
void pidNamespaceRefused();

/// The child of `parent` whose pid in its own namespace is `nsPid` (under a keeper: 2).
std::optional<pid_t> childInNamespace(pid_t parent, pid_t nsPid);

/// Ends every process whose real or effective uid is `uid` (never 0): each stopped (so it cannot
/// fork), then killed through a pidfd (a reused pid is never hit), until none is alive or
/// `seconds` pass; our zombies are reaped. Returns "" when none is left, else why not.
std::string endProcessesOf(uid_t uid, double seconds = 5);

/// A sandbox user held for one grading: released when destroyed (its processes ended by uid
/// where there are no pid namespaces).
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

/// Claims `wanted` (waiting up to a minute for another grading's lock), else an unused uid drawn
/// at random, and checks that a process runs as it. Not held (with `error`) when not root or no
/// uid works.
UidClaim claimUid(std::optional<uid_t> wanted, std::string& error);

}  // namespace a6::grader::process
