// Running an untrusted program: its own process, resource limits, a scrubbed environment, a
// fresh empty working directory, no network, captured and capped output, privileges dropped
// when the grader runs as root. See docs/instructor.md for what this does and does not protect.
//
// Design note: what the child gets, in order (everything is prepared before fork(): the plan in
// plan.cpp, the keeper and the fds in sandbox.cpp; the child between fork and exec, child.cpp,
// only makes system calls):
//   0. as root, a pid namespace of its own: the child is its init (the keeper), and the program
//      runs as the keeper's child. Whatever the program starts (a new session, a daemon, any
//      name) stays in the namespace and is ended by the kernel when the keeper ends, and no
//      signal from inside reaches a process outside: a grading ends only what it started, with
//      no search of the machine's processes by user id. The keeper hands the program's wait
//      status to the parent on a pipe. Where the kernel refuses (a container without
//      CAP_SYS_ADMIN), a plain fork, and Exit::notes says so;
//   1. its own session and process group (the parent kills the whole group with SIGKILL);
//   2. as root: a private mount namespace, with the pid namespace's own /proc, where every `hide`
//      path is covered (a directory by an empty tmpfs, a file by /dev/null), with the `reveal`
//      paths, the work dir and argv[0] bound back in place (allowOnly() makes `hide` an allow-list
//      of the machine); a folder above a revealed path that `uid` cannot search (a checkout in
//      /root, mode 0700) is covered too, and the way to the revealed path rebuilt with searchable
//      folders; the work dir a size-capped tmpfs when asked; then a new, empty network namespace;
//   3. rlimits: CPU, address space, file size, open files, processes, no core files;
//   4. stdin from /dev/null, stdout and stderr into one pipe the parent drains (capped at
//      Limits::outputBytes; the rest is read and dropped so the child never blocks), the
//      requested fds, every other fd closed;
//   5. cwd = the fresh work dir; as root: setgroups(0), setgid/setuid to `uid`/`gid` (a
//      grading's own user, grader/sandbox/process.h); a parent-death signal (SIGKILL);
//   6. no_new_privs and a seccomp filter: socket() fails with EACCES (the network stays off even
//      where namespaces are not permitted, e.g. an unprivileged Docker container), io_uring,
//      ptrace and process_vm_* fail with EPERM; with Limits::processes == 0, fork fails too;
//   7. execve(argv[0], argv, env) with `env` only.
// What could not be done (not root, namespaces refused) is said in Exit::notes, never silently.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace a6::grader {

struct Limits {
  double wallSeconds = 10;               ///< per request (probe) or per command (compiler), s
  double cpuSeconds = 60;                ///< RLIMIT_CPU for the whole process, s
  std::size_t memoryBytes = 512u << 20;  ///< RLIMIT_AS
  std::size_t fileSizeBytes = 1u << 20;  ///< RLIMIT_FSIZE
  int processes = 1;  ///< extra processes (and threads) it may create: RLIMIT_NPROC
                      ///< set to what its user runs at the start plus this (sandboxes
                      ///< sharing a uid share that headroom: give concurrent graders
                      ///< their own SandboxSpec::uid); 0 also refuses fork/clone in
                      ///< the seccomp filter
  std::size_t outputBytes = 64u << 10;  ///< stdout+stderr kept; the rest is dropped
  int openFiles = 64;                   ///< RLIMIT_NOFILE
};

/// The note of a sandbox run by a user other than root (a student's local check): it cannot hide
/// files or switch users, so the code ran as that user and saw what that user sees. One fixed
/// text, so that a grading's many sandbox runs say it once.
inline constexpr const char* kNotRootNote =
    "not running as root, so the code ran as this user and saw the files the graders' run hides "
    "(run as root, the grader hides them and runs the code as a user of its own)";

