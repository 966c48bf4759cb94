// The probe: the six student files, the framework and this main, linked into one executable
// that the grader starts in its sandbox. It reads requests on fd 3 and answers on fd 4, each a
// length-prefixed JSON message (framework/harness/wire.h), until fd 3 ends.
//
// Design note: what protects the protocol.
// Requests and answers travel only on fds 3 and 4; the student's stdout and stderr (fds 1, 2)
// are a pipe the grader drains and caps, and stdin is /dev/null. Whatever the student prints
// can never be read as an answer. Student code that writes to fd 4 itself only produces an
// answer the grader cannot decode, which fails that request ("garbage from the probe").
//
// Design note: the seccomp policy, installed once everything is ready, before the first request.
// Everything the student's code runs after that point may only compute, allocate and print:
//   allowed    read/write/readv/writev/pread64/pwrite64 on any fd, close, lseek, fstat (and
//              fstatat on an fd only), brk, mmap/mremap/mprotect without PROT_EXEC, munmap,
//              madvise, futex, clocks and sleeps, sched_yield, getpid/gettid, getrandom,
//              signal masks and handlers, rt_sigreturn, tgkill on itself (abort(), so a failed
//              assert reports SIGABRT), exit, exit_group
//   EACCES     open, openat, openat2, creat, socket, socketpair, connect (fopen returns NULL,
//              std::ifstream fails: a friendly failure the student's code can report)
//   EPERM      fork, vfork, clone, execve, execveat, kill, tkill, ptrace, mmap/mprotect with
//              PROT_EXEC (std::thread throws std::system_error)
//   ENOSYS     everything else (what glibc expects of a syscall it may do without)
// Killing on a refused call would be stricter but less helpful: the student's code sees an
// ordinary failure and the test that ran it says what went wrong. Code that runs before main
// (static initialisers) is not under this filter; the sandbox (an unprivileged user, resource
// limits, a mount namespace hiding the grader's files, no network, a filter on sockets) covers it.
#include <fcntl.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

#include "a6/a6.h"
#include "harness/student_code.h"
#include "harness/wire.h"
#include "scenes/scene.h"

