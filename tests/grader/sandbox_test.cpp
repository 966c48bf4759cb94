// The sandbox (grader/sandbox/sandbox.h), against a program that misbehaves on request
// (fixtures/sandbox_tool.cpp): every limit holds, the parent never hangs, and what the child
// sees (environment, cwd, fds, files, network, user) is what the sandbox promises.
#include "sandbox/sandbox.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sched.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sandbox/output.h"
#include "sandbox/process.h"

namespace a6::grader {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kTool = A6_SANDBOX_TOOL;
bool isRoot() { return geteuid() == 0; }

// Whether this machine lets root make mount and network namespaces (an unprivileged Docker
// container does not: the sandbox then falls back to permissions and says so in its notes).
bool namespacesAvailable() {
  if (!isRoot()) return false;
  const pid_t pid = fork();
  if (pid == 0) _exit(unshare(CLONE_NEWNS | CLONE_NEWNET) == 0 ? 0 : 1);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// A temporary folder every user can enter (the child may run as nobody).
class TempDir {
 public:
  TempDir() {
    char name[] = "/tmp/a6-sandbox-test-XXXXXX";
    path_ = mkdtemp(name);
    chmod(path_.c_str(), 0755);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

SandboxSpec toolSpec(const TempDir& tmp, std::vector<std::string> args) {
  SandboxSpec spec;
  spec.argv = {kTool};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.workDir = tmp.path() / "work";
  spec.limits.wallSeconds = 20;
  spec.limits.cpuSeconds = 20;
  return spec;
}

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

TEST(Sandbox, AnOrdinaryRunExitsWithItsOutput) {
  TempDir tmp;
  const Exit e = runSandboxed(toolSpec(tmp, {"sleep", "0"}));
  EXPECT_EQ(e.kind, Exit::Kind::Exited) << e.describe() << " " << e.error;
  EXPECT_EQ(e.code, 0);
  EXPECT_EQ(e.output, "woke up\n");
  EXPECT_TRUE(e.ok());
  EXPECT_EQ(e.describe(), "exited with 0");
  const Exit bad = runSandboxed(toolSpec(tmp, {"no-such-command"}));
  EXPECT_EQ(bad.describe(), "exited with 2");
  EXPECT_NE(bad.output.find("unknown command"), std::string::npos) << "stderr is captured too";
}

TEST(Sandbox, PastItsWallClockItIsKilledAndReportedAsTimedOut) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"sleep", "30"});
  spec.limits.wallSeconds = 1;
  const auto t0 = Clock::now();
  const Exit e = runSandboxed(spec);
  const double took = since(t0);
  EXPECT_EQ(e.kind, Exit::Kind::TimedOut) << e.describe();
  EXPECT_GE(took, 0.95);
  EXPECT_LT(took, 4.0)
      << "killed late (a loaded machine may take a second or two to kill and reap)";
  EXPECT_EQ(e.describe(), "timed out after 1 s and was killed");
}

TEST(Sandbox, PastItsCpuLimitItIsKilled) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"spin"});
  spec.limits.cpuSeconds = 1;
  spec.limits.wallSeconds = 15;
  const Exit e = runSandboxed(spec);
  ASSERT_EQ(e.kind, Exit::Kind::Signaled) << e.describe();
  EXPECT_TRUE(e.code == SIGXCPU || e.code == SIGKILL) << e.describe();
  EXPECT_LT(e.wallSeconds, 10);
}

TEST(Sandbox, ASegfaultIsReportedAsSigsegv) {
  TempDir tmp;
  const Exit e = runSandboxed(toolSpec(tmp, {"segv"}));
  EXPECT_EQ(e.kind, Exit::Kind::Signaled);
  EXPECT_EQ(e.code, SIGSEGV);
  EXPECT_EQ(e.describe(), "killed by SIGSEGV (segmentation fault)");
}

TEST(Sandbox, HugeOutputIsCappedAndNeverBlocksTheChild) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"spew", std::to_string(64 << 20)});
  spec.limits.outputBytes = 4096;
  const auto t0 = Clock::now();
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.kind, Exit::Kind::Exited) << e.describe();
  EXPECT_EQ(e.code, 0) << "the child finished writing: it was never blocked";
  EXPECT_EQ(e.output.size(), 4096u);
  EXPECT_TRUE(e.outputTruncated);
  EXPECT_LT(since(t0), 15);
}

