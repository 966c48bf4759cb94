// The probe's seccomp filter, built and installed by the probe's own code before anything of the
// student's runs. Included by probe_main.cpp only: everything here has internal linkage and calls
// no library function, so no symbol a submission defines (seccomp_load, syscall, prctl, memcpy,
// a template instance) can stand in for any of it.
//
// Takes: nothing. Gives: installFilterOrDie(), run from the executable's .preinit_array, which the
// dynamic loader runs before every constructor of every library and object (the student's
// static initialisers included); a failure ends the probe with exit status 3.
//
// Design note: the policy (what student code may do once the filter is on).
//   allowed    read/write/readv/writev/pread64/pwrite64 on any fd, close, lseek, fstat (and
//              newfstatat with AT_EMPTY_PATH only), brk, mmap/mprotect without PROT_EXEC,
//              mremap, munmap, madvise, futex, clocks and sleeps, sched_yield, getpid/gettid,
//              getppid, getuid/geteuid/getgid/getegid, getrandom, signal masks and handlers,
//              rt_sigreturn, tgkill on itself (abort(), so a failed assert reports SIGABRT), exit,
//              exit_group
//   EACCES     open, openat, openat2, creat, socket, socketpair, connect (fopen returns NULL,
//              std::ifstream fails: a friendly failure the student's code can report)
//   EPERM      fork, vfork, clone, clone3, execve, execveat, kill, tkill, ptrace, seccomp,
//              prctl, mmap/mprotect with PROT_EXEC (std::thread throws std::system_error)
//   ENOSYS     everything else (what glibc expects of a syscall it may do without)
//   killed     a system call of another architecture (the x32 ABI on x86-64)
// Killing on a refused call would be stricter but less helpful: the student's code sees an
// ordinary failure and the check that ran it says what went wrong.
//
// SECCOMP_FILTER_FLAG_TSYNC puts every thread of the process under the filter (or fails if one
// cannot be). a6_grade checks from outside, in /proc/<probe>/status, that the filter is on and
// that one thread runs before it sends the first request.
#pragma once

#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/syscall.h>

#include <cerrno>
#include <csignal>
#include <cstddef>

namespace probe_filter {
namespace {

// A system call with up to five arguments, without libc.
inline long rawSyscall(long number, long a = 0, long b = 0, long c = 0, long d = 0, long e = 0) {
#if defined(__x86_64__)
  long result;
  register long r10 __asm__("r10") = d;
  register long r8 __asm__("r8") = e;
  __asm__ volatile("syscall"
                   : "=a"(result)
                   : "a"(number), "D"(a), "S"(b), "d"(c), "r"(r10), "r"(r8)
                   : "rcx", "r11", "memory");
  return result;
#elif defined(__aarch64__)
  register long x8 __asm__("x8") = number;
  register long x0 __asm__("x0") = a;
  register long x1 __asm__("x1") = b;
  register long x2 __asm__("x2") = c;
  register long x3 __asm__("x3") = d;
  register long x4 __asm__("x4") = e;
  __asm__ volatile("svc 0" : "+r"(x0) : "r"(x8), "r"(x1), "r"(x2), "r"(x3), "r"(x4) : "memory");
  return x0;
#else
#error "the probe's seccomp filter knows x86-64 and aarch64"
#endif
}

#if defined(__x86_64__)
constexpr unsigned kArch = AUDIT_ARCH_X86_64;
#else
constexpr unsigned kArch = AUDIT_ARCH_AARCH64;
#endif

constexpr unsigned kNr = offsetof(seccomp_data, nr);
constexpr unsigned kArchOffset = offsetof(seccomp_data, arch);
constexpr unsigned argLow(int i) {  // the low 32 bits of argument i (little-endian)
  return static_cast<unsigned>(offsetof(seccomp_data, args)) + 8u * static_cast<unsigned>(i);
}

// A program of up to kMax instructions, written front to back.
struct Program {
  static constexpr int kMax = 256;
  sock_filter code[kMax];
  int size = 0;
  bool overflow = false;

