// The sandbox (see sandbox.h for what the child gets, in order).
//
// Design note: fork, then only system calls.
// The grader may run several sandboxes from several threads. Between fork() and execve() the
// child may only make async-signal-safe calls, so everything it needs (argv and envp arrays,
// paths, the mount plan, the rlimits, the seccomp program) is prepared in a Plan before fork,
// and the child reports what failed through a close-on-exec status pipe as fixed-size records
// (stage, errno); the parent turns them into sentences. EOF on that pipe means execve worked.
#include "sandbox/sandbox.h"

#include <fcntl.h>
#include <linux/filter.h>
#include <poll.h>
#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "sandbox/process.h"

namespace a6::paths {
extern const char keeper[];  // the a6-keeper program (cmake/A6FastBuild.cmake, a6_configured_path)
}  // namespace a6::paths

namespace a6::grader {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using process::secondsSince;

namespace {

std::string errnoText(int err) { return std::strerror(err); }

std::string formatSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

// Captured output
// ----------------------------------------------------------------------------------

struct Sink {
  mutable std::mutex mutex;
  std::string data;
  std::size_t cap = 0;
  bool truncated = false;

  void add(const char* bytes, std::size_t n) {
    std::lock_guard<std::mutex> lock(mutex);
    const std::size_t room = cap > data.size() ? cap - data.size() : 0;
    data.append(bytes, std::min(room, n));
    if (n > room) truncated = true;
  }
  std::string text() const {
    std::lock_guard<std::mutex> lock(mutex);
    return data;
  }
};

// Reads what is there; false at end of stream or on a hard error.
bool readSome(int fd, Sink& sink) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      sink.add(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) return false;
    if (errno == EINTR) continue;
    return errno == EAGAIN || errno == EWOULDBLOCK;
  }
}

// The status records
// ---------------------------------------------------------------------------------

enum Stage : std::int32_t {
  kSetsid = 1,
  kUnshareMounts,
  kMountPrivate,
  kHide,
  kReveal,
  kUnshareNet,
  kDevNull,
  kFds,
  kRlimit,
  kChdir,
  kSetgroups,
  kSetgid,
  kSetuid,
  kDeathSignal,
  kNoNewPrivs,
  kSeccomp,
  kExec,
  kWorkTmpfs,
  kProc,
  kFork,
};

struct Record {
  std::int32_t fatal;
  std::int32_t stage;
  std::int32_t err;
  std::int32_t index;
};

// The plan
// --------------------------------------------------------------------------------------------

struct MountOp {
  enum Kind { HideDir, HideFile, Reveal } kind = HideDir;
  std::size_t depth = 0;
  std::string path;
  // Reveal only:
  std::vector<std::string> chain;  // the ancestors of path, outermost first
  bool isDir = false;
  int fd = -1;           // O_PATH fd on the original, opened by the child in its new
                         // namespace (a bind source must be in the caller's namespace)
  char source[32] = {};  // "/proc/self/fd/<fd>", written by the child
};

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

struct Limit {
  int resource;
  rlim_t soft, hard;
};

struct Plan {
  std::vector<std::string> args, envs;
  std::vector<char*> argv, envp;
  std::string workDir;
  bool root = false;
  bool dropPrivileges = false;
  uid_t uid = 65534;
  gid_t gid = 65534;
  pid_t parent = 0;           // the program's parent as the program sees it (getppid())
  bool pidNamespace = false;  // the child is the init of its own pid namespace (the keeper)
  int endFd = -1;             // the keeper writes the program's wait status here
  int keeperFd = -1;          // a6-keeper, opened before anything is hidden (or -1)
  std::string keeperEndFd;    // its argument: endFd in digits
  std::vector<char*> keeperArgv;
  std::vector<MountOp> ops;
  std::string workTmpfs;               // tmpfs options for the work dir ("": none)
  std::vector<std::string> hidePaths;  // for messages, by op index
  std::vector<Limit> limits;
  std::vector<std::pair<int, int>> fds;  // {source, target} besides 0/1/2
  int highBase = 0;
  int maxFd = 1024;
  int statusFd = -1;
  int outFd = -1;
  std::vector<sock_filter> filter;
  std::vector<std::string> notes;  // found by the parent
};

const char* limitName(int resource) {
  switch (resource) {
    case RLIMIT_CPU:
      return "RLIMIT_CPU";
    case RLIMIT_AS:
      return "RLIMIT_AS";
    case RLIMIT_FSIZE:
      return "RLIMIT_FSIZE";
    case RLIMIT_NOFILE:
      return "RLIMIT_NOFILE";
    case RLIMIT_NPROC:
      return "RLIMIT_NPROC";
    case RLIMIT_CORE:
      return "RLIMIT_CORE";
    default:
      return "an rlimit";
  }
}

// Closes [lo, hi]; close_range where the kernel has it, else one by one.
void closeRange(int lo, int hi, int maxFd) {
  if (lo > hi) return;
  if (syscall(SYS_close_range, static_cast<unsigned>(lo), static_cast<unsigned>(hi), 0u) == 0)
    return;
  for (int fd = lo; fd <= std::min(hi, maxFd); ++fd) ::close(fd);
}

