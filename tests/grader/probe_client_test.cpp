// The ProbeClient (grader/probe/probe_client.h) against real probes: the solution's (answers bit
// for bit as in-process code does) and a hostile one (fixtures/probe_hostile/spring.cpp: crashes,
// loops, NaN, system calls, garbage on the answer pipe). A failure costs only its own request.
#include "probe/probe_client.h"

#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "harness/wire.h"
#include "sandbox_user.h"

namespace {
#include A6_FORCE_MODELS  // the reference physics (grader/reference/physics.inc)
}  // namespace

namespace a6::grader {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kSolution = A6_PROBE_SOLUTION;
const fs::path kHostile = A6_PROBE_HOSTILE;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

class TempDir {
 public:
  TempDir() {
    char name[] = "/tmp/a6-probe-test-XXXXXX";
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

harness::SpringForceRequest spring(double ks) {
  harness::SpringForceRequest r;
  r.p1.x = Vec2(0, 0);
  r.p2.x = Vec2(2, 0);
  r.restLength = 1;
  r.ks = ks;
  return r;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ---- the solution's probe answers exactly as the in-process code does
// ----------------------------

// Asks the probe and the in-process code the same: the same answer, byte for byte.
void expectSameAnswer(harness::StudentCode& probe, harness::StudentCode& local,
                      const harness::Request& request, const char* what) {
  const harness::Answer viaProbe = probe.ask(request), inProcess = local.ask(request);
  const harness::Outcome& outcome = harness::outcomeOf(viaProbe);
  EXPECT_TRUE(outcome.ok()) << what << ": " << outcome.error;
  EXPECT_EQ(wire::toBytes(wire::encodeAnswer(viaProbe)),
            wire::toBytes(wire::encodeAnswer(inProcess)))
      << what;
}

// A moving hot particle touching a half-plane, in air with drag, buoyancy and repulsion.
harness::ForcesRequest everyExternalForce() {
  harness::ForcesRequest forces;
  forces.particle.v = Vec2(0.5, -2);
  forces.particle.temperature = 500;
  forces.env.drag = 0.3;
  forces.env.buoyancy = 0.01;
  forces.env.repulsion = 1000;
  forces.env.planes.push_back(HalfPlane{});
  forces.contact.depth = 0.01;
  return forces;
}

// Two springs from a pinned particle, 120 frames in 4 substeps, recorded every 7th.
harness::SimulateRequest pinnedChain() {
  harness::SimulateRequest sim;
  sim.particles.resize(3);
  sim.particles[0].pinned = true;
  sim.particles[1].x = Vec2(0.5, 0);
  sim.particles[2].x = Vec2(1, 0.1);
  sim.springs = {{0, 1, 0.5, 100, 0.5, SpringType::Structural},
                 {1, 2, 0.5, 100, 0.5, SpringType::Structural}};
  sim.frames = 120;
  sim.substeps = 4;
  sim.recordEvery = 7;
  sim.referenceForces = true;
  return sim;
}

harness::Box2DRequest mouseDrag() {
  harness::Box2DRequest box;
  box.scene = "mouse_drag";
  box.steps = 60;
  box.drag = {{harness::DragEvent::Kind::Begin, 5, Vec2(0.5, 1)},
              {harness::DragEvent::Kind::Move, 20, Vec2(1, 2)},
              {harness::DragEvent::Kind::End, 40, Vec2(1, 2)}};
  return box;
}

TEST(ProbeClient, TheSolutionsProbeAnswersBitForBitAsInProcess) {
  TempDir tmp;
  ProbeClient probe(kSolution, tmp.path() / "run", Limits{});
  probe.setUser(a6::test::sandboxUid(), 65534);
  probe.serveForces(referenceForceModel());  // asked for over the force pipes
  auto local = harness::makeInProcess(referenceForceModel());
  auto same = [&](const harness::Request& request, const char* what) {
    expectSameAnswer(probe, *local, request, what);
  };
  // Each kind of request, then whole scenes.
  same(harness::Request(spring(50)), "springForce");
  same(harness::Request(everyExternalForce()), "forces");
  same(harness::Request(pinnedChain()), "simulate");
  ClothSpec cloth;
  cloth.n = 6;
  cloth.bending = true;
  same(harness::Request(harness::ClothRequest{cloth}), "buildCloth");
  harness::EmitRequest emit;
  emit.seed = 77;
  emit.count = 500;
  same(harness::Request(emit), "emit");
  harness::ParticleRunRequest run;
  run.seed = 5;
  run.steps = 90;
  run.dt = 1.0 / 64;
  run.referenceForces = true;
  same(harness::Request(run), "runParticles");
  harness::Box2DRequest box = mouseDrag();
  same(harness::Request(box), "runBox2D");
  box.scene = "car";
  box.drag.clear();
  same(harness::Request(box), "runBox2D car");
  harness::SceneRequest scene;
  scene.scene = "cloth_shear";
  scene.frames = {0, 30, 10};
  same(harness::Request(scene), "runScene cloth");
  scene.scene = "bridge";
  same(harness::Request(scene), "runScene bridge");
  scene.scene = "fire";
  same(harness::Request(scene), "runScene fire");

  EXPECT_EQ(probe.starts(), 1) << "one probe served every request";
}

// The grader's force answers are its own time: a check gets 2 ms a force on top of its limit,
// never more than four times the limit.
TEST(ProbeClient, ForcesTheGraderAnswersAddToTheTimeLimitUpToACap) {
  EXPECT_EQ(forceWaitAllowance(0, 2), 0);
  EXPECT_DOUBLE_EQ(forceWaitAllowance(500, 2), 1.0);
  EXPECT_DOUBLE_EQ(forceWaitAllowance(4000, 2), 8.0);
  EXPECT_DOUBLE_EQ(forceWaitAllowance(std::size_t{1} << 40, 10), 40.0);
  // The probe of tasks 3 and 5 counts them: a cloth's second of motion is one per step.
  TempDir tmp;
  ProbeClient probe(kSolution, tmp.path() / "run", Limits{});
  probe.setUser(a6::test::sandboxUid(), 65534);
  probe.serveForces(referenceForceModel());
  harness::SimulateRequest sim;
  const harness::ClothResult grid = harness::makeInProcess()->ask(harness::ClothRequest{});
  ASSERT_TRUE(grid.ok()) << grid.error;
  sim.particles = grid.particles;
  sim.springs = grid.springs;
  sim.frames = 60;
  sim.substeps = 4;
  sim.referenceForces = true;
  ASSERT_TRUE(probe.ask(sim).ok());
  // One batch of springs and one of external forces a step (240 steps).
  EXPECT_EQ(probe.forceAnswers(), 2u * 240u);
}

// What PerRequestOverheadIsSmall measures, in seconds, via the probe and in process.
struct Overheads {
  double spring = 0, springInProcess = 0;  ///< a springForce request
  double cloth = 0, clothInProcess = 0;    ///< buildCloth n=30
  double second = 0, secondInProcess = 0;  ///< a cloth's second, reference forces asked for
  std::size_t springs = 0;                 ///< of that cloth
  double firstRequest = 0;                 ///< a fresh probe: start-up plus the first request
};

// A small request and a larger one: a 30x30 cloth (961 particles, ~3500 springs) there and back.
void timeSmallAndLargeRequests(harness::StudentCode& probe, harness::StudentCode& local,
                               Overheads& o) {
  ASSERT_TRUE(probe.ask(spring(10)).ok());  // started and warm
  constexpr int kRequests = 2000;
  auto t0 = Clock::now();
  for (int k = 0; k < kRequests; ++k) ASSERT_TRUE(probe.ask(spring(k)).ok());
  o.spring = since(t0) / kRequests;
  t0 = Clock::now();
  for (int k = 0; k < kRequests; ++k) ASSERT_TRUE(local.ask(spring(k)).ok());
  o.springInProcess = since(t0) / kRequests;
  ClothSpec cloth;
  cloth.n = 30;
  t0 = Clock::now();
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(probe.ask(harness::ClothRequest{cloth}).ok());
  o.cloth = since(t0) / 20;
  t0 = Clock::now();
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(local.ask(harness::ClothRequest{cloth}).ok());
  o.clothInProcess = since(t0) / 20;
}

// Tasks 3 and 5 ask the grader for every reference force: a 10x10 cloth's second of motion.
void timeAClothsSecond(harness::StudentCode& probe, harness::StudentCode& local, Overheads& o) {
  harness::SimulateRequest sim;
  const harness::ClothResult grid = local.ask(harness::ClothRequest{});
  ASSERT_TRUE(grid.ok()) << grid.error;
  sim.particles = grid.particles;
  sim.springs = grid.springs;
  sim.frames = 60;
  sim.substeps = 4;
  sim.recordEvery = 60;
  sim.referenceForces = true;
  auto t0 = Clock::now();
  const harness::SimulateResult remote = probe.ask(sim);
  o.second = since(t0);
  ASSERT_TRUE(remote.ok()) << remote.error;
  t0 = Clock::now();
  const harness::SimulateResult here = local.ask(sim);
  o.secondInProcess = since(t0);
  o.springs = sim.springs.size();
  EXPECT_EQ(wire::toBytes(wire::encodeResult<harness::SimulateRequest>(remote)),
            wire::toBytes(wire::encodeResult<harness::SimulateRequest>(here)));
}

void timeAFreshProbe(Overheads& o) {
  TempDir tmp2;
  ProbeClient fresh(kSolution, tmp2.path() / "run", Limits{});
  fresh.setUser(a6::test::sandboxUid(), 65534);
  const auto t0 = Clock::now();
  ASSERT_TRUE(fresh.ask(spring(1)).ok());
  o.firstRequest = since(t0);
}

void printOverheads(const Overheads& o) {
  std::printf("[ overhead ] springForce: %.1f us via the probe, %.3f us in process\n",
              o.spring * 1e6, o.springInProcess * 1e6);
  std::printf("[ overhead ] buildCloth n=30: %.2f ms via the probe, %.2f ms in process\n",
              o.cloth * 1e3, o.clothInProcess * 1e3);
  std::printf("[ overhead ] starting a probe and its first request: %.1f ms\n",
              o.firstRequest * 1e3);
  std::printf(
      "[ overhead ] a cloth's second with the reference forces asked for: %.1f ms via "
      "the probe, %.1f ms in process (%zu springs, 240 steps)\n",
      o.second * 1e3, o.secondInProcess * 1e3, o.springs);
}

TEST(ProbeClient, PerRequestOverheadIsSmall) {
  TempDir tmp;
  ProbeClient probe(kSolution, tmp.path() / "run", Limits{});
  probe.setUser(a6::test::sandboxUid(), 65534);
  probe.serveForces(referenceForceModel());  // asked for over the force pipes
  auto local = harness::makeInProcess(referenceForceModel());
  Overheads o;
  timeSmallAndLargeRequests(probe, *local, o);
  if (HasFatalFailure()) return;
  timeAClothsSecond(probe, *local, o);
  if (HasFatalFailure()) return;
  timeAFreshProbe(o);
  if (HasFatalFailure()) return;
  printOverheads(o);
  EXPECT_LT(o.spring, 2e-3) << "a round trip should take well under 2 ms";
  EXPECT_LT(o.firstRequest, 2.0);
}

// ---- a hostile probe: each failure costs its own request only
// --------------------------------------------

class HostileProbe : public ::testing::Test {
 protected:
  TempDir tmp;
  ProbeClient probe{kHostile, tmp.path() / "run", Limits{}};
  void SetUp() override { probe.setUser(a6::test::sandboxUid(), 65534); }
  void expectHealthy() {
    const auto r = probe.ask(spring(10));
    EXPECT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.force, Vec2(-10, 0));
  }
};

TEST_F(HostileProbe, ACrashFailsItsRequestAndTheNextOneGetsAFreshProbe) {
  expectHealthy();
  EXPECT_EQ(probe.starts(), 1);
  const auto r = probe.ask(spring(13));
  EXPECT_EQ(r.error, "the probe crashed: killed by SIGSEGV (segmentation fault)");
  expectHealthy();
  EXPECT_EQ(probe.starts(), 2);
  EXPECT_FALSE(fs::exists(tmp.path() / "run" / "probe-1")) << "the dead probe's work dir is gone";
  EXPECT_TRUE(fs::exists(tmp.path() / "run" / "probe-2"));
}

// "Crashed" means the code crashed: a probe killed by a SIGKILL that neither the grader nor the
// CPU limit sent (the kernel's OOM killer, another program) is the machine's (Fault::Killed, run
// again by the checks), never charged as the code's crash.
TEST_F(HostileProbe, AKillFromOutsideIsTheMachinesNotACrash) {
  if (geteuid() != 0) GTEST_SKIP() << "as another user, the probe runs as this one";
  probe.setRequestTimeout(20);
  std::thread killer([] {
    for (int k = 0; k < 100; ++k) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      for (const process::Info& p : process::all()) {
        std::ifstream in("/proc/" + std::to_string(p.pid) + "/cmdline");
        std::string cmdline;
        std::getline(in, cmdline, '\0');
        // This test's probe: its program, run as this test process's own sandbox user.
        if (cmdline == kHostile.string() && p.state != 'Z' && p.realUid == a6::test::sandboxUid()) {
          kill(p.pid, SIGKILL);
          return;
        }
      }
    }
  });
  const auto r = probe.ask(spring(14));
  killer.join();
  EXPECT_EQ(r.fault, harness::Fault::Killed) << r.error;
  EXPECT_EQ(probe.incidents().crashes, 0);
  expectHealthy();
}

// ... while one killed by its CPU limit (it ignored SIGXCPU) ran out of its own time: a crash of
// the code's.
TEST(ProbeClient, AKillByTheCpuLimitIsTheCodes) {
  TempDir tmp;
  Limits limits;
  limits.cpuSeconds = 1;
  ProbeClient probe(kHostile, tmp.path() / "run", limits);
  probe.setUser(a6::test::sandboxUid(), 65534);
  probe.setRequestTimeout(30);
  const auto r = probe.ask(spring(25));
  EXPECT_EQ(r.fault, harness::Fault::Crashed) << r.error;
  EXPECT_TRUE(contains(r.error, "SIGKILL")) << r.error;
}

TEST_F(HostileProbe, ACrashReportEndsWithTheLastLinesItPrinted) {
  const auto r = probe.ask(spring(23));
  EXPECT_TRUE(contains(r.error, "killed by SIGSEGV")) << r.error;
  EXPECT_TRUE(contains(r.error, "the last lines it printed:\nabout to crash, said the spring"))
      << r.error;
  EXPECT_TRUE(contains(probe.output(), "about to crash, said the spring"));
  EXPECT_TRUE(contains(probe.output(), "[a6: probe 1 crashed: killed by SIGSEGV"));
}

TEST_F(HostileProbe, AnInfiniteLoopTimesOutWithinTheLimitAndTheNextRequestWorks) {
  probe.setRequestTimeout(1.0);
  const auto t0 = Clock::now();
  const auto r = probe.ask(spring(14));
  const double took = since(t0);
  EXPECT_EQ(r.fault, harness::Fault::TimedOut) << r.error;
  EXPECT_NE(r.error.find("ran out of time: 1 s"), std::string::npos) << r.error;
  EXPECT_GE(took, 1.0);
  EXPECT_LT(took, 3.0)
      << "reported late (a loaded machine may take a second or two to kill and reap)";
  expectHealthy();
}

TEST_F(HostileProbe, NaNAndNegativeZeroComeBackAsThemselves) {
  const auto r = probe.ask(spring(15));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(std::isnan(r.force.x()));
  EXPECT_TRUE(r.force.y() == 0 && std::signbit(r.force.y()));
}

TEST_F(HostileProbe, FilesSocketsProcessesThreadsAndExecutableMemoryAreRefused) {
  const auto r = probe.ask(spring(16));
  EXPECT_FALSE(contains(r.error, "succeeded")) << r.error;
  for (const char* what :
       {"fopen(/etc/passwd): failed", "fopen(scratch.txt, w): failed", "socket: failed",
        "fork: failed", "thread: failed", "mmap(PROT_EXEC): failed"}) {
    EXPECT_TRUE(contains(r.error, what)) << what << " in: " << r.error;
  }
  EXPECT_EQ(probe.starts(), 1) << "a refused system call is not a crash";
  expectHealthy();
}

TEST_F(HostileProbe, PrintingALotIsCappedAndHarmless) {
  const auto r = probe.ask(spring(17));
  EXPECT_TRUE(r.ok()) << r.error;
  // The output is drained by another thread: give it a moment.
  std::string out = probe.output();
  for (const auto t0 = Clock::now(); out.size() < Limits{}.outputBytes && since(t0) < 5;) {
    usleep(10000);
    out = probe.output();
  }
  EXPECT_LE(out.size(), Limits{}.outputBytes);
  EXPECT_GT(out.size(), Limits{}.outputBytes / 2);
  expectHealthy();
}

TEST_F(HostileProbe, AbortAndExceptionsAndExitAreReportedAsSuch) {
  EXPECT_TRUE(contains(probe.ask(spring(18)).error, "killed by SIGABRT")) << "abort()";
  EXPECT_EQ(probe.ask(spring(19)).error, "exception: the hostile spring throws");
  const int before = probe.starts();
  expectHealthy();
  EXPECT_EQ(probe.starts(), before) << "an exception does not cost the probe";
  EXPECT_EQ(probe.ask(spring(21)).error, "the probe crashed: exited with 0");
  expectHealthy();
}

TEST_F(HostileProbe, GarbageOnTheAnswerPipeFailsTheRequestOnly) {
  const auto r = probe.ask(spring(20));
  EXPECT_EQ(r.error.rfind("garbage from the probe: not MessagePack", 0), 0u) << r.error;
  expectHealthy();
  const auto big = probe.ask(spring(22));
  EXPECT_EQ(big.error.rfind("garbage from the probe: an answer of 1073741824 bytes announced", 0),
            0u)
      << big.error;
  expectHealthy();
  EXPECT_EQ(probe.starts(), 3);
}

TEST_F(HostileProbe, TheMemoryLimitMakesAHugeAllocationFail) {
  const auto r = probe.ask(spring(24));
  EXPECT_TRUE(contains(r.error, "bad_alloc")) << r.error;
}

TEST_F(HostileProbe, AfterTooManyStartsRequestsFailAtOnce) {
  probe.setMaxStarts(3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(contains(probe.ask(spring(13)).error, "SIGSEGV"));
  }
  const auto t0 = Clock::now();
  const auto r = probe.ask(spring(10));
  EXPECT_LT(since(t0), 0.05);
  EXPECT_EQ(r.error,
            "the probe was started 3 times (it crashed or ran out of time each time); the "
            "remaining requests were not run");
  EXPECT_EQ(probe.starts(), 3);
}

TEST(ProbeClient, AMissingProbeFailsEveryRequestWithTheReason) {
  TempDir tmp;
  ProbeClient probe(tmp.path() / "nothing-here", tmp.path() / "run", Limits{});
  probe.setUser(a6::test::sandboxUid(), 65534);
  const auto r = probe.ask(harness::EmitRequest{});
  EXPECT_TRUE(contains(r.error, "could not start the probe: exec ")) << r.error;
  EXPECT_TRUE(contains(r.error, "No such file or directory")) << r.error;
}

TEST(ProbeClient, AProbeThatDiesBeforeReadingNeverTakesTheGraderWithIt) {
  // /bin/true ends at once: large requests meet a closed pipe (EPIPE, no SIGPIPE death).
  TempDir tmp;
  ProbeClient probe("/bin/true", tmp.path() / "run", Limits{});
  harness::SimulateRequest big;
  big.particles.resize(20000);
  for (int k = 0; k < 5; ++k) {
    const auto r = probe.ask(big);
    EXPECT_EQ(r.error, "the probe crashed: exited with 0");
  }
  EXPECT_EQ(probe.starts(), 5);
}

TEST(ProbeClient, AsRootItsProtectionsApplyWithoutNotes) {
  if (geteuid() != 0) GTEST_SKIP() << "not root: privileges and namespaces are not available";
  const pid_t pid = fork();
  if (pid == 0) _exit(unshare(CLONE_NEWNS | CLONE_NEWNET) == 0 ? 0 : 1);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    GTEST_SKIP() << "this machine refuses namespaces even to root (a container?)";
  }
  TempDir tmp;
  ProbeClient probe(kSolution, tmp.path() / "run", Limits{});
  probe.setUser(a6::test::sandboxUid(), 65534);
  probe.setHidden({tmp.path() / "secret"});
  fs::create_directories(tmp.path() / "secret");
  EXPECT_TRUE(probe.ask(spring(1)).ok());
  for (const std::string& note : probe.notes()) ADD_FAILURE() << note;
}

}  // namespace
}  // namespace a6::grader
