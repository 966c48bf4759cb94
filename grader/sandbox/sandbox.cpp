// The sandbox (see sandbox.h for what the child gets, in order).
//
// Design note: fork, then only system calls. The grader forks from several threads, so the
// child may only make async-signal-safe calls: all it needs is prepared in a Plan before fork,
// and it reports failed steps as fixed-size records (stage, errno) on a close-on-exec status
// pipe, which the parent turns into sentences. EOF on that pipe means execve worked.
#include "sandbox/sandbox.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <mutex>
#include <thread>

#include "sandbox/output.h"
#include "sandbox/plan.h"
#include "sandbox/process.h"

namespace a6::paths {
extern const char keeper[];  // the a6-keeper program (cmake/A6FastBuild.cmake, a6_configured_path)
}  // namespace a6::paths

namespace a6::grader {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using process::secondsAfter;
using process::secondsSince;
using namespace sandboxing;  // NOLINT: the sandbox's own inside (plan.h)

namespace {

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

// The child's setup reports until it runs the program: a fatal one (or 30 s of silence) is
// s.error (false), the others notes.
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

// The output, status and end pipes, all close-on-exec. Returns an error, or "".
std::string openPipes(int (&pipes)[3][2]) {
  for (int k = 0; k < 3; ++k) {
    if (pipe2(pipes[k], O_CLOEXEC) == 0) continue;
    const std::string error = "pipe: " + errnoText(errno);
    for (int j = 0; j < k; ++j) {
      ::close(pipes[j][0]);
      ::close(pipes[j][1]);
    }
    return error;
  }
  return "";
}

// Kills the whole group (the child, unreaped until then, keeps its pgid from reuse) and reaps
// the child; `cpuSeconds` gets its CPU time and its reaped children's (the keeper's program).
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

// As root, the child is the init of its own pid namespace (a raw clone, so that it makes only
// system calls, as after fork); refused or not root, a plain fork, with a note. Returns the pid.
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
  if (!s.error.empty()) return s;
  int pipes[3][2];
  s.error = openPipes(pipes);
  if (!s.error.empty()) return s;
  int(&out)[2] = pipes[0];
  int(&status)[2] = pipes[1];
  int(&end)[2] = pipes[2];
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
    killAndReap(pid);
    for (int fd : {out[0], end[0]}) ::close(fd);
    return s;
  }
  for (int fd : {out[0], end[0]}) fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
  s.pid = pid;
  s.outFd = out[0];
  s.endFd = plan.pidNamespace ? end[0] : -1;
  if (!plan.pidNamespace) ::close(end[0]);
  return s;
}

// The program's wait status: the one the keeper wrote in a pid namespace, else (no namespace,
// or the keeper was killed) the child's. Closes endFd.
int programStatus(int endFd, int childStatus) {
  if (endFd < 0) return childStatus;
  int status = 0;
  const ssize_t n = ::read(endFd, &status, sizeof status);
  ::close(endFd);
  return n == static_cast<ssize_t>(sizeof status) ? status : childStatus;
}

