// The reference forces over a pipe (framework/harness/force_channel.h): both ends in this
// process, the grader's in a thread. The forces that come back are the models' bit for bit, a
// system's forces of one state cost one round trip, and no request a probe can write makes the
// grader's side crash, allocate without bound or hang.
#include "harness/force_channel.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <future>
#include <limits>
#include <optional>
#include <vector>

namespace {

#include A6_FORCE_MODELS

namespace fc = a6::harness::forcechannel;
using a6::Vec2;

// Two pipes and a stop pipe; the grader's side serves in a thread until the test ends.
class Channel {
 public:
  Channel() {
    if (pipe(requests_) != 0 || pipe(answers_) != 0 || pipe(stop_) != 0) std::abort();
  }
  ~Channel() {
    closeFd(stop_[1]);
    closeFd(requests_[1]);
    if (served_.valid()) served_.wait();
    for (int* fd : {&requests_[0], &answers_[0], &answers_[1], &stop_[0]}) closeFd(*fd);
  }
  void serve(const a6::ForceModel& models) {
    served_ = std::async(std::launch::async, [this, models] {
      return fc::serve(requests_[0], answers_[1], stop_[0], models);
    });
  }
  a6::ForceModel remote() const { return fc::remoteModel(requests_[1], answers_[0]); }
  // Raw bytes as a probe could write them.
  void write(const void* data, std::size_t n) { ASSERT_EQ(::write(requests_[1], data, n), n); }
  void writeRequest(const std::vector<double>& r) {
    const auto n = static_cast<std::uint32_t>(r.size());
    write(&n, sizeof n);
    write(r.data(), r.size() * sizeof(double));
  }
  void stop() { closeFd(stop_[1]); }
  // How many requests the grader answered, once it has ended (or nothing after 60 s: a hang).
  std::optional<std::size_t> answered() {
    if (served_.wait_for(std::chrono::seconds(60)) != std::future_status::ready) return {};
    return served_.get();
  }