// Processes whose command line contains `marker`.
int processesWith(const std::string& marker) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream in(entry.path() / "cmdline");
    std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (cmdline.find(marker) != std::string::npos) ++count;
  }
  return count;
}

TEST(Sandbox, AForkBombIsContainedAndNothingOutlivesTheRun) {
  TempDir tmp;
  const std::string marker = "a6-fork-bomb-" + std::to_string(getpid());
  SandboxSpec spec = toolSpec(tmp, {"forkbomb", "200", marker});
  spec.limits.processes = 3;
  // RLIMIT_NPROC counts per user: as root, a user of its own, so that other sandboxes running
  // meanwhile (ctest -j) neither eat nor add to its headroom. Otherwise, they share it.
  int allowed = 3;
  if (isRoot()) {
    spec.uid = spec.gid = 61000 + static_cast<uid_t>(getpid() % 1000);
  } else {
    allowed += 16;
  }
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.kind, Exit::Kind::Exited) << e.describe() << " " << e.error;
  int forked = -1;
  std::sscanf(e.output.c_str(), "forked %d", &forked);
  EXPECT_GE(forked, 0) << e.output;
  EXPECT_LE(forked, allowed) << "RLIMIT_NPROC let it fork more than Limits::processes";
  // Its sleeping children went with its process group.
  for (const auto t0 = Clock::now(); processesWith(marker) > 0 && since(t0) < 2;) usleep(10000);
  EXPECT_EQ(processesWith(marker), 0);

  spec.limits.processes = 0;
  const Exit none = runSandboxed(spec);
  EXPECT_EQ(none.output, "forked 0\n") << "processes = 0: fork is refused outright";
}

// A grading ends only what it started (grader/sandbox/process.h): what the code leaves running,
// in a session of its own, ends with the run.
TEST(Sandbox, WhatItLeavesRunningInASessionOfItsOwnEndsWithIt) {
  TempDir tmp;
  const std::string marker = "a6-escape-" + std::to_string(getpid());
  SandboxSpec spec = toolSpec(tmp, {"escape", marker});
  spec.limits.processes = 2;
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "escaped\n") << e.describe();
  if (!process::pidNamespaces()) GTEST_SKIP() << "no pid namespace here: ended by uid instead";
  for (const auto t0 = Clock::now(); processesWith(marker) > 0 && since(t0) < 2;) usleep(10000);
  EXPECT_EQ(processesWith(marker), 0) << "the escaped child outlived its sandbox";
}

// ... and nothing it does reaches a process it did not start, even one of its own user (another
// grading's, on a machine where two graders drew the same uid).
TEST(Sandbox, ItCannotSignalAProcessOutsideItEvenOfItsOwnUser) {
  if (!process::pidNamespaces()) GTEST_SKIP() << "needs root and pid namespaces";
  TempDir tmp;
  const uid_t uid = 61000 + static_cast<uid_t>(getpid() % 1000);
  const pid_t outside = fork();
  if (outside == 0) {
    if (setgid(65534) != 0 || setuid(uid) != 0) _exit(126);
    for (;;) pause();
  }
  ASSERT_GT(outside, 0);
  usleep(100000);
  SandboxSpec spec = toolSpec(tmp, {"killall"});
  spec.uid = uid;
  spec.gid = 65534;
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "sent\n") << e.describe();
  EXPECT_EQ(waitpid(outside, nullptr, WNOHANG), 0) << "the process outside was killed";
  kill(outside, SIGKILL);
  waitpid(outside, nullptr, 0);
}

// Under its keeper, the program dies of its own signals as it would alone.
TEST(Sandbox, AnAbortIsReportedAsSigabrt) {
  TempDir tmp;
  const Exit e = runSandboxed(toolSpec(tmp, {"abort"}));
  EXPECT_EQ(e.kind, Exit::Kind::Signaled) << e.describe();
  EXPECT_EQ(e.code, SIGABRT) << e.describe();
}

