// The process layer (see process.h).
#include "sandbox/process.h"

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace a6::grader::process {
namespace {

using Clock = std::chrono::steady_clock;

constexpr gid_t kNogroup = 65534;
// Sandbox uids: [1e6, 2e9] where every uid is mapped; else (a container's 65536) the top of the
// mapped range, below nobody's.
constexpr unsigned long kDrawFrom = 1000000, kDrawTo = 2000000000;
constexpr unsigned long kSmallRangeFrom = 60001, kSmallRangeTo = 65533;

void pause(int milliseconds) {
  std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
}

bool isPid(const std::string& name) {
  return !name.empty() && name.find_first_not_of("0123456789") == std::string::npos;
}

// Sends `signo` to `pid` if it still runs as `uid`, through a pidfd (a reused pid is never hit).
void signalIfUid(pid_t pid, uid_t uid, int signo) {
  const int fd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
  if (fd < 0) {
    if (errno == ENOSYS) kill(pid, signo);  // kernels before 5.3
    return;
  }
  const std::optional<Info> now = describe(pid);  // the process the pidfd holds, if still there
  if (now && (now->realUid == uid || now->effectiveUid == uid)) {
    syscall(SYS_pidfd_send_signal, fd, signo, nullptr, 0);
  }
  ::close(fd);
}

// An exclusive lock on the uid's lock file: its fd, or -1 when another grading holds it.
int lockUid(uid_t uid) {
  const fs::path dir = access("/run/lock", W_OK) == 0 ? "/run/lock" : "/tmp";
  const fs::path file = dir / ("a6-sandbox-uid-" + std::to_string(uid) + ".lock");
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) return -1;
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// True when /bin/true runs as `uid` (its group nogroup).
bool runsAs(uid_t uid) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (syscall(SYS_setgroups, 0, nullptr) != 0 || syscall(SYS_setgid, kNogroup) != 0 ||
        syscall(SYS_setuid, uid) != 0) {
      _exit(126);
    }
    const int devnull = ::open("/dev/null", O_WRONLY);
    if (devnull >= 0) {
      dup2(devnull, STDOUT_FILENO);
      dup2(devnull, STDERR_FILENO);
    }
    execl("/bin/true", "true", static_cast<char*>(nullptr));
    _exit(127);
  }
  if (pid < 0) return false;
  const std::optional<int> status = waitFor(pid, 10);
  if (!status) {
    kill(pid, SIGKILL);
    waitFor(pid, 5);
    return false;
  }
  return WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
}

// Where sandbox uids are drawn: the widest range the user namespace maps, cut to those above.
std::pair<unsigned long, unsigned long> drawRange() {
  std::ifstream map("/proc/self/uid_map");
  unsigned long inside = 0, outside = 0, count = 0, bestFrom = 0, bestCount = 0;
  while (map >> inside >> outside >> count) {
    if (count > bestCount) bestFrom = inside, bestCount = count;
  }
  if (bestCount == 0) bestFrom = 0, bestCount = 65536;  // no map to read: the classic range
  const unsigned long last = bestFrom + bestCount - 1;
  if (bestFrom <= kDrawFrom && last >= kDrawTo) return {kDrawFrom, kDrawTo};
  return {std::max(bestFrom + 1, kSmallRangeFrom), std::min(last, kSmallRangeTo)};
}

bool inUse(uid_t uid, const std::vector<Info>& processes) {
  return std::any_of(processes.begin(), processes.end(),
                     [uid](const Info& p) { return p.realUid == uid || p.effectiveUid == uid; });
}