// Fills kind and code from a wait status, and the output from what was captured.
void setEnding(Exit& exit, int status, const Sink& sink) {
  if (WIFSIGNALED(status)) {
    exit.kind = Exit::Kind::Signaled;
    exit.code = WTERMSIG(status);
  } else {
    exit.kind = Exit::Kind::Exited;
    exit.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  exit.output = sink.text();
  exit.outputTruncated = sink.truncated;
}

// True once `pid` has ended (left unreaped).
bool hasEnded(pid_t pid) {
  siginfo_t info{};
  return waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
         info.si_pid == pid;
}

const char* signalText(int sig) {
  static const std::map<int, const char*> kTexts = {
      {SIGSEGV, "SIGSEGV (segmentation fault)"},
      {SIGABRT, "SIGABRT (aborted: abort(), a failed assert or an uncaught exception)"},
      {SIGFPE, "SIGFPE (arithmetic exception, e.g. an integer division by zero)"},
      {SIGBUS, "SIGBUS (bus error: a bad memory access)"},
      {SIGILL, "SIGILL (illegal instruction)"},
      {SIGKILL, "SIGKILL (killed by the grader or the memory limit)"},
      {SIGXCPU, "SIGXCPU (CPU time limit exceeded)"},
      {SIGXFSZ, "SIGXFSZ (file size limit exceeded)"},
      {SIGSYS, "SIGSYS (a system call the sandbox refuses)"},
      {SIGPIPE, "SIGPIPE (broken pipe)"},
      {SIGTERM, "SIGTERM (terminated)"},
      {SIGTRAP, "SIGTRAP (trace/breakpoint trap)"}};
  const auto it = kTexts.find(sig);
  return it == kTexts.end() ? nullptr : it->second;
}

// Reads the child's output until it ends (true) or `deadline` passes (false); `outOpen` says
// whether its pipe is still open.
bool readUntilEnd(pid_t pid, int outFd, Clock::time_point deadline, Sink& sink, bool& outOpen) {
  const int pidFd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
  bool ended = false;
  while (!(ended = hasEnded(pid)) && Clock::now() < deadline) {
    pollfd pfds[2];
    nfds_t n = 0;
    if (outOpen) pfds[n++] = {outFd, POLLIN, 0};
    if (pidFd >= 0) pfds[n++] = {pidFd, POLLIN, 0};
    long long wait =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count() + 1;
    if (pidFd < 0) wait = std::min(wait, 5LL);  // no pidfd: poll the child
    poll(pfds, n, static_cast<int>(std::clamp(wait, 0LL, 1000LL)));
    if (outOpen && !readSome(outFd, sink)) outOpen = false;
  }
  if (pidFd >= 0) ::close(pidFd);
  return ended;
}

// Adds to `out` what to hide so that only the `keep` paths of `secret` can be read: the secret
// itself, or its other entries level by level down to what is kept.
void hideExcept(const fs::path& secret, const std::vector<fs::path>& keep,
                std::vector<fs::path>& out, int depth = 0) {
  std::vector<fs::path> inside;
  for (const fs::path& k : keep) {
    if (isWithin(secret, k)) return;  // the secret lies inside something kept visible
    if (isWithin(k, secret)) inside.push_back(k);
  }
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(secret, ec);
  // A link is not covered (that would cover its target, a secret of its own or harmless).
  if (ec || !fs::exists(st) || fs::is_symlink(st)) return;
  if (inside.empty() || !fs::is_directory(st) || depth > 64) {
    out.push_back(secret);
    return;
  }
  for (fs::directory_iterator it(secret, ec), end; !ec && it != end; it.increment(ec)) {
    hideExcept(it->path(), inside, out, depth + 1);
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
      return "timed out after " + secondsText(wallSeconds) + " s and was killed";
    case Kind::FailedToStart:
      return "failed to start: " + error;
  }
  return "ended in an unknown way";
}

bool killedByTheMachine(const Exit& e, const Limits& limits) {
  return e.kind == Exit::Kind::Signaled && e.code == SIGKILL && e.cpuSeconds < limits.cpuSeconds;
}

// ---- runSandboxed -------------------------------------------------------------------------------

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
  const auto deadline = secondsAfter(begin, std::max(0.0, spec.limits.wallSeconds));
  bool outOpen = true;
  const bool timedOut = !readUntilEnd(s.pid, s.outFd, deadline, sink, outOpen);
  const int status = timedOut ? killAndReap(s.pid) : killAndReap(s.pid, &exit.cpuSeconds);
  if (outOpen) readAfterEnd(s.outFd, sink, Clock::now() + std::chrono::milliseconds(500));
  ::close(s.outFd);
  setEnding(exit, programStatus(s.endFd, status), sink);
  if (timedOut) {
    exit.kind = Exit::Kind::TimedOut;
    exit.code = SIGKILL;
  }
  exit.wallSeconds = timedOut ? spec.limits.wallSeconds : secondsSince(begin);
  if (spec.removeWorkDir) deleteWorkDir(s.workDir);
  return exit;
}

// ---- SandboxedProcess ---------------------------------------------------------------------------

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
  // Drains the output until its end, or shortly after stop() (an escaped process could hold
  // the pipe open forever).
  state_->drainer = std::thread([state] {
    bool open = true;
    while (open && !state->stopping.load()) {
      pollfd pfd{state->outFd, POLLIN, 0};
      poll(&pfd, 1, 50);
      open = readSome(state->outFd, state->sink);
    }
    if (open)
      readAfterEnd(state->outFd, state->sink, Clock::now() + std::chrono::milliseconds(300));
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
  setEnding(exit, status, state_->sink);
  exit.cpuSeconds = cpuSeconds;
  exit.wallSeconds = secondsSince(state_->begin);
  exit.notes = state_->notes;
  if (state_->removeWorkDir) deleteWorkDir(state_->workDir);
  return exit;
}

fs::path absoluteClean(const fs::path& path) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return (ec ? fs::absolute(path) : c).lexically_normal();
}

bool permits(const struct stat& st, uid_t uid, gid_t gid, unsigned want) {
  const unsigned bits = st.st_uid == uid   ? (st.st_mode >> 6) & 7u
                        : st.st_gid == gid ? (st.st_mode >> 3) & 7u
                                           : st.st_mode & 7u;
  return (bits & want) == want;
}

bool isWithin(const std::filesystem::path& inner, const std::filesystem::path& outer) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

SandboxView allowOnly(const std::vector<std::filesystem::path>& visible,
                      const std::vector<std::filesystem::path>& secrets) {
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
  // Revealed too, for a folder above one that the child's user cannot search (planMounts).
  for (const fs::path& v : visible) view.reveal.push_back(fs::absolute(v).lexically_normal());
  return view;
}

}  // namespace a6::grader
