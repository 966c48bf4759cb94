// The process layer (grader/sandbox/process.h) alone: waiting for one child, ending strays without
// reaping what is kept, ending every process of a sandbox user whatever it is named, and claiming
// a user per grading.
#include "sandbox/process.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "poisoner.h"

namespace {

namespace process = a6::grader::process;

// A child that exits with `code` after `ms` milliseconds.
pid_t childExiting(int code, int ms) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    _exit(code);
  }
  return pid;
}

// Processes whose real or effective uid is `uid`, zombies left out.
int aliveOf(uid_t uid) {
  int n = 0;
  for (const process::Info& p : process::all()) {
    if ((p.realUid == uid || p.effectiveUid == uid) && p.state != 'Z') ++n;
  }
  return n;
}

TEST(ProcessWait, GivesTheStatusOfItsOwnChild) {
  const pid_t pid = childExiting(7, 10);
  const std::optional<int> status = process::waitFor(pid, 30);
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFEXITED(*status));
  EXPECT_EQ(WEXITSTATUS(*status), 7);
}

TEST(ProcessWait, SaysWhenThePidIsNoChildOfOurs) {
  bool vanished = false;
  EXPECT_FALSE(process::waitFor(getppid(), 1, &vanished).has_value());
  EXPECT_TRUE(vanished);
}

TEST(ProcessWait, ARunningChildGivesNothingYet) {
  const pid_t pid = childExiting(0, 3000);
  bool vanished = true;
  EXPECT_FALSE(process::waitFor(pid, 0, &vanished).has_value());
  EXPECT_FALSE(vanished);
  kill(pid, SIGKILL);
  EXPECT_TRUE(process::waitFor(pid, 30).has_value());
}

// The batch's hang: a kept child that has exited must still be there for its own wait after a
// sweep for strays, however often the sweep runs.
TEST(ProcessStrays, AKeptChildThatExitedIsNeverReapedByASweep) {
  for (int round = 0; round < 20; ++round) {
    const pid_t kept = childExiting(3, 0);
    const pid_t stray = childExiting(0, 60000);
    for (int k = 0; k < 5; ++k) {
      process::endStrayChildren({kept});
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const std::optional<int> status = process::waitFor(kept, 30);
    ASSERT_TRUE(status.has_value()) << "round " << round << ": the kept child was reaped";
    EXPECT_EQ(WEXITSTATUS(*status), 3);
    bool vanished = false;
    EXPECT_FALSE(process::waitFor(stray, 0, &vanished).has_value());
    EXPECT_TRUE(vanished) << "the stray was ended and reaped";
  }
}

TEST(ProcessUsers, TwoClaimsNeverShareAUid) {
  if (geteuid() != 0) GTEST_SKIP() << "only root changes the sandbox's user";
  std::string e1, e2;
  const process::UidClaim a = process::claimUid(std::nullopt, e1);
  const process::UidClaim b = process::claimUid(std::nullopt, e2);
  ASSERT_TRUE(a.held()) << e1;
  ASSERT_TRUE(b.held()) << e2;
  EXPECT_NE(a.uid(), b.uid());
  EXPECT_NE(a.uid(), 65534u) << "never nobody: other programs run as nobody";
  std::ifstream map("/proc/self/uid_map");
  unsigned long inside = 1, outside = 0, count = 0;
  map >> inside >> outside >> count;
  if (inside == 0 && count == 4294967295ul) {
    EXPECT_GE(a.uid(), 1000000u) << "drawn far above every account";
    EXPECT_GE(b.uid(), 1000000u);
  }
}

TEST(ProcessUsers, EveryProcessOfAUserEndsWhateverItIsNamed) {
  if (geteuid() != 0) GTEST_SKIP() << "only root changes the sandbox's user";
  std::string error;
  process::UidClaim claim = process::claimUid(std::nullopt, error);
  ASSERT_TRUE(claim.held()) << error;
  const uid_t uid = claim.uid();
  const pid_t poisoner = a6::test::startPoisoner(uid);
  for (int k = 0; k < 200 && aliveOf(uid) < 2; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_GE(aliveOf(uid), 1) << "the poisoner did not start";
  EXPECT_EQ(process::endProcessesOf(uid), "");
  EXPECT_EQ(aliveOf(uid), 0);
  process::waitFor(poisoner, 5);
}

// A grading ends only what it started: a uid some process runs as (another grading's, or what
// one left behind) is never drawn, and asked for by name it is refused, its processes untouched.
TEST(ProcessUsers, AUidInUseIsNeverClaimedAndItsProcessesAreLeftAlone) {
  if (!process::pidNamespaces()) GTEST_SKIP() << "needs root and pid namespaces";
  const uid_t uid = 62000 + static_cast<uid_t>(getpid() % 1000);
  const pid_t poisoner = a6::test::startPoisoner(uid);
  for (int k = 0; k < 200 && aliveOf(uid) < 1; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_GE(aliveOf(uid), 1) << "the poisoner did not start";
  std::string error;
  const process::UidClaim named = process::claimUid(uid, error);
  EXPECT_FALSE(named.held());
  EXPECT_NE(error.find("in use"), std::string::npos) << error;
  EXPECT_GE(aliveOf(uid), 1) << "the claim ended processes it did not start";
  for (int k = 0; k < 20; ++k) {
    const process::UidClaim drawn = process::claimUid(std::nullopt, error);
    ASSERT_TRUE(drawn.held()) << error;
    EXPECT_NE(drawn.uid(), uid);
    EXPECT_EQ(aliveOf(drawn.uid()), 0) << "a drawn uid has no process";
  }
  EXPECT_GE(aliveOf(uid), 1);
  kill(poisoner, SIGKILL);
  process::waitFor(poisoner, 5);
  process::endProcessesOf(uid);  // the poisoner's child, in a session of its own
}

}  // namespace