// A random uid no account, process or other grading's lock holds, locked in `fd`. False (with
// `error`) when 200 draws found none.
bool drawUnusedUid(int& fd, uid_t& uid, std::string& error) {
  const auto [from, to] = drawRange();
  if (from > to) {
    error = "this user namespace maps no uid to run the sandbox as";
    return false;
  }
  std::random_device entropy;
  std::mt19937_64 draw((static_cast<std::uint64_t>(entropy()) << 32) ^ entropy() ^
                       static_cast<std::uint64_t>(getpid()));
  std::uniform_int_distribution<unsigned long> pick(from, to);
  const std::vector<Info> processes = all();
  for (int attempt = 0; attempt < 200; ++attempt) {
    const auto candidate = static_cast<uid_t>(pick(draw));
    if (getpwuid(candidate) != nullptr || inUse(candidate, processes)) continue;
    if ((fd = lockUid(candidate)) < 0) continue;
    if (inUse(candidate, all())) {  // taken between the two looks
      ::close(fd);
      fd = -1;
      continue;
    }
    uid = candidate;
    return true;
  }
  error = "no unused sandbox uid was found in " + std::to_string(from) + ".." + std::to_string(to) +
          " (200 draws)";
  return false;
}

}  // namespace

std::optional<Info> describe(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  if (!in) return std::nullopt;
  Info info;
  info.pid = pid;
  bool any = false;
  // Name: escapes a newline as "\n", so every field is a line of its own.
  for (std::string line; std::getline(in, line);) {
    any = true;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = line.substr(0, colon);
    const std::string rest = line.substr(colon + 1);
    if (key == "State") {
      const std::size_t at = rest.find_first_not_of(" \t");
      if (at != std::string::npos) info.state = rest[at];
    } else if (key == "PPid") {
      info.ppid = static_cast<pid_t>(std::atol(rest.c_str()));
    } else if (key == "Uid") {  // real, effective, saved, filesystem
      long real = -1, effective = -1;
      std::istringstream(rest) >> real >> effective;
      info.realUid = static_cast<uid_t>(real);
      info.effectiveUid = static_cast<uid_t>(effective);
    } else if (key == "Threads") {
      info.threads = std::atoi(rest.c_str());
    } else if (key == "Seccomp") {
      info.seccompMode = std::atoi(rest.c_str());
    } else if (key == "Seccomp_filters") {
      info.seccompFilters = std::atoi(rest.c_str());
    } else if (key == "NSpid") {
      std::istringstream in(rest);
      for (long pid; in >> pid;) info.nsPid = static_cast<pid_t>(pid);  // the innermost
    }
  }
  if (!any) return std::nullopt;
  return info;
}

std::vector<Info> all() {
  std::vector<Info> out;
  std::error_code ec;
  for (fs::directory_iterator it("/proc", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!isPid(name)) continue;
    if (auto info = describe(static_cast<pid_t>(std::atol(name.c_str())))) out.push_back(*info);
  }
  return out;
}

std::optional<int> waitFor(pid_t pid, double seconds, bool* vanished) {
  if (vanished != nullptr) *vanished = false;
  const auto start = Clock::now();
  for (int delay = 1;; delay = std::min(delay * 2, 50)) {
    int status = 0;
    const pid_t got = waitpid(pid, &status, WNOHANG);
    if (got == pid) return status;
    if (got < 0 && errno != EINTR) {
      if (vanished != nullptr) *vanished = true;
      return std::nullopt;
    }
    if (secondsSince(start) >= seconds) return std::nullopt;
    pause(delay);
  }
}

int endStrayChildren(const std::vector<pid_t>& keep) {
  const pid_t self = getpid();
  int ended = 0;
  for (int round = 0; round < 100; ++round) {
    std::vector<pid_t> strays;
    for (const Info& p : all()) {
      if (p.ppid != self) continue;
      if (std::find(keep.begin(), keep.end(), p.pid) != keep.end()) continue;
      strays.push_back(p.pid);
    }
    if (strays.empty()) break;
    for (const pid_t pid : strays) {
      // Our child cannot be reaped (and its pid reused) before we wait for it: no race here.
      if (getpgid(pid) == pid) kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
    }
    for (const pid_t pid : strays) {
      if (waitFor(pid, 5)) ++ended;
    }
  }
  return ended;
}

namespace {
std::atomic<bool> gPidNamespaceRefused{false};
}

void pidNamespaceRefused() { gPidNamespaceRefused = true; }

