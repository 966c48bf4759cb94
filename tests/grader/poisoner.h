// What poisoned the next grading before the process layer (grader/sandbox/process.h): a process of
// the sandbox's user in a session of its own, named with a newline (which a line-by-line reader of
// /proc/PID/stat skips), with a child of the same kind, sending SIGKILL to every process of its
// user in a loop. Started as root; the caller reaps the pid it returns.
#pragma once

#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace a6::test {

inline pid_t startPoisoner(uid_t uid) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (syscall(SYS_setgroups, 0, nullptr) != 0 || syscall(SYS_setgid, 65534) != 0 ||
        syscall(SYS_setuid, uid) != 0) {
      _exit(126);
    }
    setsid();
    prctl(PR_SET_NAME, "a6\nx", 0, 0, 0);
    if (fork() == 0) prctl(PR_SET_NAME, "a6\ny", 0, 0, 0);
    for (;;) {
      kill(-1, SIGKILL);
      usleep(500);
    }
  }
  return pid;
}

}  // namespace a6::test