TEST(Sandbox, AHugeAllocationFails) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"alloc", "1024"});
  spec.limits.memoryBytes = 256u << 20;
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "allocation failed\n") << e.describe();
  const Exit small = runSandboxed(toolSpec(tmp, {"alloc", "16"}));
  EXPECT_EQ(small.output, "allocated 1\n") << "a modest allocation works";
}

TEST(Sandbox, AHugeFileIsCutAtTheFileSizeLimit) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"write", "big.bin", std::to_string(16 << 20)});
  spec.limits.fileSizeBytes = 1u << 20;
  spec.removeWorkDir = false;
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "wrote 1048576\n") << e.describe();
  EXPECT_EQ(fs::file_size(spec.workDir / "big.bin"), 1u << 20);
}

TEST(Sandbox, TheEnvironmentIsOnlyWhatWasGiven) {
  TempDir tmp;
  setenv("A6_SANDBOX_TEST_SECRET", "leaked", 1);
  SandboxSpec spec = toolSpec(tmp, {"env"});
  spec.env = {"PATH=/usr/bin:/bin", "ONLY=this"};
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "PATH=/usr/bin:/bin\nONLY=this\n");
  const Exit byDefault = runSandboxed(toolSpec(tmp, {"env"}));
  EXPECT_EQ(byDefault.output, "PATH=/usr/bin:/bin\n");
}

TEST(Sandbox, TheWorkingDirIsFreshAndEmptyAndRemovedWhenAsked) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"pwd"});
  fs::create_directories(spec.workDir);
  std::ofstream(spec.workDir / "stale.txt") << "left over";
  spec.removeWorkDir = true;
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, spec.workDir.string() + "\n0\n");
  EXPECT_FALSE(fs::exists(spec.workDir));
  spec.removeWorkDir = false;
  runSandboxed(spec);
  EXPECT_TRUE(fs::is_directory(spec.workDir)) << "kept when not asked to remove it";
}

TEST(Sandbox, OnlyTheStandardAndRequestedFdsAreOpenAndStdinIsEmpty) {
  TempDir tmp;
  const int stray = open("/etc/hostname", O_RDONLY);  // not close-on-exec
  int extra[2];
  ASSERT_EQ(pipe(extra), 0);
  SandboxSpec spec = toolSpec(tmp, {"fds"});
  spec.mapFds = {{extra[1], 5}};
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "0 1 2 5 \n")
      << "parent fds " << stray << ", " << extra[0] << ", " << extra[1];
  close(stray);
  close(extra[0]);
  close(extra[1]);
  const Exit in = runSandboxed(toolSpec(tmp, {"cat", "/dev/stdin"}));
  EXPECT_EQ(in.output, "") << "stdin is /dev/null";
  EXPECT_EQ(in.code, 0);
}

TEST(Sandbox, TheNetworkIsUnavailable) {
  // A listener the child would reach without the sandbox.
  const int listener = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(listener, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(listen(listener, 4), 0);
  socklen_t length = sizeof address;
  getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length);
  const std::string port = std::to_string(ntohs(address.sin_port));
  TempDir tmp;
  const Exit e = runSandboxed(toolSpec(tmp, {"connect", port}));
  EXPECT_NE(e.output.find("failed"), std::string::npos) << e.output;
  EXPECT_EQ(e.output.find("connected"), std::string::npos) << e.output;
  close(listener);
}

TEST(Sandbox, AsRootTheChildRunsAsNobodyWithoutGroups) {
  if (!isRoot()) GTEST_SKIP() << "privileges are dropped only when the grader runs as root";
  TempDir tmp;
  const Exit e = runSandboxed(toolSpec(tmp, {"id"}));
  EXPECT_EQ(e.output, "uid=65534 gid=65534 groups=0\n");
}