// The child, between fork and execve: system calls only, no allocation. Its set-up is a list of
// small named steps (childMain, at the end); a fatal step reports its stage and errno on the
// status pipe and exits 127, a step that only weakens the sandbox reports and goes on.
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

  // The grader's files out of sight (as root, when there is anything to hide, a work tmpfs or a
  // pid namespace whose /proc to mount).
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

  // In its own pid namespace (the keeper), a /proc of that namespace: the code sees its own
  // processes only, not the machine's (needs the private mount namespace).
  void mountOwnProc() {
    if (!p_.pidNamespace || !mountNamespace_) return;
    if (mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) != 0) {
      report(false, kProc, errno, -1);
    }
  }

  // No network (as root).
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

  // The rlimits: RLIMIT_NPROC (`processes`) comes after the uid change: set before it, a count
  // of the new user's tasks that other sandboxes pushed over the limit meanwhile would make
  // execve fail (EAGAIN).
  void applyLimits(bool processes) {
    for (std::size_t k = 0; k < p_.limits.size(); ++k) {
      if ((p_.limits[k].resource == RLIMIT_NPROC) != processes) continue;
      const rlimit lim{p_.limits[k].soft, p_.limits[k].hard};
      if (setrlimit(p_.limits[k].resource, &lim) != 0) die(kRlimit, static_cast<int>(k));
    }
  }

  // The sandbox's user. Raw system calls: in the child of a threaded parent, only this thread
  // exists.
  void dropPrivileges() {
    if (!p_.dropPrivileges) return;
    if (syscall(SYS_setgroups, 0, nullptr) != 0) die(kSetgroups);
    if (syscall(SYS_setgid, p_.gid) != 0) die(kSetgid);
    if (syscall(SYS_setuid, p_.uid) != 0) die(kSetuid);
  }

  // Dies with its parent (set after the uid change, which clears it): the grader, or in a pid
  // namespace the keeper, which dies with the grader.
  void dieWithTheGrader() {
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) die(kDeathSignal);
    if (getppid() != p_.parent) _exit(127);
  }

  // The keeper, init of the pid namespace, dies with the grader. Its parent lies outside the
  // namespace (getppid() is 0), so a grader that died before the signal was set is seen by the
  // status pipe having no reader any more.
  void keeperDiesWithTheGrader() {
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) die(kDeathSignal);
    pollfd pfd{statusFd_, 0, 0};
    if (poll(&pfd, 1, 0) > 0 && (pfd.revents & (POLLERR | POLLHUP)) != 0) _exit(127);
  }

  // The program's process, from the keeper: a plain fork (raw, as glibc's fork would take the
  // locks of the grader's other threads, which this copy of them may hold forever).
  pid_t forkProgram() {
    const long pid = syscall(SYS_clone, SIGCHLD, 0, 0, 0, 0);
    if (pid < 0) die(kFork);
    return static_cast<pid_t>(pid);
  }

  // The keeper, once the program runs: holds no descriptor of the grader's but its end pipe,
  // reaps whatever the namespace leaves to it, and when the program ends writes its wait status
  // and exits, which ends every process left in the namespace.
  [[noreturn]] void keep(pid_t program) {
    const int endFd = p_.endFd;
    const int low = std::min(endFd, p_.keeperFd < 0 ? endFd : p_.keeperFd);
    const int high = std::max(endFd, p_.keeperFd);
    closeRange(0, low - 1, p_.maxFd);
    if (high != low) closeRange(low + 1, high - 1, p_.maxFd);
    closeRange(high + 1, 0x7fffffff, p_.maxFd);
    // a6-keeper in place of this copy of the grader (whose memory it would hold); the loop below
    // where it cannot be run.
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

  // /dev/null, what covers a hidden file, and everything to reveal: opened before anything is
  // covered.
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

  // The original bound back, unless it is still visible as it is; the way to it rebuilt with
  // folders searchable by the child's user, whatever the grader's umask.
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

  // The work dir: a tmpfs of its own size, so that what the child writes is bounded.
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

// The child of the grader. In its own pid namespace (as root) it is that namespace's init, the
// keeper, and the program runs as its child: every process the program starts, in a new session
// or not, lives in the namespace and ends with the keeper, and no signal from the code reaches a
// process outside it. Without one, the child is the program itself.
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

// The seccomp program every sandboxed child gets (default: allow) ---------------------------------

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

const std::vector<sock_filter>& filterFor(bool noFork, std::string& error) {
  static std::once_flag once[2];
  static std::vector<sock_filter> programs[2];
  static std::string errors[2];
  const int k = noFork ? 1 : 0;
  std::call_once(once[k], [&] { programs[k] = buildFilter(noFork, errors[k]); });
  error = errors[k];
  return programs[k];
}

// Tasks (threads) of a user, from /proc: RLIMIT_NPROC counts them all.
long tasksOf(uid_t uid) {
  long total = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream status(entry.path() / "status");
    std::string line;
    bool mine = false;
    long threads = 1;
    while (std::getline(status, line)) {
      if (line.compare(0, 4, "Uid:") == 0) {
        std::istringstream in(line.substr(4));
        long real = -1;
        in >> real;
        mine = real == static_cast<long>(uid);
      } else if (line.compare(0, 8, "Threads:") == 0) {
        threads = std::max(1L, std::atol(line.c_str() + 8));
      }
    }
    if (mine) total += threads;
  }
  return total;
}