/// How a sandboxed process ended.
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
  std::filesystem::path workDir;  ///< created fresh and empty (an existing one is emptied);
                                  ///< the process's cwd; owned by `uid` when root drops
  bool removeWorkDir = false;     ///< remove workDir when the process ends (the probe's);
                                  ///< false keeps what it wrote (the compiler's object)
  Limits limits;
  std::vector<std::string> env = {"PATH=/usr/bin:/bin"};  ///< the whole environment
  std::vector<std::pair<int, int>> mapFds;    ///< {parent fd, child fd}: passed at another number
                                              ///< (the probe's pipes become its fds 3 and 4)
  std::vector<std::filesystem::path> hide;    ///< paths the child must not be able to read
  std::vector<std::filesystem::path> reveal;  ///< paths inside hidden ones that stay visible
                                              ///< (the work dir and argv[0] always do)
  std::size_t workDirTmpfsBytes = 0;  ///< > 0: the work dir is a tmpfs of this size (as root,
                                      ///< in the child's mount namespace)
  uid_t uid = 65534;                  ///< who the child runs as when the grader is root
  gid_t gid = 65534;                  ///< (nobody / nogroup)
};

/// True when `e` was killed by a SIGKILL that neither the grader (it kills at the wall-clock
/// limit: Kind::TimedOut) nor the CPU limit sent (it had not used it up): the machine's doing
/// (out of memory, another program), not the code's.
bool killedByTheMachine(const Exit& e, const Limits& limits);

/// Runs a command to completion in the sandbox (the compiler, the linker). Never throws for
/// what the command does; a setup failure is Kind::FailedToStart with `error`.
Exit runSandboxed(const SandboxSpec& spec);

/// A long-running sandboxed child (the probe): started, talked to, killed. Its output is
/// drained by a thread of this object, so it never blocks on a full pipe.
class SandboxedProcess {
 public:
  /// Starts it; on failure `error()` says why.
  explicit SandboxedProcess(const SandboxSpec& spec);
  ~SandboxedProcess();  ///< kills it (SIGKILL to its process group) and reaps it
  SandboxedProcess(const SandboxedProcess&) = delete;
  SandboxedProcess& operator=(const SandboxedProcess&) = delete;

  const std::string& error() const { return error_; }
  /// The child the grader started and kills: the program itself, or in a pid namespace its
  /// keeper (the namespace's init, which ends every process in it when it ends).
  pid_t pid() const { return pid_; }
  /// The program's own pid, to inspect it in /proc (-1 when gone or not found).
  pid_t programPid();
  /// False once it has exited (it stays unreaped, so its pid and group are not reused, until
  /// stop()).
  bool alive();
  /// What it printed so far (capped).
  std::string output() const;
  /// Protections that could not be applied (see Exit::notes).
  const std::vector<std::string>& notes() const;
  /// Kills and reaps it; returns how it ended (with its captured output). Calling it again
  /// returns the same Exit.
  Exit stop();

 private:
  pid_t pid_ = -1;
  std::string error_;
  // implementation details (output capture, timing) live in sandbox.cpp
  struct State;
  State* state_ = nullptr;
};

/// What a sandboxed child sees of the machine (SandboxSpec::hide and reveal).
struct SandboxView {
  std::vector<std::filesystem::path> hide;
  std::vector<std::filesystem::path> reveal;
};

/// The allow-list view: everything hidden but the system's programs and libraries (/usr and the
/// links into it, /etc/alternatives, the dynamic loader's cache), /proc, the devices /dev/null,
/// /dev/zero and /dev/urandom (in a /dev of their own), and `visible`. A child's work dir and
/// argv[0] are always visible too (SandboxSpec). As root only: without a mount namespace
/// nothing is hidden (Exit::notes says so, naming the `secrets` first: the paths that matter,
/// such as the grader's source and build trees, hidden except what is `visible` in them).
SandboxView allowOnly(const std::vector<std::filesystem::path>& visible,
                      const std::vector<std::filesystem::path>& secrets = {});

/// True when `inner` is `outer` or lies inside it (both absolute and lexically normal).
bool isWithin(const std::filesystem::path& inner, const std::filesystem::path& outer);

/// Adds to `out` what SandboxSpec::hide needs so that `secret` cannot be read except the `keep`
/// paths within it: the secret itself when nothing in it is kept, otherwise its other entries,
/// level by level down to what is kept. Links are not covered (that would cover their targets).
void hideExcept(const std::filesystem::path& secret, const std::vector<std::filesystem::path>& keep,
                std::vector<std::filesystem::path>& out, int depth = 0);

}  // namespace a6::grader
