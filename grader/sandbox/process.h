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
// Design note: a grading ends only what it started.
// Other graders may run on the same machine: in the same checkout, another one, a chroot or a
// container with its own /run (so its own lock files), sharing the host's uids. A grading never
// signals a process it did not start: each sandboxed command runs in a pid namespace of its own
// (grader/sandbox/sandbox.h), so whatever the code leaves running ends with it, and nothing here
// searches the machine for processes to kill. Only where the kernel refuses pid namespaces (a
// container without CAP_SYS_ADMIN) are the sandbox user's processes found by uid and ended,
// and the grading's notes say so.
//
// Design note: a sandbox user per grading, unused machine-wide.
// RLIMIT_NPROC counts every process of a user machine-wide (per user namespace), and file access
// is per user. So each grading claims a user no one else runs as: a uid drawn at random from a
// range far above any account (1e6 to 2e9 where the user namespace maps every uid; within the
// mapped range otherwise), without an account, with no process in /proc, and held by a lock file
// (a second guard for graders that share /run/lock). Two graders that cannot see each other's
// processes or lock files (two containers) draw the same uid with a chance of about 1 in 2e9.
// Processes are found by their uid, read from /proc/PID/status (where names are escaped), never
// by their name or parent.
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
  pid_t nsPid = 0;          ///< its pid in its own (innermost) pid namespace (NSpid:)
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

/// Whether sandboxed children get a pid namespace each (root, and the kernel allows it; found
/// once by trying, and false from the first sandbox that could not get one). When false, what a
/// submission leaves running is ended by its uid.
bool pidNamespaces();
/// A sandbox could not get its pid namespace (sandbox.cpp): from now on pidNamespaces() is false.
void pidNamespaceRefused();

/// The child of `parent` whose pid in its own namespace is `nsPid` (the program under a keeper:
/// 2), found in /proc; nothing when there is none.
std::optional<pid_t> childInNamespace(pid_t parent, pid_t nsPid);

/// Ends every process whose real or effective uid is `uid` (never uid 0), found in /proc by
/// uid whatever it is named: each is stopped (a stopped process cannot fork), then killed,
/// through a pidfd so that a reused pid is never hit; repeated until /proc shows none alive or
/// `seconds` pass. Zombies that are our children are reaped. Returns "" when none is left, else
/// why not.
std::string endProcessesOf(uid_t uid, double seconds = 5);

/// A sandbox user held for one grading (see the design note): released when destroyed (and its
/// processes ended by uid where there are no pid namespaces).
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
/// another grading holds it), else a uid drawn at random (see the design note) that has no
/// account, no process and no other grading's lock. Checks that a process can run as it. Not
/// held (with `error`) when not root or when no uid works.
UidClaim claimUid(std::optional<uid_t> wanted, std::string& error);

}  // namespace a6::grader::process