  void put(unsigned short op, unsigned k, unsigned char jt = 0, unsigned char jf = 0) {
    if (size == kMax) {
      overflow = true;
      return;
    }
    code[size++] = sock_filter{op, jt, jf, k};
  }
  void ret(unsigned action) { put(BPF_RET | BPF_K, action); }
  // With the syscall number in A: `action` for `nr`, else on to what follows.
  void on(long nr, unsigned action) {
    put(BPF_JMP | BPF_JEQ | BPF_K, static_cast<unsigned>(nr), 0, 1);
    ret(action);
  }
  // With the syscall number in A: for `nr`, `yes` when argument `arg` passes `test` against
  // `k` (BPF_JSET: has any of the bits k; BPF_JEQ: equals k), `no` when it does not; else on to
  // what follows (A still holds the number).
  void onArg(long nr, int arg, unsigned short test, unsigned k, unsigned yes, unsigned no) {
    put(BPF_JMP | BPF_JEQ | BPF_K, static_cast<unsigned>(nr), 0, 4);
    put(BPF_LD | BPF_W | BPF_ABS, argLow(arg));
    put(BPF_JMP | test | BPF_K, k, 0, 1);
    ret(yes);
    ret(no);
  }
};

constexpr unsigned kAllow = SECCOMP_RET_ALLOW;
constexpr unsigned errnoAction(int e) {
  return SECCOMP_RET_ERRNO | (static_cast<unsigned>(e) & SECCOMP_RET_DATA);
}

// The policy of the design note, for the process `self`.
void buildPolicy(Program& p, long self) {
  // Another architecture's numbers mean other calls: kill.
  p.put(BPF_LD | BPF_W | BPF_ABS, kArchOffset);
  p.put(BPF_JMP | BPF_JEQ | BPF_K, kArch, 1, 0);
  p.ret(SECCOMP_RET_KILL_PROCESS);
  p.put(BPF_LD | BPF_W | BPF_ABS, kNr);
#if defined(__x86_64__)
  p.put(BPF_JMP | BPF_JGE | BPF_K, 0x40000000u, 0, 1);  // the x32 ABI
  p.ret(SECCOMP_RET_KILL_PROCESS);
#endif
  // Computing, allocating, printing.
  for (long nr :
       {SYS_read,         SYS_write,        SYS_readv,     SYS_writev,          SYS_pread64,
        SYS_pwrite64,     SYS_close,        SYS_lseek,     SYS_fstat,           SYS_brk,
        SYS_munmap,       SYS_madvise,      SYS_mremap,    SYS_futex,           SYS_clock_gettime,
        SYS_clock_getres, SYS_gettimeofday, SYS_nanosleep, SYS_clock_nanosleep, SYS_sched_yield,
        SYS_getpid,       SYS_gettid,       SYS_getrandom, SYS_getuid,          SYS_geteuid,
        SYS_getgid,       SYS_getegid,      SYS_getppid,   SYS_rt_sigprocmask,  SYS_rt_sigaction,
        SYS_rt_sigreturn, SYS_sigaltstack,  SYS_exit,      SYS_exit_group}) {
    p.on(nr, kAllow);
  }
#ifdef SYS_time
  p.on(SYS_time, kAllow);
#endif
  // fstat(fd) is fstatat(fd, "", buf, AT_EMPTY_PATH) in glibc; a path lookup is refused.
  p.onArg(SYS_newfstatat, 3, BPF_JSET, AT_EMPTY_PATH, kAllow, errnoAction(EACCES));
  // Memory, never executable.
  p.onArg(SYS_mmap, 2, BPF_JSET, PROT_EXEC, errnoAction(EPERM), kAllow);
  p.onArg(SYS_mprotect, 2, BPF_JSET, PROT_EXEC, errnoAction(EPERM), kAllow);
  // abort() signals itself.
  p.onArg(SYS_tgkill, 0, BPF_JEQ, static_cast<unsigned>(self), kAllow, errnoAction(EPERM));
  // Files and the network: refused, politely.
  for (long nr : {SYS_openat, SYS_openat2, SYS_socket, SYS_socketpair, SYS_connect}) {
    p.on(nr, errnoAction(EACCES));
  }
#ifdef SYS_open
  p.on(SYS_open, errnoAction(EACCES));
  p.on(SYS_creat, errnoAction(EACCES));
#endif
  // Other processes, and the filter itself: refused.
  for (long nr : {SYS_clone, SYS_clone3, SYS_execve, SYS_execveat, SYS_kill, SYS_tkill, SYS_ptrace,
                  SYS_seccomp, SYS_prctl}) {
    p.on(nr, errnoAction(EPERM));
  }
#ifdef SYS_fork
  p.on(SYS_fork, errnoAction(EPERM));
  p.on(SYS_vfork, errnoAction(EPERM));
#endif
  p.ret(errnoAction(ENOSYS));
}

// Writes `text` to stderr and ends the process with status 3.
[[noreturn]] void die(const char* text) {
  long n = 0;
  while (text[n] != '\0') ++n;
  rawSyscall(SYS_write, 2, reinterpret_cast<long>(text), n);
  for (;;) rawSyscall(SYS_exit_group, 3);
}

void installFilterOrDie(int, char**, char**) {
  static Program program;  // zero-initialised storage: no constructor runs
  buildPolicy(program, rawSyscall(SYS_getpid));
  if (program.overflow) die("a6 probe: the seccomp program is too long\n");
  if (rawSyscall(SYS_prctl, PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) {
    die("a6 probe: could not set no_new_privs\n");
  }
  sock_fprog prog{static_cast<unsigned short>(program.size), program.code};
  if (rawSyscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, SECCOMP_FILTER_FLAG_TSYNC,
                 reinterpret_cast<long>(&prog)) != 0) {
    die("a6 probe: could not install the seccomp filter on every thread\n");
  }
}

// First in the probe's .preinit_array: the probe's main object is linked before the student's.
__attribute__((used, section(".preinit_array"))) void (*const kInstallAtStart)(
    int, char**, char**) = &installFilterOrDie;

}  // namespace
}  // namespace probe_filter
