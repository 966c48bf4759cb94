// Running an untrusted program: its own process, resource limits, a scrubbed environment, a
// fresh empty work dir, no network, capped output, privileges dropped when the grader is root.
// See docs/instructor.md for what this does and does not protect.
//
// Design note: what the child gets, in order (prepared before fork; child.cpp then makes only
// system calls):
//   0. as root, a pid namespace whose init (the keeper) runs the program: whatever the program
//      starts ends with the keeper and cannot signal outside, so a grading ends only what it
//      started, with no search by uid. Where refused (no CAP_SYS_ADMIN), a plain fork;
//   1. its own session and process group (killed whole with SIGKILL);
//   2. as root, a private mount namespace with its own /proc, `hide` covered (a folder by an
//      empty tmpfs, a file by /dev/null) and `reveal`, the work dir and argv[0] bound back
//      (allowOnly() makes it an allow-list), a folder above a reveal that `uid` cannot search
//      covered and the way rebuilt; then no network;
//   3. rlimits: CPU, address space, file size, open files, processes, no core files;
//   4. stdin /dev/null, stdout and stderr one pipe the parent drains (so the child never
//      blocks), the requested fds, every other fd closed;
//   5. cwd the work dir; as root no groups and `uid`/`gid`; SIGKILL when the parent dies;
//   6. no_new_privs and seccomp: socket() fails with EACCES (no network even without
//      namespaces), io_uring, ptrace and process_vm_* with EPERM, fork too when processes == 0;
//   7. execve(argv[0], argv, env) with `env` only.
// What could not be done is said in Exit::notes, never silently.
#pragma once

#include <sys/stat.h>
#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/limits.h"

namespace a6::grader {

/// The modes of what the grader makes for the sandbox's user: a folder it reaches (rwxr-xr-x),
/// a file it reads (rw-r--r--).
constexpr std::filesystem::perms kOpenFolder = std::filesystem::perms(0755);
constexpr std::filesystem::perms kReadableFile = std::filesystem::perms(0644);

struct Limits {
  double wallSeconds = kDefaultTimeLimit;       ///< per request (probe) or command (compiler), s
  double cpuSeconds = kProbeCpuSeconds;         ///< RLIMIT_CPU for the whole process, s
  std::size_t memoryBytes = kProbeMemoryBytes;  ///< RLIMIT_AS
  std::size_t fileSizeBytes = 1u << 20;         ///< RLIMIT_FSIZE
  int processes = 1;  ///< extra processes and threads: RLIMIT_NPROC is its user's count plus
                      ///< this (shared by a uid's sandboxes); 0 also refuses fork in seccomp
  std::size_t outputBytes = 64u << 10;  ///< stdout+stderr kept; the rest is dropped
  int openFiles = 64;                   ///< RLIMIT_NOFILE
};

/// The note of a run not as root (nothing hidden, no user switch): one fixed text, said once.
inline constexpr const char* kNotRootNote =
    "not running as root, so the code ran as this user and saw the files the graders' run hides "
    "(run as root, the grader hides them and runs the code as a user of its own)";

struct Exit {
  enum class Kind { Exited, Signaled, TimedOut, FailedToStart } kind = Kind::Exited;
  int code = 0;        ///< exit status or signal number
  std::string output;  ///< captured stdout+stderr, capped at Limits::outputBytes
  bool outputTruncated = false;
  double wallSeconds = 0;
  double cpuSeconds = 0;  ///< CPU time of the program and what it waited for (0 when timed out)
  std::string error;      ///< FailedToStart: why ("exec /x/a6_probe: Permission denied ...")
  std::vector<std::string> notes;  ///< protections that could not be applied, and why
  std::string describe() const;  ///< "exited with 1", "killed by SIGSEGV (segmentation fault)", ...
  bool ok() const { return kind == Kind::Exited && code == 0; }
};

struct SandboxSpec {
  std::vector<std::string> argv;  ///< argv[0] is an absolute path
  std::filesystem::path workDir;  ///< its cwd, made fresh and empty, owned by `uid` as root
  bool removeWorkDir = false;     ///< removed at the end (the probe's), else kept (an object)
  Limits limits;
  std::vector<std::string> env = {"PATH=/usr/bin:/bin"};  ///< the whole environment
  std::vector<std::pair<int, int>> mapFds;    ///< {parent fd, child fd} (the probe's 3 and 4)
  std::vector<std::filesystem::path> hide;    ///< paths the child must not be able to read
  std::vector<std::filesystem::path> reveal;  ///< visible inside hidden ones, as workDir and
                                              ///< argv[0] always are
  std::size_t workDirTmpfsBytes = 0;  ///< > 0: the work dir is a tmpfs of this size (as root)
  uid_t uid = 65534;                  ///< who the child runs as when the grader is root
  gid_t gid = 65534;                  ///< (nobody / nogroup)
};

/// True when `e` was killed by a SIGKILL neither the grader (Kind::TimedOut) nor the CPU limit
/// sent: the machine's doing (out of memory, another program), not the code's.
bool killedByTheMachine(const Exit& e, const Limits& limits);

/// Runs a command to completion (the compiler, the linker); a setup failure is FailedToStart.
Exit runSandboxed(const SandboxSpec& spec);

/// A long-running sandboxed child (the probe). A thread drains its output, so it never blocks.
class SandboxedProcess {
 public:
  /// Starts it; on failure `error()` says why.
  explicit SandboxedProcess(const SandboxSpec& spec);
  ~SandboxedProcess();  ///< kills it (SIGKILL to its process group) and reaps it
  SandboxedProcess(const SandboxedProcess&) = delete;
  SandboxedProcess& operator=(const SandboxedProcess&) = delete;

  const std::string& error() const { return error_; }
  /// The program's own pid, to inspect it in /proc (-1 when gone or not found).
  pid_t programPid();
  /// False once it has exited (unreaped until stop(), so its pid and group are not reused).
  bool alive();
  /// What it printed so far (capped).
  std::string output() const;
  /// Protections that could not be applied (see Exit::notes).
  const std::vector<std::string>& notes() const;
  /// Kills and reaps it; returns how it ended (the same Exit when called again).
  Exit stop();

 private:
  pid_t pid_ = -1;
  std::string error_;
  struct State;
  State* state_ = nullptr;
};

/// What a sandboxed child sees of the machine (SandboxSpec::hide and reveal).
struct SandboxView {
  std::vector<std::filesystem::path> hide;
  std::vector<std::filesystem::path> reveal;
};

/// The allow-list view: everything hidden but the system's programs and libraries, /proc,
/// /dev/null, /dev/zero and /dev/urandom (in a /dev of their own), and `visible`. As root only:
/// without a mount namespace nothing is hidden, and the notes say so naming the `secrets` (the
/// grader's trees, first in `hide`, hidden except what is `visible` in them).
SandboxView allowOnly(const std::vector<std::filesystem::path>& visible,
                      const std::vector<std::filesystem::path>& secrets = {});

/// True when `inner` is `outer` or lies inside it (both absolute and lexically normal).
bool isWithin(const std::filesystem::path& inner, const std::filesystem::path& outer);

/// `path` absolute and lexically normal, its links resolved as far as it exists.
std::filesystem::path absoluteClean(const std::filesystem::path& path);

/// Whether `uid`/`gid` (no supplementary groups) may read (`want` 4) or search (1) by the bits.
bool permits(const struct stat& st, uid_t uid, gid_t gid, unsigned want);

}  // namespace a6::grader
