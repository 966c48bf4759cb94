// What poisoned the next grading before the process layer (grader/sandbox/process.h): a process of
// the sandbox's user in a session of its own, named with a newline (which a line-by-line reader of
// /proc/PID/stat skips), with a child of the same kind, sending SIGKILL to every process of its
// user but the other of the two in a loop. Started as root; the caller kills and reaps the pid it
// returns, and the child dies with it.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <cstring>

namespace a6::test {

// Sends SIGKILL to every process this user may signal, itself and `spare` excepted: what
// kill(-1, SIGKILL) does, except that the poisoner's two processes would then kill each other,
// and a test could find neither alive. Only async-signal-safe calls: it runs in a child forked
// from a threaded test.
inline void killAllBut(pid_t spare) {
  const int proc = open("/proc", O_RDONLY | O_DIRECTORY);
  if (proc < 0) return;
  alignas(8) char buffer[8192];
  const pid_t self = getpid();
  for (;;) {
    const long n = syscall(SYS_getdents64, proc, buffer, sizeof buffer);
    if (n <= 0) break;
    for (long at = 0; at < n;) {
      unsigned short length = 0;  // struct linux_dirent64: d_reclen at 16, d_name at 19
      std::memcpy(&length, buffer + at + 16, sizeof length);
      pid_t pid = 0;
      for (const char* c = buffer + at + 19; *c >= '0' && *c <= '9'; ++c)
        pid = 10 * pid + (*c - '0');
      at += length;
      if (pid > 1 && pid != self && pid != spare) kill(pid, SIGKILL);  // others' users: EPERM
    }
  }
  close(proc);
}

inline pid_t startPoisoner(uid_t uid) {
  const pid_t test = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    if (syscall(SYS_setgroups, 0, nullptr) != 0 || syscall(SYS_setgid, 65534) != 0 ||
        syscall(SYS_setuid, uid) != 0) {
      _exit(126);
    }
    // Both die with what started them (after setuid, which would clear it): a test killed
    // before its end leaves no poisoner of its uid for the next run.
    prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
    if (getppid() != test) _exit(0);
    setsid();
    prctl(PR_SET_NAME, "a6\nx", 0, 0, 0);
    const pid_t parent = getpid();
    const pid_t child = fork();
    pid_t spare = child;  // each spares the other
    if (child == 0) {
      prctl(PR_SET_NAME, "a6\ny", 0, 0, 0);
      prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
      if (getppid() != parent) _exit(0);
      spare = parent;
    }
    const timespec pause{0, 500000};
    for (;;) {
      killAllBut(spare);
      nanosleep(&pause, nullptr);
    }
  }
  return pid;
}

}  // namespace a6::test
