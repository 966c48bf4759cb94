// The seccomp program of every sandboxed child: allow by default; no sockets, io_uring, ptrace
// or cross-process memory, and for the probe no new processes.
#include <sched.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>

#include "sandbox/plan.h"

namespace a6::grader::sandboxing {

namespace {

std::vector<sock_filter> buildFilter(bool noFork, std::string& error) {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  if (ctx == nullptr) {
    error = "seccomp_init failed";
    return {};
  }
  int rc = 0;
  auto deny = [&](int syscall, int err, unsigned args = 0, scmp_arg_cmp cmp = {}) {
    if (rc == 0) {
      rc = args == 0 ? seccomp_rule_add(ctx, SCMP_ACT_ERRNO(err), syscall, 0)
                     : seccomp_rule_add(ctx, SCMP_ACT_ERRNO(err), syscall, 1, cmp);
    }
  };
  deny(SCMP_SYS(socket), EACCES);
  for (int sc : {SCMP_SYS(io_uring_setup), SCMP_SYS(io_uring_enter), SCMP_SYS(io_uring_register),
                 SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev)}) {
    deny(sc, EPERM);
  }
  if (noFork) {
    deny(SCMP_SYS(fork), EPERM);
    deny(SCMP_SYS(vfork), EPERM);
    deny(SCMP_SYS(clone), EPERM, 1, SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
    deny(SCMP_SYS(clone3), ENOSYS);  // glibc then falls back to clone, checked above
  }
  std::vector<sock_filter> program;
  if (rc == 0) {
    const int fd = memfd_create("a6-seccomp", MFD_CLOEXEC);
    if (fd < 0) {
      rc = -errno;
    } else {
      rc = seccomp_export_bpf(ctx, fd);
      const off_t size = lseek(fd, 0, SEEK_END);
      if (rc == 0 && size > 0 && size % static_cast<off_t>(sizeof(sock_filter)) == 0) {
        program.resize(static_cast<std::size_t>(size) / sizeof(sock_filter));
        if (pread(fd, program.data(), static_cast<std::size_t>(size), 0) != size) program.clear();
      }
      ::close(fd);
    }
  }
  seccomp_release(ctx);
  if (program.empty())
    error = "could not build the seccomp filter: " + errnoText(rc < 0 ? -rc : EINVAL);
  return program;
}

}  // namespace

const std::vector<sock_filter>& filterFor(bool noFork, std::string& error) {
  static std::once_flag once[2];
  static std::vector<sock_filter> programs[2];
  static std::string errors[2];
  const int k = noFork ? 1 : 0;
  std::call_once(once[k], [&] { programs[k] = buildFilter(noFork, errors[k]); });
  error = errors[k];
  return programs[k];
}

}  // namespace a6::grader::sandboxing