bool within(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

std::size_t depthOf(const fs::path& path) {
  return static_cast<std::size_t>(std::distance(path.begin(), path.end()));
}

fs::path canonicalish(const fs::path& path) {
  std::error_code ec;
  fs::path out = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : out;
}

// Creates the work dir fresh and empty, writable by the user the child runs as.
std::string prepareWorkDir(const fs::path& dir, const Plan& plan) {
  if (dir.empty()) return "no work dir given";
  const fs::path abs = fs::absolute(dir).lexically_normal();
  if (abs == abs.root_path() || depthOf(abs) < 3) {
    return "refusing to use " + abs.string() + " as a work dir (too close to /)";
  }
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(abs, ec);
  if (fs::exists(st)) {
    if (fs::is_directory(st)) {
      fs::remove_all(abs, ec);
    } else {
      fs::remove(abs, ec);
    }
    if (ec) return "cannot empty the work dir " + abs.string() + ": " + ec.message();
  }
  fs::create_directories(abs, ec);
  if (ec) return "cannot create the work dir " + abs.string() + ": " + ec.message();
  ::chmod(abs.c_str(), 0700);
  if (plan.dropPrivileges && ::chown(abs.c_str(), plan.uid, plan.gid) != 0) {
    return "cannot hand the work dir " + abs.string() + " to uid " + std::to_string(plan.uid) +
           ": " + errnoText(errno);
  }
  return "";
}

void deleteWorkDir(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  fs::remove_all(dir, ec);
}

// Whether `uid`/`gid` (no supplementary groups: the child drops them) may search a folder.
bool searchableBy(const struct stat& st, uid_t uid, gid_t gid) {
  if (st.st_uid == uid) return (st.st_mode & S_IXUSR) != 0;
  if (st.st_gid == gid) return (st.st_mode & S_IXGRP) != 0;
  return (st.st_mode & S_IXOTH) != 0;
}

// The paths a child must see whatever is hidden: SandboxSpec::reveal, its work dir, argv[0].
std::vector<fs::path> revealsOf(const SandboxSpec& spec, const Plan& plan) {
  std::vector<fs::path> reveals;
  for (const fs::path& r : spec.reveal) reveals.push_back(canonicalish(r));
  reveals.push_back(canonicalish(plan.workDir));
  reveals.push_back(canonicalish(spec.argv[0]));
  return reveals;
}

// A folder the child's user cannot search (a checkout in /root, mode 0700) would keep it from
// what lies inside, even bound back in place: the outermost such folder above a revealed path is
// covered whole, and the reveal rebuilds the way in with searchable folders (childMain).
std::vector<fs::path> unsearchableAncestors(const std::vector<fs::path>& reveals,
                                            const Plan& plan) {
  std::vector<fs::path> covers;
  for (const fs::path& path : reveals) {
    fs::path ancestor;
    for (auto part = path.begin(); part != path.end(); ++part) {
      ancestor /= *part;
      if (ancestor == path || ancestor == ancestor.root_path()) continue;
      struct stat st;
      if (stat(ancestor.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) break;
      if (!searchableBy(st, plan.uid, plan.gid)) {
        if (std::find(covers.begin(), covers.end(), ancestor) == covers.end()) {
          covers.push_back(ancestor);
        }
        break;
      }
    }
  }
  return covers;
}

// The paths to hide: the spec's, and as a dropped user the unsearchable folders above a reveal.
std::vector<fs::path> hidesOf(const SandboxSpec& spec, const std::vector<fs::path>& reveals,
                              const Plan& plan) {
  std::vector<fs::path> hides;
  for (const fs::path& h : spec.hide) hides.push_back(canonicalish(h));
  if (plan.dropPrivileges) {
    for (const fs::path& c : unsearchableAncestors(reveals, plan)) hides.push_back(c);
  }
  return hides;
}

// One hide operation per existing path (as root); returns the paths hidden.
std::vector<fs::path> planHides(const std::vector<fs::path>& hides, Plan& plan) {
  std::vector<fs::path> hidden;
  bool unhidden = false;
  for (const fs::path& path : hides) {
    struct stat st;
    if (lstat(path.c_str(), &st) != 0) continue;  // nothing to hide
    if (path == path.root_path()) {
      plan.notes.push_back("refusing to hide / (everything would be hidden)");
      continue;
    }
    if (!plan.root) {
      unhidden = true;
      continue;
    }
    MountOp op;
    op.kind = S_ISDIR(st.st_mode) ? MountOp::HideDir : MountOp::HideFile;
    op.path = path.string();
    op.depth = depthOf(path);
    plan.ops.push_back(op);
    hidden.push_back(path);
  }
  if (unhidden) plan.notes.push_back(kNotRootNote);
  return hidden;
}

// One reveal operation per revealed path that lies under a hidden one.
void planReveals(const std::vector<fs::path>& reveals, const std::vector<fs::path>& hidden,
                 Plan& plan) {
  for (const fs::path& path : reveals) {
    if (std::none_of(hidden.begin(), hidden.end(),
                     [&](const fs::path& h) { return within(path, h); })) {
      continue;
    }
    MountOp op;
    op.kind = MountOp::Reveal;
    op.path = path.string();
    op.depth = depthOf(path);
    struct stat st;
    if (stat(path.c_str(), &st) != 0) {
      plan.notes.push_back("cannot keep " + op.path + " visible: " + errnoText(errno));
      continue;
    }
    op.isDir = S_ISDIR(st.st_mode);
    for (fs::path a = path.parent_path(); a != a.root_path(); a = a.parent_path()) {
      op.chain.insert(op.chain.begin(), a.string());
    }
    plan.ops.push_back(op);
  }
}

// SandboxSpec::hide and reveal as mount operations, outer paths first; as a non-root user, a
// note naming what stays readable instead.
void planMounts(const SandboxSpec& spec, Plan& plan) {
  const std::vector<fs::path> reveals = revealsOf(spec, plan);
  const std::vector<fs::path> hidden = planHides(hidesOf(spec, reveals, plan), plan);
  if (plan.ops.empty()) return;
  planReveals(reveals, hidden, plan);
  // Outer paths first; at equal depth, hide before revealing.
  std::stable_sort(plan.ops.begin(), plan.ops.end(), [](const MountOp& a, const MountOp& b) {
    if (a.depth != b.depth) return a.depth < b.depth;
    return (a.kind == MountOp::Reveal ? 1 : 0) < (b.kind == MountOp::Reveal ? 1 : 0);
  });
}

// Who the child runs as, and its argv and envp arrays (pointing into plan's own strings).
void planProgram(const SandboxSpec& spec, Plan& plan) {
  plan.root = geteuid() == 0;
  plan.dropPrivileges = plan.root && spec.uid != 0;
  plan.uid = spec.uid;
  plan.gid = spec.gid;
  plan.parent = getpid();  // forkChild sets the keeper instead when it makes a pid namespace
  plan.args = spec.argv;
  plan.envs = spec.env;
  for (std::string& a : plan.args) plan.argv.push_back(a.data());
  plan.argv.push_back(nullptr);
  for (std::string& e : plan.envs) plan.envp.push_back(e.data());
  plan.envp.push_back(nullptr);
}

// The work dir, and as root the options of the tmpfs laid over it.
std::string planWorkDir(const SandboxSpec& spec, Plan& plan) {
  if (std::string e = prepareWorkDir(spec.workDir, plan); !e.empty()) return e;
  plan.workDir = fs::absolute(spec.workDir).lexically_normal().string();
  if (plan.root && spec.workDirTmpfsBytes > 0) {
    plan.workTmpfs = "size=" + std::to_string(spec.workDirTmpfsBytes) +
                     ",mode=0700,uid=" + std::to_string(plan.dropPrivileges ? plan.uid : 0) +
                     ",gid=" + std::to_string(plan.dropPrivileges ? plan.gid : 0);
  }
  return "";
}

// The rlimits, in the order the child sets them.
void planLimits(const Limits& l, Plan& plan) {
  const auto cpu = static_cast<rlim_t>(std::max(1.0, std::ceil(l.cpuSeconds)));
  plan.limits.push_back({RLIMIT_CPU, cpu, cpu + 1});  // SIGXCPU first, SIGKILL a second later
  plan.limits.push_back({RLIMIT_AS, l.memoryBytes, l.memoryBytes});
  plan.limits.push_back({RLIMIT_FSIZE, l.fileSizeBytes, l.fileSizeBytes});
  const auto files = static_cast<rlim_t>(std::max(8, l.openFiles));
  plan.limits.push_back({RLIMIT_NOFILE, files, files});
  plan.limits.push_back({RLIMIT_CORE, 0, 0});
  const long tasks = tasksOf(plan.dropPrivileges ? plan.uid : getuid());
  const auto nproc = static_cast<rlim_t>(tasks + 1 + std::max(0, l.processes));
  plan.limits.push_back({RLIMIT_NPROC, nproc, nproc});
}

// The descriptors the child keeps or receives, and the free range above them the child uses
// while moving them into place. Returns an error, or "".
std::string planFds(const SandboxSpec& spec, Plan& plan) {
  int highest = 2;
  for (int fd : spec.keepFds) {
    plan.fds.push_back({fd, fd});
    highest = std::max(highest, fd);
  }
  for (const auto& [from, to] : spec.mapFds) {
    if (to < 3) return "mapFds: child fd " + std::to_string(to) + " is one of 0, 1, 2";
    plan.fds.push_back({from, to});
    highest = std::max(highest, to);
  }
  if (plan.fds.size() > 64) return "too many fds to pass (64 at most)";
  plan.highBase = highest + 1;
  rlimit nofile{};
  getrlimit(RLIMIT_NOFILE, &nofile);
  plan.maxFd = static_cast<int>(std::min<rlim_t>(nofile.rlim_cur, 65536));
  if (plan.highBase + 70 > plan.maxFd) return "fd numbers too high to pass";
  return "";
}

// Everything before fork. Returns an error, or "".
std::string makePlan(const SandboxSpec& spec, Plan& plan) {
  if (spec.argv.empty() || spec.argv[0].empty() || spec.argv[0][0] != '/') {
    return "argv[0] must be an absolute path" +
           (spec.argv.empty() ? std::string() : " (got '" + spec.argv[0] + "')");
  }
  planProgram(spec, plan);
  if (std::string e = planWorkDir(spec, plan); !e.empty()) return e;
  planMounts(spec, plan);
  planLimits(spec.limits, plan);
  if (std::string e = planFds(spec, plan); !e.empty()) return e;
  std::string filterError;
  plan.filter = filterFor(spec.limits.processes <= 0, filterError);
  if (!filterError.empty()) plan.notes.push_back(filterError + "; sockets are not refused");
  return "";
}

// The sentence for a failed step that isolates the child (mounts, network, seccomp); "" for
// the other steps.
std::string describeIsolationStep(const Record& r, const Plan& plan) {
  const std::string err = errnoText(r.err);
  const bool hasOp = r.index >= 0 && static_cast<std::size_t>(r.index) < plan.ops.size();
  const std::string opPath = hasOp ? plan.ops[r.index].path : std::string();
  switch (r.stage) {
    case kUnshareMounts:
      return "could not hide the grader's files (unshare(CLONE_NEWNS): " + err +
             "): only file permissions protect them";
    case kMountPrivate:
      return "could not hide the grader's files (making / private: " + err +
             "): only file permissions protect them";
    case kHide:
      return "could not hide " + opPath + " (mount: " + err + ")";
    case kReveal:
      return "could not keep " + opPath + " visible under a hidden path: " + err;
    case kUnshareNet:
      return "no network namespace (unshare(CLONE_NEWNET): " + err +
             "): sockets are refused by the seccomp filter only";
    case kWorkTmpfs:
      return "mounting a tmpfs on the work dir " + plan.workDir + ": " + err;
    case kProc:
      return "could not mount the pid namespace's own /proc (" + err +
             "): the code sees the machine's processes in /proc (it still cannot signal them)";
    case kSeccomp:
      return "could not install the seccomp filter (" + err + "): sockets are not refused";
    default:
      return "";
  }
}

// The sentence for a failed exec, with the likely cause when it runs as another user.
std::string describeExec(const Record& r, const Plan& plan, const SandboxSpec& spec) {
  std::string text = "exec " + spec.argv[0] + ": " + errnoText(r.err);
  if (r.err == EACCES && plan.dropPrivileges) {
    text += " (it runs as uid " + std::to_string(plan.uid) +
            ": the program and every folder above it must be readable and searchable by "
            "other users)";
  }
  return text;
}

// The sentence for a failed step that sets up the process (session, fds, limits, identity).
std::string describeProcessStep(const Record& r, const Plan& plan, const SandboxSpec& spec) {
  const std::string err = errnoText(r.err);
  switch (r.stage) {
    case kSetsid:
      return "setsid: " + err;
    case kDevNull:
      return "opening /dev/null: " + err;
    case kFds:
      return "passing file descriptors: " + err;
    case kRlimit:
      return std::string("setting ") +
             (r.index >= 0 && static_cast<std::size_t>(r.index) < plan.limits.size()
                  ? limitName(plan.limits[r.index].resource)
                  : "an rlimit") +
             ": " + err;
    case kChdir:
      return "entering the work dir " + plan.workDir + ": " + err;
    case kSetgroups:
      return "dropping supplementary groups: " + err;
    case kSetgid:
      return "switching to gid " + std::to_string(plan.gid) + ": " + err;
    case kSetuid:
      return "switching to uid " + std::to_string(plan.uid) + ": " + err;
    case kDeathSignal:
      return "setting the parent-death signal: " + err;
    case kNoNewPrivs:
      return "setting no_new_privs: " + err;
    case kExec:
      return describeExec(r, plan, spec);
    case kFork:
      return "starting the program in its pid namespace (fork): " + err;
    default:
      return "unknown setup stage " + std::to_string(r.stage) + ": " + err;
  }
}

// A child's setup report as a sentence for the grader's log or the student's report.
std::string describeRecord(const Record& r, const Plan& plan, const SandboxSpec& spec) {
  if (std::string text = describeIsolationStep(r, plan); !text.empty()) return text;
  return describeProcessStep(r, plan, spec);
}

// A started child: its pid, its output pipe, and what the setup said.
struct Started {
  pid_t pid = -1;
  int outFd = -1;
  int endFd = -1;  // in a pid namespace: where the keeper writes the program's wait status
  std::string error;
  std::vector<std::string> notes;
  std::string workDir;
};

// Reads one setup report from the child, waiting until `deadline`.
enum class Report { Got, Exec, Silent };
Report readReport(int fd, Clock::time_point deadline, Record& r) {
  std::size_t got = 0;
  while (got < sizeof r) {
    pollfd pfd{fd, POLLIN, 0};
    const int wait = static_cast<int>(std::max<long long>(
        0, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count()));
    const int ready = poll(&pfd, 1, wait);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return Report::Silent;
    const ssize_t n = ::read(fd, reinterpret_cast<char*>(&r) + got, sizeof r - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Report::Exec;  // EOF: the close-on-exec pipe closed in execve
    got += static_cast<std::size_t>(n);
  }
  return Report::Got;
}

// Reads the child's setup reports until it runs the program: a fatal report (or silence for
// 30 s) becomes s.error and returns false; the others become notes.
bool awaitExec(int statusFd, const Plan& plan, const SandboxSpec& spec, Started& s) {
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  bool started = true;
  for (Record r; started;) {
    const Report report = readReport(statusFd, deadline, r);
    if (report == Report::Exec) break;
    if (report == Report::Silent) {
      s.error = "the sandboxed child did not start within 30 s";
      started = false;
    } else if (r.fatal != 0) {
      s.error = describeRecord(r, plan, spec);
      started = false;
    } else {
      s.notes.push_back(describeRecord(r, plan, spec));
    }
  }
  ::close(statusFd);
  return started;
}

// The output pipe and the status pipe, both close-on-exec. Returns an error, or "".
std::string openPipes(int out[2], int status[2]) {
  if (pipe2(out, O_CLOEXEC) != 0) return "pipe: " + errnoText(errno);
  if (pipe2(status, O_CLOEXEC) != 0) {
    const std::string error = "pipe: " + errnoText(errno);
    ::close(out[0]);
    ::close(out[1]);
    return error;
  }
  return "";
}

// The child: as root, the init of a pid namespace of its own (clone(CLONE_NEWPID), raw, so the
// child runs only system calls as after fork); where the kernel refuses one, or not as root, a
// plain fork, and a note says what that leaves unprotected. Returns fork()'s result.
pid_t forkChild(Plan& plan, std::vector<std::string>& notes) {
  if (plan.root) {
    plan.pidNamespace = true;
    plan.keeperFd = ::open(paths::keeper, O_PATH | O_CLOEXEC);
    plan.keeperEndFd = std::to_string(plan.endFd);
    plan.keeperArgv = {const_cast<char*>("a6-keeper"), plan.keeperEndFd.data(), nullptr};
    plan.parent = 1;  // the program's parent: the keeper, init of the namespace
    const long pid = syscall(SYS_clone, CLONE_NEWPID | SIGCHLD, 0, 0, 0, 0);
    if (pid == 0) childMain(plan);
    if (pid > 0) return static_cast<pid_t>(pid);
    notes.push_back("no pid namespace (clone(CLONE_NEWPID): " + errnoText(errno) +
                    "): a process the code leaves running is found and ended by its user id");
    process::pidNamespaceRefused();
    plan.pidNamespace = false;
    plan.parent = getpid();
  }
  const pid_t pid = fork();
  if (pid == 0) childMain(plan);
  return pid;
}

Started start(const SandboxSpec& spec) {
  Started s;
  Plan plan;
  s.error = makePlan(spec, plan);
  s.workDir = plan.workDir;
  s.notes = plan.notes;
  int out[2], status[2], end[2] = {-1, -1};
  if (!s.error.empty() || !(s.error = openPipes(out, status)).empty()) return s;
  if (pipe2(end, O_CLOEXEC) != 0) {
    s.error = "pipe: " + errnoText(errno);
    for (int fd : {out[0], out[1], status[0], status[1]}) ::close(fd);
    return s;
  }
  plan.outFd = out[1];
  plan.statusFd = status[1];
  plan.endFd = end[1];

  const pid_t pid = forkChild(plan, s.notes);
  if (plan.keeperFd >= 0) ::close(plan.keeperFd);
  ::close(out[1]);
  ::close(status[1]);
  ::close(end[1]);
  if (pid < 0) {
    s.error = "fork: " + errnoText(errno);
    for (int fd : {out[0], status[0], end[0]}) ::close(fd);
    return s;
  }
  if (!awaitExec(status[0], plan, spec, s)) {
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    ::close(out[0]);
    ::close(end[0]);
    return s;
  }
  fcntl(out[0], F_SETFL, fcntl(out[0], F_GETFL) | O_NONBLOCK);
  fcntl(end[0], F_SETFL, fcntl(end[0], F_GETFL) | O_NONBLOCK);
  s.pid = pid;
  s.outFd = out[0];
  s.endFd = plan.pidNamespace ? end[0] : -1;
  if (!plan.pidNamespace) ::close(end[0]);
  return s;
}

// How the program ended, given the child's wait status: in a pid namespace the keeper wrote the
// program's own status before it exited; without that (the keeper was killed: a time-out, a
// stop) the child's. Closes endFd.
int programStatus(int endFd, int childStatus) {
  if (endFd < 0) return childStatus;
  int status = 0;
  const ssize_t n = ::read(endFd, &status, sizeof status);
  ::close(endFd);
  return n == static_cast<ssize_t>(sizeof status) ? status : childStatus;
}

// Fills kind and code from a wait status.
void setEnding(Exit& exit, int status) {
  if (WIFSIGNALED(status)) {
    exit.kind = Exit::Kind::Signaled;
    exit.code = WTERMSIG(status);
  } else {
    exit.kind = Exit::Kind::Exited;
    exit.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
}

// True once `pid` has ended (left unreaped).
bool hasEnded(pid_t pid) {
  siginfo_t info{};
  return waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
         info.si_pid == pid;
}

// Kills the whole group (the child stays unreaped until then, so its pgid is not reused) and
// reaps the child.
// `cpuSeconds`, when given, receives the CPU time the child and what it reaped used (in a pid
// namespace, the keeper reaped the program: its time is in there).
int killAndReap(pid_t pid, double* cpuSeconds = nullptr) {
  kill(-pid, SIGKILL);
  kill(pid, SIGKILL);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  if (cpuSeconds != nullptr) {
    *cpuSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                  static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
  }
  return status;
}

const char* signalText(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV (segmentation fault)";
    case SIGABRT:
      return "SIGABRT (aborted: abort(), a failed assert or an uncaught exception)";
    case SIGFPE:
      return "SIGFPE (arithmetic exception, e.g. an integer division by zero)";
    case SIGBUS:
      return "SIGBUS (bus error: a bad memory access)";
    case SIGILL:
      return "SIGILL (illegal instruction)";
    case SIGKILL:
      return "SIGKILL (killed by the grader or the memory limit)";
    case SIGXCPU:
      return "SIGXCPU (CPU time limit exceeded)";
    case SIGXFSZ:
      return "SIGXFSZ (file size limit exceeded)";
    case SIGSYS:
      return "SIGSYS (a system call the sandbox refuses)";
    case SIGPIPE:
      return "SIGPIPE (broken pipe)";
    case SIGTERM:
      return "SIGTERM (terminated)";
    case SIGTRAP:
      return "SIGTRAP (trace/breakpoint trap)";
    default:
      return nullptr;
  }
}

}  // namespace

std::string Exit::describe() const {
  switch (kind) {
    case Kind::Exited:
      return "exited with " + std::to_string(code);
    case Kind::Signaled: {
      const char* text = signalText(code);
      return std::string("killed by ") +
             (text != nullptr ? text : "signal " + std::to_string(code));
    }
    case Kind::TimedOut:
      return "timed out after " + formatSeconds(wallSeconds) + " s and was killed";
    case Kind::FailedToStart:
      return "failed to start: " + error;
  }
  return "ended in an unknown way";
}

bool killedByTheMachine(const Exit& e, const Limits& limits) {
  return e.kind == Exit::Kind::Signaled && e.code == SIGKILL && e.cpuSeconds < limits.cpuSeconds;
}

// runSandboxed
// -------------------------------------------------------------------------------------

Exit runSandboxed(const SandboxSpec& spec) {
  const auto begin = Clock::now();
  Exit exit;
  Started s = start(spec);
  exit.notes = s.notes;
  if (!s.error.empty()) {
    exit.kind = Exit::Kind::FailedToStart;
    exit.error = s.error;
    if (spec.removeWorkDir) deleteWorkDir(s.workDir);
    exit.wallSeconds = secondsSince(begin);
    return exit;
  }
  Sink sink;
  sink.cap = spec.limits.outputBytes;
  const auto deadline =
      begin + std::chrono::duration_cast<Clock::duration>(
                  std::chrono::duration<double>(std::max(0.0, spec.limits.wallSeconds)));
  const int pidFd = static_cast<int>(syscall(SYS_pidfd_open, s.pid, 0));
  bool ended = false, timedOut = false, outOpen = true;
  int status = 0;
  Clock::time_point graceEnd{};
  for (;;) {
    if (!ended && hasEnded(s.pid)) {
      ended = true;
      status = killAndReap(s.pid, &exit.cpuSeconds);  // stragglers of its group go too
      graceEnd = Clock::now() + std::chrono::milliseconds(500);
    }
    if (!ended && Clock::now() >= deadline) {
      timedOut = true;
      ended = true;
      status = killAndReap(s.pid);
      graceEnd = Clock::now() + std::chrono::milliseconds(500);
    }
    if (ended && (!outOpen || Clock::now() >= graceEnd)) break;
    // Wait for output, the child's end (pidfd), or the next check.
    pollfd pfds[2];
    nfds_t n = 0;
    if (outOpen) pfds[n++] = {s.outFd, POLLIN, 0};
    if (!ended && pidFd >= 0) pfds[n++] = {pidFd, POLLIN, 0};
    const auto until = ended ? graceEnd : deadline;
    long long wait =
        std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count() + 1;
    if (pidFd < 0 && !ended) wait = std::min(wait, 5LL);  // no pidfd: poll the child
    poll(pfds, n, static_cast<int>(std::clamp(wait, 0LL, 1000LL)));
    if (outOpen && !readSome(s.outFd, sink)) outOpen = false;
  }
  if (pidFd >= 0) ::close(pidFd);
  ::close(s.outFd);
  status = programStatus(s.endFd, status);
  if (timedOut) {
    exit.kind = Exit::Kind::TimedOut;
    exit.code = SIGKILL;
  } else {
    setEnding(exit, status);
  }
  exit.output = sink.text();
  exit.outputTruncated = sink.truncated;
  exit.wallSeconds = timedOut ? spec.limits.wallSeconds : secondsSince(begin);
  if (spec.removeWorkDir) deleteWorkDir(s.workDir);
  return exit;
}

// SandboxedProcess
// -------------------------------------------------------------------------------------

struct SandboxedProcess::State {
  Sink sink;
  int outFd = -1;
  int endFd = -1;  // the keeper's report of the program's status (pid namespace), or -1
  bool pidNamespace = false;
  pid_t program = -1;  // the program's pid (found once, in a pid namespace)
  std::thread drainer;
  std::atomic<bool> stopping{false};
  Clock::time_point begin;
  std::string workDir;
  bool removeWorkDir = false;
  std::vector<std::string> notes;
  bool stopped = false;
  Exit exit;
  std::mutex mutex;  // stop() and alive() from several threads
};

SandboxedProcess::SandboxedProcess(const SandboxSpec& spec) : state_(new State) {
  state_->begin = Clock::now();
  state_->sink.cap = spec.limits.outputBytes;
  state_->removeWorkDir = spec.removeWorkDir;
  Started s = start(spec);
  state_->notes = s.notes;
  state_->workDir = s.workDir;
  if (!s.error.empty()) {
    error_ = s.error;
    state_->stopped = true;
    state_->exit.kind = Exit::Kind::FailedToStart;
    state_->exit.error = s.error;
    state_->exit.notes = s.notes;
    if (state_->removeWorkDir) deleteWorkDir(state_->workDir);
    return;
  }
  pid_ = s.pid;
  state_->outFd = s.outFd;
  state_->endFd = s.endFd;
  state_->pidNamespace = s.endFd >= 0;
  State* state = state_;
  // Drains the output until its end, or shortly after stop() (a process that escaped the group
  // could hold the pipe open forever).
  state_->drainer = std::thread([state] {
    Clock::time_point graceEnd{};
    for (;;) {
      pollfd pfd{state->outFd, POLLIN, 0};
      poll(&pfd, 1, 50);
      if (!readSome(state->outFd, state->sink)) break;
      if (state->stopping.load()) {
        if (graceEnd == Clock::time_point{})
          graceEnd = Clock::now() + std::chrono::milliseconds(300);
        if (Clock::now() >= graceEnd) break;
      }
    }
  });
}

SandboxedProcess::~SandboxedProcess() {
  stop();
  delete state_;
}

bool SandboxedProcess::alive() {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return !state_->stopped && pid_ > 0 && !hasEnded(pid_);
}

pid_t SandboxedProcess::programPid() {
  std::lock_guard<std::mutex> lock(state_->mutex);
  if (!state_->pidNamespace || state_->stopped) return state_->stopped ? -1 : pid_;
  if (state_->program <= 0) state_->program = process::childInNamespace(pid_, 2).value_or(-1);
  return state_->program;
}

std::string SandboxedProcess::output() const { return state_->sink.text(); }

const std::vector<std::string>& SandboxedProcess::notes() const { return state_->notes; }

Exit SandboxedProcess::stop() {
  std::lock_guard<std::mutex> lock(state_->mutex);
  if (state_->stopped) return state_->exit;
  state_->stopped = true;
  double cpuSeconds = 0;
  const int status = programStatus(state_->endFd, killAndReap(pid_, &cpuSeconds));
  state_->endFd = -1;
  state_->stopping = true;
  if (state_->drainer.joinable()) state_->drainer.join();
  ::close(state_->outFd);
  state_->outFd = -1;
  Exit& exit = state_->exit;
  setEnding(exit, status);
  exit.cpuSeconds = cpuSeconds;
  exit.output = state_->sink.text();
  exit.outputTruncated = state_->sink.truncated;
  exit.wallSeconds = secondsSince(state_->begin);
  exit.notes = state_->notes;
  if (state_->removeWorkDir) deleteWorkDir(state_->workDir);
  return exit;
}

bool isWithin(const std::filesystem::path& inner, const std::filesystem::path& outer) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

void hideExcept(const std::filesystem::path& secret, const std::vector<std::filesystem::path>& keep,
                std::vector<std::filesystem::path>& out, int depth) {
  namespace fs = std::filesystem;
  std::vector<fs::path> inside;
  for (const fs::path& k : keep) {
    if (isWithin(secret, k)) return;  // the secret lies inside something kept visible
    if (isWithin(k, secret)) inside.push_back(k);
  }
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(secret, ec);
  // A link is not covered itself (that would cover its target): what it points to is either a
  // secret of its own or harmless.
  if (ec || !fs::exists(st) || fs::is_symlink(st)) return;
  if (inside.empty() || !fs::is_directory(st) || depth > 64) {
    out.push_back(secret);
    return;
  }
  for (fs::directory_iterator it(secret, ec), end; !ec && it != end; it.increment(ec)) {
    hideExcept(it->path(), inside, out, depth + 1);
  }
}

SandboxView allowOnly(const std::vector<std::filesystem::path>& visible,
                      const std::vector<std::filesystem::path>& secrets) {
  namespace fs = std::filesystem;
  SandboxView view;
  std::vector<fs::path> keep = {"/usr",
                                "/bin",
                                "/sbin",
                                "/lib",
                                "/lib32",
                                "/lib64",
                                "/libx32",
                                "/etc/alternatives",
                                "/etc/ld.so.cache",
                                "/etc/ld.so.conf",
                                "/etc/ld.so.conf.d",
                                "/proc"};
  for (const fs::path& v : visible) keep.push_back(fs::absolute(v).lexically_normal());
  for (const fs::path& s : secrets) hideExcept(fs::absolute(s).lexically_normal(), keep, view.hide);
  std::vector<fs::path> rest;
  hideExcept("/", keep, rest);
  // /dev: a fresh one, with only what a compiler or a program may read without harm.
  rest.emplace_back("/dev");
  for (const fs::path& p : rest) {
    if (std::find(view.hide.begin(), view.hide.end(), p) == view.hide.end()) view.hide.push_back(p);
  }
  view.reveal = {"/dev/null", "/dev/zero", "/dev/urandom"};
  // Kept in reveal too: where a folder above one cannot be searched by the child's user, that
  // folder is covered and the visible path bound back (planMounts).
  for (const fs::path& v : visible) view.reveal.push_back(fs::absolute(v).lexically_normal());
  return view;
}

}  // namespace a6::grader