TEST(Sandbox, HiddenPathsAreUnreadableEvenByAbsolutePath) {
  TempDir tmp;
  const fs::path secrets = tmp.path() / "secrets";
  fs::create_directories(secrets / "goldens");
  std::ofstream(secrets / "solution.cpp") << "the answer is 42\n";
  std::ofstream(secrets / "goldens" / "image.txt") << "golden\n";
  const fs::path single = tmp.path() / "key.txt";
  std::ofstream(single) << "secret key\n";
  for (const fs::path& p : {secrets / "solution.cpp", secrets / "goldens" / "image.txt", single}) {
    chmod(p.c_str(), 0644);  // readable by everyone: only the sandbox protects them
  }
  chmod(secrets.c_str(), 0755);
  chmod((secrets / "goldens").c_str(), 0755);

  // Without hiding, the child reads them (so the checks below mean something).
  const Exit seen = runSandboxed(toolSpec(tmp, {"cat", (secrets / "solution.cpp").string()}));
  EXPECT_EQ(seen.output, "the answer is 42\n");

  auto hidden = [&](std::vector<std::string> args) {
    SandboxSpec spec = toolSpec(tmp, std::move(args));
    spec.hide = {secrets, single};
    return runSandboxed(spec);
  };
  const Exit probe = hidden({"cat", (secrets / "solution.cpp").string()});
  if (!isRoot()) {
    ASSERT_FALSE(probe.notes.empty());
    EXPECT_EQ(probe.notes[0], kNotRootNote);
    GTEST_SKIP() << "not root: hiding needs a mount namespace; the note says so";
  }
  if (!namespacesAvailable()) {
    ASSERT_FALSE(probe.notes.empty());
    EXPECT_NE(probe.notes[0].find("unshare(CLONE_NEWNS)"), std::string::npos) << probe.notes[0];
    GTEST_SKIP() << "no mount namespaces here; the note says so: " << probe.notes[0];
  }
  for (const std::string& note : probe.notes) ADD_FAILURE() << "note: " << note;
  EXPECT_EQ(probe.output.find("the answer is"), std::string::npos) << probe.output;
  EXPECT_NE(probe.output.find("cannot open"), std::string::npos) << probe.output;
  EXPECT_EQ(hidden({"ls", secrets.string()}).output, "") << "the hidden folder looks empty";
  const Exit key = hidden({"cat", single.string()});
  EXPECT_EQ(key.output.find("secret"), std::string::npos) << key.output;
  // The grader's own view is untouched.
  std::ifstream still(secrets / "solution.cpp");
  std::string line;
  std::getline(still, line);
  EXPECT_EQ(line, "the answer is 42");
}

TEST(Sandbox, AWorkDirInsideAHiddenFolderStaysVisibleAndItsSiblingsDoNot) {
  if (!namespacesAvailable()) GTEST_SKIP() << "hiding needs root and a mount namespace";
  TempDir tmp;
  const fs::path base = tmp.path() / "grader";
  fs::create_directories(base / "secret");
  std::ofstream(base / "secret" / "hidden.txt") << "hidden\n";
  chmod((base / "secret" / "hidden.txt").c_str(), 0644);
  chmod(base.c_str(), 0755);
  chmod((base / "secret").c_str(), 0755);
  SandboxSpec spec = toolSpec(tmp, {"ls", base.string()});
  spec.workDir = base / "runs" / "one";
  spec.hide = {base};
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.output, "runs\n") << e.describe() << " " << e.error;
  spec.argv = {kTool, "pwd"};
  const Exit here = runSandboxed(spec);
  EXPECT_EQ(here.output, spec.workDir.string() + "\n0\n") << here.error;
}

TEST(Sandbox, AProgramThatCannotStartSaysWhy) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {});
  spec.argv = {"/no/such/program"};
  const Exit e = runSandboxed(spec);
  EXPECT_EQ(e.kind, Exit::Kind::FailedToStart);
  EXPECT_NE(e.error.find("exec /no/such/program: No such file or directory"), std::string::npos)
      << e.error;
  EXPECT_EQ(e.describe().rfind("failed to start: ", 0), 0u);
  spec.argv = {"relative/program"};
  EXPECT_NE(runSandboxed(spec).error.find("absolute path"), std::string::npos);
  spec.argv = {kTool};
  spec.workDir = "/";
  EXPECT_NE(runSandboxed(spec).error.find("too close to /"), std::string::npos);
}

