// The sandboxed child between fork and execve (sandbox.cpp's design note): system calls only,
// no allocation; a fatal step reports its stage and errno on the status pipe and exits 127.
#include <fcntl.h>
#include <linux/seccomp.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "sandbox/plan.h"

namespace a6::grader::sandboxing {

namespace {

// "/proc/self/fd/<fd>" into out, without allocating.
void procFdPath(int fd, char (&out)[32]) {
  static const char prefix[] = "/proc/self/fd/";
  char digits[12];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + fd % 10);
    fd /= 10;
  } while (fd > 0 && n < 11);
  std::size_t k = 0;
  for (; prefix[k] != '\0'; ++k) out[k] = prefix[k];
  while (n > 0) out[k++] = digits[--n];
  out[k] = '\0';
}

// Closes [lo, hi]; close_range where the kernel has it, else one by one.
void closeRange(int lo, int hi, int maxFd) {
  if (lo > hi) return;
  if (syscall(SYS_close_range, static_cast<unsigned>(lo), static_cast<unsigned>(hi), 0u) == 0)
    return;
  for (int fd = lo; fd <= std::min(hi, maxFd); ++fd) ::close(fd);
}

// The child's steps (childMain, at the end); one that only weakens the sandbox reports and goes on.
class Child {
 public:
  explicit Child(Plan& plan) : p_(plan), statusFd_(plan.statusFd) {}

  void report(bool fatal, Stage stage, int err, int index) {
    const Record r{fatal ? 1 : 0, stage, err, index};
    ssize_t ignored = ::write(statusFd_, &r, sizeof r);
    (void)ignored;
  }
  [[noreturn]] void die(Stage stage, int index = -1) {
    report(true, stage, errno, index);
    _exit(127);
  }

  void newSession() {
    if (setsid() < 0) die(kSetsid);
  }

