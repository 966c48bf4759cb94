// The inside of the sandbox (sandbox/, not for use outside it): the Plan that sandbox.cpp makes
// before fork, the records the child reports its steps in, and the parts by concern:
//   plan.cpp    what the child will do, prepared in the parent: mounts (what is hidden and what
//               revealed), the work folder, limits, fds (makePlan); the sentence for a step that
//               failed (describeRecord)
//   child.cpp   the child between fork and execve, system calls only: its session, namespaces,
//               mounts, network, limits, fds, user, filter, exec (childMain)
//   filter.cpp  the seccomp program (filterFor)
//   output.cpp  the captured output and how the pipe is read (output.h)
//   sandbox.cpp starting, waiting, ending and capturing (runSandboxed, SandboxedProcess), views
#pragma once

#include <linux/filter.h>
#include <sys/resource.h>
#include <sys/types.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "sandbox/sandbox.h"

namespace a6::grader::sandboxing {

inline std::string errnoText(int err) { return std::strerror(err); }

// The status pipe's records: a step of the child that failed (fatal or not), with its errno.

enum Stage : std::int32_t {
  kSetsid = 1,
  kUnshareMounts,
  kMountPrivate,
  kHide,
  kReveal,
  kUnshareNet,
  kDevNull,
  kFds,
  kRlimit,
  kChdir,
  kSetgroups,
  kSetgid,
  kSetuid,
  kDeathSignal,
  kNoNewPrivs,
  kSeccomp,
  kExec,
  kWorkTmpfs,
  kProc,
  kFork,
};

struct Record {
  std::int32_t fatal;
  std::int32_t stage;
  std::int32_t err;
  std::int32_t index;
};

struct MountOp {
  enum Kind { HideDir, HideFile, Reveal } kind = HideDir;
  std::size_t depth = 0;
  std::string path;
  // Reveal only:
  std::vector<std::string> chain;  // the ancestors of path, outermost first
  bool isDir = false;
  int fd = -1;           // O_PATH fd on the original, opened by the child in its new
                         // namespace (a bind source must be in the caller's namespace)
  char source[32] = {};  // "/proc/self/fd/<fd>", written by the child
};

struct Limit {
  int resource;
  rlim_t soft, hard;
};

struct Plan {
  std::vector<std::string> args, envs;
  std::vector<char*> argv, envp;
  std::string workDir;
  bool root = false;
  bool dropPrivileges = false;
  uid_t uid = 65534;
  gid_t gid = 65534;
  pid_t parent = 0;           // the program's parent as the program sees it (getppid())
  bool pidNamespace = false;  // the child is the init of its own pid namespace (the keeper)
  int endFd = -1;             // the keeper writes the program's wait status here
  int keeperFd = -1;          // a6-keeper, opened before anything is hidden (or -1)
  std::string keeperEndFd;    // its argument: endFd in digits
  std::vector<char*> keeperArgv;
  std::vector<MountOp> ops;
  std::string workTmpfs;  // tmpfs options for the work dir ("": none)
  std::vector<Limit> limits;
  std::vector<std::pair<int, int>> fds;  // {source, target} besides 0/1/2
  int highBase = 0;
  int maxFd = 1024;
  int statusFd = -1;
  int outFd = -1;
  std::vector<sock_filter> filter;
  std::vector<std::string> notes;  // found by the parent
};

// plan.cpp: the plan for spec, or what keeps the sandbox from starting ("": none).
std::string makePlan(const SandboxSpec& spec, Plan& plan);
// plan.cpp: the sentence for a record the child sent.
std::string describeRecord(const Record& r, const Plan& plan, const SandboxSpec& spec);
// plan.cpp: removes a work folder the plan made.
void deleteWorkDir(const std::string& dir);
// filter.cpp: the seccomp program (built once per kind), or empty with error set.
const std::vector<sock_filter>& filterFor(bool noFork, std::string& error);
// child.cpp: the child's whole life after fork: never returns (execve, or _exit 127).
[[noreturn]] void childMain(Plan& plan);

}  // namespace a6::grader::sandboxing