namespace {
#include A6_FORCE_MODELS  // reference_models.inc, or own_models.inc in a student release

constexpr int kRequestFd = 3;
constexpr int kAnswerFd = 4;

// Builds and loads the filter described above; returns what failed, or "".
std::string installFilter() {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ERRNO(ENOSYS));
  if (ctx == nullptr) return "seccomp_init failed";
  int rc = 0;
  auto rule = [&](uint32_t action, int syscall, unsigned count = 0, scmp_arg_cmp a = {},
                  scmp_arg_cmp b = {}) {
    if (rc != 0) return;
    if (count == 0) {
      rc = seccomp_rule_add(ctx, action, syscall, 0);
    } else if (count == 1) {
      rc = seccomp_rule_add(ctx, action, syscall, 1, a);
    } else {
      rc = seccomp_rule_add(ctx, action, syscall, 2, a, b);
    }
  };
  const uint32_t allow = SCMP_ACT_ALLOW;
  for (int sc : {SCMP_SYS(read),
                 SCMP_SYS(write),
                 SCMP_SYS(readv),
                 SCMP_SYS(writev),
                 SCMP_SYS(pread64),
                 SCMP_SYS(pwrite64),
                 SCMP_SYS(close),
                 SCMP_SYS(lseek),
                 SCMP_SYS(fstat),
                 SCMP_SYS(brk),
                 SCMP_SYS(munmap),
                 SCMP_SYS(madvise),
                 SCMP_SYS(futex),
                 SCMP_SYS(clock_gettime),
                 SCMP_SYS(clock_getres),
                 SCMP_SYS(gettimeofday),
                 SCMP_SYS(time),
                 SCMP_SYS(nanosleep),
                 SCMP_SYS(clock_nanosleep),
                 SCMP_SYS(sched_yield),
                 SCMP_SYS(getpid),
                 SCMP_SYS(gettid),
                 SCMP_SYS(getrandom),
                 SCMP_SYS(rt_sigprocmask),
                 SCMP_SYS(rt_sigaction),
                 SCMP_SYS(rt_sigreturn),
                 SCMP_SYS(sigaltstack),
                 SCMP_SYS(exit),
                 SCMP_SYS(exit_group)}) {
    rule(allow, sc);
  }
  // fstat(fd) is fstatat(fd, "", buf, AT_EMPTY_PATH) in glibc; a path lookup is refused.
  rule(allow, SCMP_SYS(newfstatat), 1, SCMP_A3(SCMP_CMP_MASKED_EQ, AT_EMPTY_PATH, AT_EMPTY_PATH));
  rule(SCMP_ACT_ERRNO(EACCES), SCMP_SYS(newfstatat), 1,
       SCMP_A3(SCMP_CMP_MASKED_EQ, AT_EMPTY_PATH, 0));
  // Memory, never executable.
  for (int sc : {SCMP_SYS(mmap), SCMP_SYS(mprotect)}) {
    rule(allow, sc, 1, SCMP_A2(SCMP_CMP_MASKED_EQ, PROT_EXEC, 0));
    rule(SCMP_ACT_ERRNO(EPERM), sc, 1, SCMP_A2(SCMP_CMP_MASKED_EQ, PROT_EXEC, PROT_EXEC));
  }
  rule(allow, SCMP_SYS(mremap));
  // abort() signals itself.
  rule(allow, SCMP_SYS(tgkill), 1, SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(getpid())));
  // Files and the network: refused, politely.
  for (int sc : {SCMP_SYS(open), SCMP_SYS(openat), SCMP_SYS(openat2), SCMP_SYS(creat),
                 SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(connect)}) {
    rule(SCMP_ACT_ERRNO(EACCES), sc);
  }
  // Other processes: refused.
  for (int sc :
       {SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(clone), SCMP_SYS(clone3), SCMP_SYS(execve),
        SCMP_SYS(execveat), SCMP_SYS(kill), SCMP_SYS(tkill), SCMP_SYS(ptrace)}) {
    rule(SCMP_ACT_ERRNO(EPERM), sc);
  }
  if (rc != 0) {
    seccomp_release(ctx);
    return std::string("seccomp_rule_add failed: ") + std::strerror(-rc);
  }
  rc = seccomp_load(ctx);
  seccomp_release(ctx);
  if (rc != 0) return std::string("seccomp_load failed: ") + std::strerror(-rc);
  return "";
}

}  // namespace

int main() {
  // The grader's pipes must be there; anyone else starting the probe gets told what it is.
  struct stat st;
  if (fstat(kRequestFd, &st) != 0 || fstat(kAnswerFd, &st) != 0) {
    std::fprintf(stderr,
                 "a6 probe: fds 3 and 4 are not open. This program answers the grader's "
                 "requests and is started by it (a6_grade); it is not meant to be run by hand.\n");
    return 2;
  }
  // Output reaches the grader line by line, so a crash report shows the last lines printed.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  // Everything the requests need is built before the filter: the harness and the scene list.
  std::unique_ptr<a6::harness::StudentCode> code =
      a6::harness::makeInProcess(referenceForceModel());
  (void)a6::sceneNames();

  const std::string filterError = installFilter();
  if (!filterError.empty()) {
    std::fprintf(stderr, "a6 probe: could not install the seccomp filter: %s\n",
                 filterError.c_str());
    return 3;
  }

  for (;;) {
    std::string body;
    try {
      if (!a6::wire::readFrame(kRequestFd, body)) return 0;  // the grader is done
    } catch (const std::exception& e) {
      std::fprintf(stderr, "a6 probe: bad request stream: %s\n", e.what());
      return 4;
    }
    std::string answer;
    try {
      nlohmann::json reply;
      try {
        reply = a6::wire::serve(*code, a6::wire::parse(body));
      } catch (const a6::wire::Malformed& e) {
        reply = {
            {"error", std::string("the grader sent a request the probe cannot read: ") + e.what()}};
      }
      body.clear();
      body.shrink_to_fit();
      answer = a6::wire::frame(reply);
    } catch (const std::exception& e) {
      // Too large to send, or out of memory while encoding: say so in a small answer.
      answer = a6::wire::frame(
          {{"error", std::string("the probe could not send its result: ") + e.what()}});
    }
    std::fflush(stdout);
    std::fflush(stderr);
    if (!a6::wire::writeAll(kAnswerFd, answer)) return 5;
  }
}
