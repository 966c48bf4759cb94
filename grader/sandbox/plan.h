// The inside of the sandbox (not for use outside sandbox/): the Plan made before fork, the
// records the child reports failed steps in, and the parts by concern:
//   plan.cpp    the plan, made in the parent (makePlan); a failed step's sentence (describeRecord)
//   child.cpp   the child between fork and execve, system calls only (childMain)
//   filter.cpp  the seccomp program (filterFor)
//   output.cpp  the captured output (output.h)
//   sandbox.cpp starting, waiting, ending and capturing; the views
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
                         // namespace (a bind source must be in the caller's mount namespace)
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

// plan.cpp: the plan, or what keeps the sandbox from starting ("": none).
std::string makePlan(const SandboxSpec& spec, Plan& plan);
std::string describeRecord(const Record& r, const Plan& plan, const SandboxSpec& spec);
void deleteWorkDir(const std::string& dir);
// filter.cpp: the seccomp program (built once per kind), or empty with error set.
const std::vector<sock_filter>& filterFor(bool noFork, std::string& error);
// child.cpp: never returns (execve, or _exit 127).
[[noreturn]] void childMain(Plan& plan);

}  // namespace a6::grader::sandboxing