 private:
  static void closeFd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
  int requests_[2], answers_[2], stop_[2];
  std::future<std::size_t> served_;
};

bool same(const Vec2& a, const Vec2& b) { return std::memcmp(a.data(), b.data(), 16) == 0; }

// A chain of particles and springs, not at rest.
struct Chain {
  std::vector<a6::Particle> particles = std::vector<a6::Particle>(6);
  std::vector<a6::Spring> springs;
  Chain() {
    for (std::size_t i = 0; i < particles.size(); ++i) {
      particles[i].x = Vec2(0.3 * i, 0.01 * i * i);
      particles[i].v = Vec2(0.1, -0.2 * i);
      particles[i].temperature = 300 + 40 * i;
    }
    for (std::size_t i = 0; i + 1 < particles.size(); ++i) {
      a6::Spring s;
      s.p1 = &particles[i];
      s.p2 = &particles[i + 1];
      s.restLength = 0.25;
      s.ks = 100 + i;
      s.kd = 0.5;
      springs.push_back(s);
    }
  }
  a6::ParticlesView view() const {
    return {particles.size(),
            [this](std::size_t i) -> const a6::Particle& { return particles[i]; }};
  }
};

a6::Environment environment() {
  a6::Environment env;
  env.drag = 0.3;
  env.buoyancy = 0.01;
  env.repulsion = 500;
  env.planes.push_back({Vec2(0, 1), 0.05});
  env.circles.push_back({Vec2(0.6, 0), 0.2});
  return env;
}

TEST(ForceChannel, AnswersAreTheModelsBitForBitAndOneStateCostsOneRequest) {
  Channel channel;
  channel.serve(referenceForceModel());
  const a6::ForceModel remote = channel.remote();
  Chain chain;
  const a6::Environment env = environment();
  for (const a6::Spring& s : chain.springs) {
    EXPECT_TRUE(same(remote.spring(s), referenceSpringForce(s)));
    EXPECT_TRUE(same(remote.springAmong(s, chain.springs), referenceSpringForce(s)));
  }
  for (const a6::Particle& p : chain.particles) {
    EXPECT_TRUE(same(remote.external(p, env), referenceExternalForce(p, env)));
    EXPECT_TRUE(same(remote.externalAmong(p, chain.view(), env), referenceExternalForce(p, env)));
  }
  // A new state: one more batch; copies of the springs (a stepper looping by value), in reverse
  // order, cost nothing more; a spring like none of the system's: a batch, then asked alone.
  chain.particles[2].x.x() += 0.01;
  for (const a6::Spring& s : chain.springs) {
    EXPECT_TRUE(same(remote.springAmong(s, chain.springs), referenceSpringForce(s)));
  }
  for (auto it = chain.springs.rbegin(); it != chain.springs.rend(); ++it) {
    const a6::Spring copy = *it;
    EXPECT_TRUE(same(remote.springAmong(copy, chain.springs), referenceSpringForce(copy)));
  }
  a6::Spring other = chain.springs[0];
  other.restLength = 0.5;
  EXPECT_TRUE(same(remote.springAmong(other, chain.springs), referenceSpringForce(other)));
  channel.stop();
  // 5 + 6 single requests, one batch of springs and one of particles, a second batch of springs,
  // and the other spring: a batch (it is not among them), then alone.
  EXPECT_EQ(channel.answered(), std::optional<std::size_t>(5 + 6 + 1 + 1 + 1 + 2));
}

TEST(ForceChannel, NaNAndInfinitiesTravelAsTheyAre) {
  Channel channel;
  channel.serve(referenceForceModel());
  Chain chain;
  chain.particles[0].x = Vec2(std::numeric_limits<double>::quiet_NaN(), 1);
  chain.springs[1].ks = std::numeric_limits<double>::infinity();
  for (const a6::Spring& s : chain.springs) {
    const Vec2 got = channel.remote().spring(s);
    const Vec2 want = referenceSpringForce(s);
    EXPECT_TRUE(same(got, want) || (got.hasNaN() && want.hasNaN())) << got << " vs " << want;
  }
}

// Each is what a hostile probe may write instead of a request: the grader's side stops serving
// (answering nothing) and never crashes, hangs or allocates what a count announces.
TEST(ForceChannel, AMalformedRequestEndsTheServing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::vector<double>> malformed = {
      {0},                                                     // an unknown kind
      {1, 0, 0},                                               // a spring too short
      {2, 0, 0, 0, 0, 1, 300},                                 // a particle without its environment
      {2, 0, 0, 0, 0, 1, 300, 0, -9.81, 293, 0, 0, 0, 1, 0},   // a plane announced, none sent
      {2, 0, 0, 0, 0, 1, 300, 0, -9.81, 293, 0, 0, 0, -1, 0},  // a negative count
      {2, 0, 0, 0, 0, 1, 300, 0, -9.81, 293, 0, 0, 0, nan, 0},    // a count that is NaN
      {2, 0, 0, 0, 0, 1, 300, 0, -9.81, 293, 0, 0, 0, 1e300, 0},  // a count beyond any limit
      {3, 2, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1},                    // two springs, one sent
      {3, 1e18},                                                  // a batch beyond any limit
      {4, 1, 0, -9.81, 293, 0, 0, 0, 0, 0},                       // a particle announced, none
      {3, 1.5, 0, 0, 0, 0, 1, 300, 1, 0, 0, 0, 1, 300, 0.25, 100, 0.5, 0},  // a count not whole
      {1, 0, 0, 0, 0, 1, 300, 1, 0, 0, 0, 1, 300, 0.25, 100, 0.5, 7},       // a spring type unknown
  };
  // Forces enough, against obstacles enough, to keep the grader busy for seconds: refused.
  std::vector<double> busy = {4, 2048, 0, -9.81, 293, 0, 0, 0, 1024};
  for (int k = 0; k < 1024; ++k) busy.insert(busy.end(), {0, 1, -1.0 * k});
  busy.push_back(0);  // and no circle
  busy.resize(busy.size() + 2048 * 6, 0.5);
  malformed.push_back(busy);
  for (const std::vector<double>& request : malformed) {
    Channel channel;
    channel.serve(referenceForceModel());
    channel.writeRequest(request);
    EXPECT_EQ(channel.answered(), std::optional<std::size_t>(0)) << request.size() << " doubles";
  }
  for (const std::uint32_t count :
       {0u, static_cast<std::uint32_t>(fc::kMaxRequestDoubles + 1), 0xffffffffu}) {
    Channel channel;
    channel.serve(referenceForceModel());
    channel.write(&count, sizeof count);
    EXPECT_EQ(channel.answered(), std::optional<std::size_t>(0)) << count;
  }
}

TEST(ForceChannel, AHalfWrittenRequestDoesNotHoldTheGraderOnceStopped) {
  Channel channel;
  channel.serve(referenceForceModel());
  const std::uint32_t n = 12;
  channel.write(&n, sizeof n);  // and never the doubles
  channel.stop();
  EXPECT_EQ(channel.answered(), std::optional<std::size_t>(0));
}

TEST(ForceChannel, WithTheGraderGoneAForceIsNaNNotACrash) {
  std::signal(SIGPIPE, SIG_IGN);  // as the probe does: its writes then fail with EPIPE
  int requests[2], answers[2];
  ASSERT_EQ(pipe(requests), 0);
  ASSERT_EQ(pipe(answers), 0);
  ::close(requests[0]);
  ::close(answers[1]);
  Chain chain;
  const a6::ForceModel remote = fc::remoteModel(requests[1], answers[0]);
  EXPECT_TRUE(remote.spring(chain.springs[0]).hasNaN());
  EXPECT_TRUE(remote.springAmong(chain.springs[0], chain.springs).hasNaN());
  EXPECT_TRUE(remote.externalAmong(chain.particles[0], chain.view(), environment()).hasNaN());
  ::close(requests[1]);
  ::close(answers[0]);
}

// A batch past the grader's work bound (particles times obstacles) is asked one force at a time:
// every force is the model's, none NaN.
TEST(ForceChannel, ABatchPastTheWorkBoundIsAskedOneForceAtATime) {
  Channel channel;
  channel.serve(referenceForceModel());
  a6::Environment env = environment();
  env.planes.resize(fc::kMaxObstacles - 1, env.planes[0]);
  std::vector<a6::Particle> many(2100);
  for (std::size_t i = 0; i < many.size(); ++i) many[i].x = Vec2(0.001 * i, 0.01);
  const a6::ParticlesView view{many.size(),
                               [&](std::size_t i) -> const a6::Particle& { return many[i]; }};
  const a6::ForceModel remote = channel.remote();
  for (std::size_t i : {std::size_t{0}, std::size_t{1}, many.size() - 1}) {
    EXPECT_TRUE(
        same(remote.externalAmong(many[i], view, env), referenceExternalForce(many[i], env)))
        << i;
  }
  channel.stop();
  EXPECT_EQ(channel.answered(), std::optional<std::size_t>(3)) << "three forces asked alone";
}

TEST(ForceChannel, AnEnvironmentOverTheLimitIsNaNWithoutAsking) {
  Channel channel;
  channel.serve(referenceForceModel());
  Chain chain;
  a6::Environment env = environment();
  env.planes.resize(fc::kMaxObstacles);
  EXPECT_TRUE(channel.remote().external(chain.particles[0], env).hasNaN());
  EXPECT_TRUE(channel.remote().externalAmong(chain.particles[0], chain.view(), env).hasNaN());
  env.planes.resize(fc::kMaxObstacles - 1);  // with the circle: at the limit
  EXPECT_TRUE(same(channel.remote().external(chain.particles[0], env),
                   referenceExternalForce(chain.particles[0], env)));
  channel.stop();
  EXPECT_EQ(channel.answered(), std::optional<std::size_t>(1));
}

}  // namespace