TEST(SandboxedProcess, RunsUntilStoppedAndStopsAtOnce) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"sleep", "30"});
  spec.removeWorkDir = true;
  SandboxedProcess process(spec);
  ASSERT_EQ(process.error(), "");
  EXPECT_TRUE(process.alive());
  EXPECT_TRUE(fs::is_directory(spec.workDir));
  const auto t0 = Clock::now();
  const Exit e = process.stop();
  EXPECT_LT(since(t0), 2);
  EXPECT_EQ(e.kind, Exit::Kind::Signaled);
  EXPECT_EQ(e.code, SIGKILL);
  EXPECT_FALSE(process.alive());
  EXPECT_EQ(process.stop().code, SIGKILL) << "stopping twice gives the same Exit";
  EXPECT_FALSE(fs::exists(spec.workDir));
}

TEST(SandboxedProcess, ItsOutputIsDrainedWhileItRunsAndCapped) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {"spew", std::to_string(8 << 20)});
  spec.limits.outputBytes = 1000;
  SandboxedProcess process(spec);
  ASSERT_EQ(process.error(), "");
  const auto t0 = Clock::now();
  while (process.alive() && since(t0) < 10) usleep(10000);
  EXPECT_FALSE(process.alive()) << "it could write all its output without anyone asking";
  const Exit e = process.stop();
  EXPECT_EQ(e.describe(), "exited with 0");
  EXPECT_EQ(e.output.size(), 1000u);
  EXPECT_TRUE(e.outputTruncated);
}

TEST(SandboxedProcess, ACrashIsWhatStopReports) {
  TempDir tmp;
  SandboxedProcess process(toolSpec(tmp, {"segv"}));
  ASSERT_EQ(process.error(), "");
  const auto t0 = Clock::now();
  while (process.alive() && since(t0) < 10) usleep(5000);
  EXPECT_EQ(process.stop().describe(), "killed by SIGSEGV (segmentation fault)");
}

TEST(SandboxedProcess, AFailedStartSaysWhy) {
  TempDir tmp;
  SandboxSpec spec = toolSpec(tmp, {});
  spec.argv = {"/no/such/probe"};
  SandboxedProcess process(spec);
  EXPECT_NE(process.error().find("No such file"), std::string::npos) << process.error();
  EXPECT_FALSE(process.alive());
  EXPECT_EQ(process.stop().kind, Exit::Kind::FailedToStart);
}

// The output pipe after the program ended. A grader held up by the load may come to read it only
// after the grace has passed: what the program wrote is still all there.
TEST(SandboxOutput, WhatThePipeHoldsIsReadEvenAfterTheGrace) {
  int fds[2];
  ASSERT_EQ(pipe2(fds, O_NONBLOCK), 0);
  const std::string text(60000, 'x');  // under the pipe's 64 KiB
  ASSERT_EQ(write(fds[1], text.data(), text.size()), static_cast<ssize_t>(text.size()));
  sandboxing::Sink sink;
  sink.cap = 1 << 20;
  // The write end stays open, as a process that escaped the group would hold it.
  sandboxing::readAfterEnd(fds[0], sink, Clock::now() - std::chrono::seconds(1));
  EXPECT_EQ(sink.text().size(), text.size());
  EXPECT_FALSE(sink.truncated);
  close(fds[0]);
  close(fds[1]);
}

// A writer that never stops (here /dev/zero, which always has more) cannot hold the reader: one
// call reads at most its bound, keeps what the cap allows and says the pipe is still open.
TEST(SandboxOutput, AWriterThatNeverStopsCannotHoldTheReader) {
  const int fd = open("/dev/zero", O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  sandboxing::Sink sink;
  sink.cap = 1000;
  EXPECT_TRUE(sandboxing::readSome(fd, sink));
  EXPECT_EQ(sink.text().size(), 1000u);
  EXPECT_TRUE(sink.truncated);
  // After the end, the grace bounds the wait for the pipe's end: it returns.
  sandboxing::readAfterEnd(fd, sink, Clock::now() + std::chrono::milliseconds(100));
  EXPECT_EQ(sink.text().size(), 1000u);
  close(fd);
}

}  // namespace
}  // namespace a6::grader