bool pidNamespaces() {
  if (gPidNamespaceRefused) return false;
  static const bool allowed = [] {
    if (geteuid() != 0) return false;
    const long pid = syscall(SYS_clone, CLONE_NEWPID | SIGCHLD, 0, 0, 0, 0);
    if (pid == 0) _exit(0);
    if (pid < 0) return false;
    const std::optional<int> status = waitFor(static_cast<pid_t>(pid), 30);
    return status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
  }();
  return allowed;
}

std::optional<pid_t> childInNamespace(pid_t parent, pid_t nsPid) {
  for (const Info& p : all()) {
    if (p.ppid == parent && p.nsPid == nsPid) return p.pid;
  }
  return std::nullopt;
}

std::string endProcessesOf(uid_t uid, double seconds) {
  if (uid == 0) return "refusing to end the processes of root";
  const auto start = Clock::now();
  const pid_t self = getpid();
  for (;;) {
    std::vector<Info> left;
    for (const Info& p : all()) {
      if (p.pid == self || (p.realUid != uid && p.effectiveUid != uid)) continue;
      if (p.state == 'Z') {
        if (p.ppid == self) waitFor(p.pid, 0);  // ours: reap it (it counts for RLIMIT_NPROC)
        continue;
      }
      left.push_back(p);
    }
    if (left.empty()) return "";
    if (secondsSince(start) > seconds) {
      return std::to_string(left.size()) + " processes of uid " + std::to_string(uid) +
             " are still alive after " + std::to_string(static_cast<int>(seconds)) + " s";
    }
    // Stopped processes cannot fork: stop them all first, then kill them.
    for (const Info& p : left) signalIfUid(p.pid, uid, SIGSTOP);
    for (const Info& p : left) signalIfUid(p.pid, uid, SIGKILL);
    pause(2);
  }
}

UidClaim::~UidClaim() {
  if (fd_ < 0) return;
  if (!pidNamespaces()) endProcessesOf(uid_);
  ::close(fd_);  // releases the lock
}

UidClaim::UidClaim(UidClaim&& other) noexcept : fd_(other.fd_), uid_(other.uid_) { other.fd_ = -1; }

UidClaim& UidClaim::operator=(UidClaim&& other) noexcept {
  if (this != &other) {
    this->~UidClaim();
    fd_ = other.fd_;
    uid_ = other.uid_;
    other.fd_ = -1;
  }
  return *this;
}

UidClaim claimUid(std::optional<uid_t> wanted, std::string& error) {
  const auto fail = [&error](std::string why) {
    error = std::move(why);
    return UidClaim{};
  };
  if (geteuid() != 0)
    return fail("not root: the sandbox runs as this user, with no user of its own");
  UidClaim claim;
  if (wanted) {
    if (*wanted == 0) return fail("the sandbox user cannot be root");
    const auto start = Clock::now();
    while ((claim.fd_ = lockUid(*wanted)) < 0 && secondsSince(start) < 60) pause(100);
    if (claim.fd_ < 0) {
      return fail("another grading has held sandbox uid " + std::to_string(*wanted) +
                  " for a minute");
    }
    claim.uid_ = *wanted;
    // Its processes are not ours to end, unless no pid namespace ends what each sandbox starts.
    if (pidNamespaces()) {
      if (inUse(*wanted, all())) {
        return fail("sandbox uid " + std::to_string(*wanted) +
                    " is in use by processes this grading did not start: give another uid, or "
                    "none (a grading draws an unused one)");
      }
    } else if (const std::string e = endProcessesOf(*wanted); !e.empty()) {
      return fail("sandbox uid " + std::to_string(*wanted) + ": " + e);
    }
  } else if (!drawUnusedUid(claim.fd_, claim.uid_, error)) {
    return claim;
  }
  if (!runsAs(claim.uid_)) {
    return fail("no process could run as sandbox uid " + std::to_string(claim.uid_));
  }
  return claim;
}

}  // namespace a6::grader::process
