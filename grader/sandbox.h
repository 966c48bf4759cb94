// Running an untrusted program: its own process, resource limits, a scrubbed environment, a
// fresh empty working directory, no network, captured and capped output, privileges dropped
// when the grader runs as root. See docs/instructor.md for what this does and does not protect.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace a6::grader {

struct Limits {
  double wallSeconds = 10;        ///< per request (probe) or per command (compiler), s
  double cpuSeconds = 60;         ///< RLIMIT_CPU for the whole process, s
  std::size_t memoryBytes = 512u << 20;   ///< RLIMIT_AS
  std::size_t fileSizeBytes = 1u << 20;   ///< RLIMIT_FSIZE
  int processes = 1;              ///< extra processes it may create (RLIMIT_NPROC, counted per uid
                                  ///< when privileges are dropped; otherwise a seccomp rule)
  std::size_t outputBytes = 64u << 10;    ///< stdout+stderr kept; the rest is dropped
};

/// How a sandboxed process ended.
struct Exit {
  enum class Kind { Exited, Signaled, TimedOut, FailedToStart } kind = Kind::Exited;
  int code = 0;         ///< exit status or signal number
  std::string output;   ///< captured stdout+stderr, capped at Limits::outputBytes
  bool outputTruncated = false;
  double wallSeconds = 0;
  std::string describe() const;  ///< "exited with 1", "killed by SIGSEGV (segmentation fault)", ...
};

struct SandboxSpec {
  std::vector<std::string> argv;        ///< argv[0] is an absolute path
  std::filesystem::path workDir;        ///< created fresh and empty; the process's cwd
  Limits limits;
  std::vector<std::string> env;         ///< the whole environment (scrubbed: PATH=/usr/bin:/bin)
  std::vector<int> keepFds;             ///< parent fds passed to the child at the same numbers
  std::vector<std::filesystem::path> hide;  ///< paths the child must not be able to read
};

/// Runs a command to completion in the sandbox (the compiler, the linker).
Exit runSandboxed(const SandboxSpec& spec);

/// A long-running sandboxed child (the probe): started, talked to, killed.
class SandboxedProcess {
 public:
  /// Starts it; on failure `error()` says why.
  explicit SandboxedProcess(const SandboxSpec& spec);
  ~SandboxedProcess();  ///< kills it (SIGKILL to its process group) and reaps it
  SandboxedProcess(const SandboxedProcess&) = delete;
  SandboxedProcess& operator=(const SandboxedProcess&) = delete;

  const std::string& error() const { return error_; }
  pid_t pid() const { return pid_; }
  bool alive();
  /// Kills and reaps it; returns how it ended (with its captured output).
  Exit stop();

 private:
  pid_t pid_ = -1;
  std::string error_;
  // implementation details (output capture, timing) live in sandbox.cpp
  struct State;
  State* state_ = nullptr;
};

}  // namespace a6::grader