  // The grader's files out of sight (as root, when there is anything to mount).
  void hideTheMachine() {
    if (!p_.root || (p_.ops.empty() && p_.workTmpfs.empty() && !p_.pidNamespace)) return;
    if (unshare(CLONE_NEWNS) != 0) return report(false, kUnshareMounts, errno, -1);
    if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) {
      return report(false, kMountPrivate, errno, -1);
    }
    mountNamespace_ = true;
    openBeforeCovering();
    for (std::size_t k = 0; k < p_.ops.size(); ++k) {
      if (p_.ops[k].kind == MountOp::Reveal) {
        reveal(p_.ops[k], static_cast<int>(k));
      } else {
        hide(p_.ops[k], static_cast<int>(k));
      }
    }
    boundTheWorkDir();
  }

  // The pid namespace's own /proc: the code sees its own processes only, not the machine's.
  void mountOwnProc() {
    if (!p_.pidNamespace || !mountNamespace_) return;
    if (mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) != 0) {
      report(false, kProc, errno, -1);
    }
  }

  void isolateNetwork() {
    if (p_.root && unshare(CLONE_NEWNET) != 0) report(false, kUnshareNet, errno, -1);
  }

  // File descriptors: every source above every target first, then into place; the rest closed.
  void placeFds() {
    const int devNull = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (devNull < 0) die(kDevNull);
    statusFd_ = fcntl(statusFd_, F_DUPFD_CLOEXEC, p_.highBase);
    if (statusFd_ < 0) _exit(127);
    const int outFd = fcntl(p_.outFd, F_DUPFD_CLOEXEC, p_.highBase);
    const int nullFd = fcntl(devNull, F_DUPFD_CLOEXEC, p_.highBase);
    if (outFd < 0 || nullFd < 0) die(kFds);
    int moved[64];
    const std::size_t count = fdCount();
    for (std::size_t k = 0; k < count; ++k) {
      moved[k] = fcntl(p_.fds[k].first, F_DUPFD_CLOEXEC, p_.highBase);
      if (moved[k] < 0) die(kFds, static_cast<int>(k));
    }
    if (dup2(nullFd, 0) < 0 || dup2(outFd, 1) < 0 || dup2(outFd, 2) < 0) die(kFds);
    for (std::size_t k = 0; k < count; ++k) {
      if (dup2(moved[k], p_.fds[k].second) < 0) die(kFds, static_cast<int>(k));
    }
    closeTheRest();
  }

  void enterWorkDir() {
    if (chdir(p_.workDir.c_str()) != 0) die(kChdir);
  }

  // RLIMIT_NPROC (`processes`) comes after the uid change: before it, the new user's tasks that
  // other sandboxes started meanwhile could make execve fail (EAGAIN).
  void applyLimits(bool processes) {
    for (std::size_t k = 0; k < p_.limits.size(); ++k) {
      if ((p_.limits[k].resource == RLIMIT_NPROC) != processes) continue;
      const rlimit lim{p_.limits[k].soft, p_.limits[k].hard};
      if (setrlimit(p_.limits[k].resource, &lim) != 0) die(kRlimit, static_cast<int>(k));
    }
  }

  // Raw system calls: glibc's would signal the parent's other threads, absent in this child.
  void dropPrivileges() {
    if (!p_.dropPrivileges) return;
    if (syscall(SYS_setgroups, 0, nullptr) != 0) die(kSetgroups);
    if (syscall(SYS_setgid, p_.gid) != 0) die(kSetgid);
    if (syscall(SYS_setuid, p_.uid) != 0) die(kSetuid);
  }

  // Dies with its parent, the grader or the keeper (set after the uid change, which clears it).
  void dieWithTheGrader() {
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) die(kDeathSignal);
    if (getppid() != p_.parent) _exit(127);
  }

  // The keeper dies with the grader. Its getppid() is 0 (outside the namespace), so a grader
  // that died before the signal was set is seen by the status pipe having no reader.
  void keeperDiesWithTheGrader() {
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) die(kDeathSignal);
    pollfd pfd{statusFd_, 0, 0};
    if (poll(&pfd, 1, 0) > 0 && (pfd.revents & (POLLERR | POLLHUP)) != 0) _exit(127);
  }

  // The program, forked by the keeper (raw: glibc's fork takes locks the grader's other
  // threads may hold forever in this copy).
  pid_t forkProgram() {
    const long pid = syscall(SYS_clone, SIGCHLD, 0, 0, 0, 0);
    if (pid < 0) die(kFork);
    return static_cast<pid_t>(pid);
  }

  // The keeper: holds only its end pipe, reaps what the namespace leaves to it, and when the
  // program ends writes its wait status and exits, ending every process left in the namespace.
  [[noreturn]] void keep(pid_t program) {
    const int endFd = p_.endFd;
    const int low = std::min(endFd, p_.keeperFd < 0 ? endFd : p_.keeperFd);
    const int high = std::max(endFd, p_.keeperFd);
    closeRange(0, low - 1, p_.maxFd);
    if (high != low) closeRange(low + 1, high - 1, p_.maxFd);
    closeRange(high + 1, 0x7fffffff, p_.maxFd);
    // a6-keeper in place of this copy of the grader (whose memory it would hold); else the loop.
    if (p_.keeperFd >= 0 && fcntl(endFd, F_SETFD, 0) == 0) {  // the pipe kept across exec
      char* noEnv[] = {nullptr};
      syscall(SYS_execveat, p_.keeperFd, "", p_.keeperArgv.data(), noEnv, AT_EMPTY_PATH);
    }
    for (;;) {
      int status = 0;
      const pid_t got = waitpid(-1, &status, __WALL);
      if (got == program) {
        ssize_t ignored = ::write(endFd, &status, sizeof status);
        (void)ignored;
        _exit(0);
      }
      if (got < 0 && errno != EINTR) _exit(126);
    }
  }

  void noNewPrivileges() {
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) die(kNoNewPrivs);
  }

  void installFilter() {
    if (p_.filter.empty()) return;
    sock_fprog prog{static_cast<unsigned short>(p_.filter.size()),
                    const_cast<sock_filter*>(p_.filter.data())};
    if (prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &prog) != 0) {
      report(false, kSeccomp, errno, -1);
    }
  }

  [[noreturn]] void exec() {
    execve(p_.argv[0], p_.argv.data(), p_.envp.data());
    die(kExec);
  }

 private:
  std::size_t fdCount() const { return std::min<std::size_t>(p_.fds.size(), 64); }

  // /dev/null (covers hidden files) and everything to reveal, opened before anything is covered.
  void openBeforeCovering() {
    const int nullPath = ::open("/dev/null", O_PATH | O_CLOEXEC);
    if (nullPath >= 0) procFdPath(nullPath, nullSource_);
    for (std::size_t k = 0; k < p_.ops.size(); ++k) {
      MountOp& op = p_.ops[k];
      if (op.kind != MountOp::Reveal) continue;
      op.fd = ::open(op.path.c_str(), O_PATH | O_CLOEXEC);
      if (op.fd < 0) die(kReveal, static_cast<int>(k));
      procFdPath(op.fd, op.source);
    }
  }

  // A folder covered by an empty tmpfs, a file by /dev/null (read-only).
  void hide(const MountOp& op, int index) {
    struct stat st;
    if (lstat(op.path.c_str(), &st) != 0) return;  // already under a hidden folder
    int rc;
    if (op.kind == MountOp::HideDir) {
      rc = mount("a6-hidden", op.path.c_str(), "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC,
                 "size=64k,mode=755");
    } else {
      rc = mount(nullSource_, op.path.c_str(), nullptr, MS_BIND, nullptr);
      if (rc == 0) {
        mount(nullptr, op.path.c_str(), nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY, nullptr);
      }
    }
    if (rc != 0) report(false, kHide, errno, index);
  }

  // The original bound back unless still visible; the way to it rebuilt with folders the
  // child's user can search, whatever the grader's umask.
  void reveal(const MountOp& op, int index) {
    struct stat st, want;
    if (fstat(op.fd, &want) != 0) die(kReveal, index);
    if (stat(op.path.c_str(), &st) == 0 && st.st_dev == want.st_dev && st.st_ino == want.st_ino) {
      return;
    }
    for (const std::string& dir : op.chain) {
      if (lstat(dir.c_str(), &st) == 0) continue;
      if (errno != ENOENT || mkdir(dir.c_str(), 0755) != 0 || chmod(dir.c_str(), 0755) != 0) {
        die(kReveal, index);
      }
    }
    if (lstat(op.path.c_str(), &st) != 0) makeMountPoint(op, index);
    if (mount(op.source, op.path.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) {
      die(kReveal, index);
    }
  }

  void makeMountPoint(const MountOp& op, int index) {
    if (op.isDir) {
      if (mkdir(op.path.c_str(), 0755) != 0) die(kReveal, index);
      return;
    }
    const int fd = ::open(op.path.c_str(), O_CREAT | O_WRONLY | O_CLOEXEC, 0644);
    if (fd < 0) die(kReveal, index);
    ::close(fd);
  }

  // A tmpfs work dir bounds what the child writes.
  void boundTheWorkDir() {
    if (!p_.workTmpfs.empty() && mount("a6-work", p_.workDir.c_str(), "tmpfs", MS_NOSUID | MS_NODEV,
                                       p_.workTmpfs.c_str()) != 0) {
      die(kWorkTmpfs);
    }
  }

  // Closes everything but 0-2, the targets and the status pipe (sorted: targets < highBase).
  void closeTheRest() {
    int keep[66];
    std::size_t kept = 0;
    for (std::size_t k = 0; k < fdCount(); ++k) keep[kept++] = p_.fds[k].second;
    keep[kept++] = statusFd_;
    std::sort(keep, keep + kept);
    int next = 3;
    for (std::size_t k = 0; k < kept; ++k) {
      closeRange(next, keep[k] - 1, p_.maxFd);
      next = std::max(next, keep[k] + 1);
    }
    closeRange(next, 0x7fffffff, p_.maxFd);
  }

  Plan& p_;
  int statusFd_;
  bool mountNamespace_ = false;
  char nullSource_[32] = "/dev/null";
};

// The program's own set-up, then the program.
[[noreturn]] void programMain(Child& child) {
  child.placeFds();
  child.enterWorkDir();
  child.applyLimits(false);
  child.dropPrivileges();
  child.applyLimits(true);
  child.dieWithTheGrader();
  child.noNewPrivileges();
  child.installFilter();
  child.exec();
}

}  // namespace

// In its own pid namespace the child is the keeper, the program its child (sandbox.h, step 0);
// without one, the child is the program itself.
[[noreturn]] void childMain(Plan& plan) {
  Child child(plan);
  if (plan.pidNamespace) child.keeperDiesWithTheGrader();
  child.newSession();
  child.hideTheMachine();
  child.mountOwnProc();
  child.isolateNetwork();
  if (plan.pidNamespace) {
    const pid_t program = child.forkProgram();
    if (program > 0) child.keep(program);
  }
  programMain(child);
}

}  // namespace a6::grader::sandboxing
