// Running one of the grader's commands from a test: its exit status, everything it printed, and
// how long it took (wall and CPU). Shared by the tests that drive a6_grade, a6_batch and the
// Gradescope package.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace a6::test {

struct CommandRun {
  int status = -1;     ///< exit status, 128 + signal when killed, -1 when it could not start
  std::string output;  ///< stdout and stderr together
  double seconds = 0;  ///< wall-clock time
  /// CPU time (user and system) of the command and every process it and its children waited
  /// for: unlike the wall time, hardly changed by other work on the machine
  double cpuSeconds = 0;
};

/// The CPU time of this process's children that have ended and been waited for, s.
inline double childrenCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto seconds = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

/// Runs `command` with /bin/sh, its stderr joined to its stdout.
inline CommandRun runCommand(const std::string& command) {
  CommandRun r;
  const auto start = std::chrono::steady_clock::now();
  const double cpuBefore = childrenCpuSeconds();
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : -1;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpuSeconds = childrenCpuSeconds() - cpuBefore;
  return r;
}

}  // namespace a6::test
