// Task 5 — emitParticle and ParticleSystem::update.
//
// The emitter is random, so it is compared by DISTRIBUTIONS over thousands of particles, never
// particle by particle: an emitter that draws its random numbers in another order passes. Every
// statistical tolerance is 6 standard errors of the statistic for a correct emitter (a false
// failure has odds below one in 10^8 per check, whatever the seed).
//
// The update runs with the reference force model (referenceForces = true: a bug in task 2 costs
// task 2 only), and its oracles are exact: symplectic Euler's discrete free fall
// x_n = x0 + v0 t_n + a t_n (t_n + h) / 2, the fixed point m g / k_d of drag, the cooling law,
// and ages on a time step that is a power of two (1/64 s), so that k steps make exactly k/64 s.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

#include "suite.h"

namespace a6::test {
namespace task5_particles {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDt = 1.0 / 64;  // exact in binary: ages add up without round-off
constexpr int kEmitted = 4000;    // particles per emitter test

// ----------------------------------------------------------------------------------------------
// The emitter
// ----------------------------------------------------------------------------------------------

EmitterSpec emitterSpec() {
  EmitterSpec spec;
  spec.position = Vec2(2.0, -1.0);
  spec.radius = 0.5;
  spec.velocity = Vec2(0.3, 1.5);
  spec.velocitySpread = 0.4;
  spec.mass = 0.002;
  spec.temperatureMin = 600;
  spec.temperatureMax = 900;
  spec.lifetimeMin = 1.5;
  spec.lifetimeMax = 4.0;
  return spec;
}

std::string input(const EmitterSpec& s, std::uint64_t seed, int count) {
  std::ostringstream out;
  out << "  input: " << count << " particles from emitParticle with seed " << seed
      << ", EmitterSpec{position=" << str(s.position) << ", radius=" << s.radius
      << ", velocity=" << str(s.velocity) << ", velocitySpread=" << s.velocitySpread
      << ", mass=" << num(s.mass) << ", temperature=[" << num(s.temperatureMin) << ", "
      << num(s.temperatureMax) << "], lifetime=[" << num(s.lifetimeMin) << ", "
      << num(s.lifetimeMax) << "]}";
  return out.str();
}

harness::ParticlesResult emit(const EmitterSpec& spec, std::uint64_t seed, int count = kEmitted) {
  harness::EmitRequest request;
  request.spec = spec;
  request.seed = seed;
  request.count = count;
  return student().ask(request);
}

double mean(const std::vector<double>& xs) {
  double sum = 0;
  for (double x : xs) sum += x;
  return xs.empty() ? 0 : sum / static_cast<double>(xs.size());
}

double variance(const std::vector<double>& xs) {
  const double m = mean(xs);
  double sum = 0;
  for (double x : xs) sum += (x - m) * (x - m);
  return xs.size() < 2 ? 0 : sum / static_cast<double>(xs.size() - 1);
}

double correlation(const std::vector<double>& xs, const std::vector<double>& ys) {
  const double mx = mean(xs), my = mean(ys);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    sxy += (xs[k] - mx) * (ys[k] - my);
    sxx += (xs[k] - mx) * (xs[k] - mx);
    syy += (ys[k] - my) * (ys[k] - my);
  }
  return sxy / std::sqrt(sxx * syy);  // NaN (a failure) when one of them does not vary
}

// Failures reported so far in the running test: loops over particles stop at the first one
// that fails, so that a student reads one clear message, not thousands.
int failures() {
  return ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
}

template <typename Get>
std::vector<double> collect(const std::vector<Particle>& ps, Get get) {
  std::vector<double> out;
  out.reserve(ps.size());
  for (const Particle& p : ps) out.push_back(get(p));
  return out;
}

// Checks that `xs` looks uniform on [lo, hi]: the range is respected, the range is covered up
// to its ends, and the mean and variance are those of the uniform distribution.
void expectUniform(const std::vector<double>& xs, double lo, double hi, const std::string& what,
                   const std::string& in, const std::string& advice) {
  ASSERT_FALSE(xs.empty());
  const double n = static_cast<double>(xs.size());
  const double width = hi - lo, a = width / 2;
  const double slack = 1e-12 * (std::abs(lo) + std::abs(hi) + 1);
  const auto [mn, mx] = std::minmax_element(xs.begin(), xs.end());
  const std::string range = "[" + num(lo) + ", " + num(hi) + "]: smallest " + num(*mn) +
                            ", largest " + num(*mx) + "\n  " + in;
  // Outside the range or not spread at all: the statistics below would only repeat it.
  ASSERT_TRUE(*mn >= lo - slack && *mx <= hi + slack)
      << currentTask() << ": " << what << " outside " << range << hint(advice);
  ASSERT_LT(*mn, *mx) << currentTask() << ": all the " << what << " are the same, " << range
                      << hint(advice);
  // With 4000 draws the extremes come within 1% of the ends (odds of failing ~1e-17).
  EXPECT_TRUE(*mn - lo < 0.01 * width && hi - *mx < 0.01 * width)
      << currentTask() << ": " << what << " do not cover " << range << hint(advice);
  // Mean: standard error width / sqrt(12 n). Variance a²/3: standard error sqrt(4/45) a² / sqrt(n).
  EXPECT_CLOSE(mean(xs), (lo + hi) / 2, modelError(6 * width / std::sqrt(12 * n), width))
      << "mean of the " << what << ", " << in << hint(advice);
  EXPECT_CLOSE(variance(xs), a * a / 3,
               modelError(6 * std::sqrt(4.0 / 45) * a * a / std::sqrt(n), a * a / 3))
      << "variance of the " << what << " (a uniform draw on [lo, hi] has (hi - lo)²/12), " << in
      << hint(advice);
}

TEST(Task5Particles, EmittedPositionsLieInTheDisc) {
  const EmitterSpec spec = emitterSpec();
  const auto r = emit(spec, 11);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), static_cast<std::size_t>(kEmitted));
  for (const Particle& p : r.particles) {
    const double distance = (p.x - spec.position).norm();
    ASSERT_LE(distance, spec.radius * (1 + 1e-12))
        << currentTask() << ": a particle at " << str(p.x) << ", " << distance
        << " m from the emitter's centre, " << input(spec, 11, kEmitted)
        << hint("x = spec.position + rng.inDisc(spec.radius): inside the disc, not the square");
  }
}

TEST(Task5Particles, EmittedPositionsAreUniformOverTheDisc) {
  const EmitterSpec spec = emitterSpec();
  // Four times the usual sample: a radius drawn uniformly must miss by ten times the tolerance.
  const int count = 4 * kEmitted;
  const auto r = emit(spec, 12, count);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), static_cast<std::size_t>(count));
  const double n = count, radius = spec.radius;
  const std::string in = input(spec, 12, count);
  const std::string advice =
      "x = spec.position + rng.inDisc(spec.radius); a radius drawn uniformly in [0, r] crowds the "
      "centre (uniform over the area needs r sqrt(u))";
  // Offsets from the centre: each coordinate has mean 0 and variance r²/4.
  const auto dx =
      collect(r.particles, [&](const Particle& p) { return p.x.x() - spec.position.x(); });
  const auto dy =
      collect(r.particles, [&](const Particle& p) { return p.x.y() - spec.position.y(); });
  EXPECT_CLOSE(mean(dx), 0.0, modelError(6 * radius / 2 / std::sqrt(n), radius))
      << "mean x offset from the centre, " << in << hint(advice);
  EXPECT_CLOSE(mean(dy), 0.0, modelError(6 * radius / 2 / std::sqrt(n), radius))
      << "mean y offset from the centre, " << in << hint(advice);
  // Uniform over the area: u = |d|²/r² is uniform on [0, 1], so half the particles lie within
  // r / sqrt(2) and the quadrants hold a quarter each.
  std::vector<double> u;
  double inner = 0;
  double quadrant[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < dx.size(); ++k) {
    u.push_back((dx[k] * dx[k] + dy[k] * dy[k]) / (radius * radius));
    if (u.back() <= 0.5) inner += 1;
    quadrant[(dx[k] >= 0 ? 0 : 1) + (dy[k] >= 0 ? 0 : 2)] += 1;
  }
  EXPECT_CLOSE(inner / n, 0.5, modelError(6 * 0.5 / std::sqrt(n), 1))
      << "fraction of the particles within r/sqrt(2) of the centre, " << in << hint(advice);
  EXPECT_CLOSE(mean(u), 0.5, modelError(6 * std::sqrt(1.0 / 12 / n), 1))
      << "mean of |x - centre|² / r², " << in << hint(advice);
  EXPECT_GT(*std::max_element(u.begin(), u.end()), 0.99)
      << currentTask() << ": no particle near the rim of the disc, " << in << hint(advice);
  const char* const names[4] = {"x>0, y>0", "x<0, y>0", "x>0, y<0", "x<0, y<0"};
  for (int q = 0; q < 4; ++q) {
    EXPECT_CLOSE(quadrant[q] / n, 0.25, modelError(6 * std::sqrt(0.25 * 0.75 / n), 1))
        << "fraction of the particles in the quadrant " << names[q] << " around the centre, " << in
        << hint("the disc must be filled in every direction around spec.position");
  }
}

TEST(Task5Particles, EmittedVelocitiesSpreadUniformlyAroundTheMean) {
  const EmitterSpec spec = emitterSpec();
  const auto r = emit(spec, 13);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), static_cast<std::size_t>(kEmitted));
  const double s = spec.velocitySpread;
  const std::string in = input(spec, 13, kEmitted);
  const std::string advice =
      "v = spec.velocity + (rng.uniform(-s, s), rng.uniform(-s, s)) with s = velocitySpread, a "
      "separate draw per component";
  const auto vx = collect(r.particles, [](const Particle& p) { return p.v.x(); });
  const auto vy = collect(r.particles, [](const Particle& p) { return p.v.y(); });
  expectUniform(vx, spec.velocity.x() - s, spec.velocity.x() + s, "x velocities", in, advice);
  expectUniform(vy, spec.velocity.y() - s, spec.velocity.y() + s, "y velocities", in, advice);
}

TEST(Task5Particles, EmittedTemperaturesAreUniformInTheirRange) {
  const EmitterSpec spec = emitterSpec();
  const auto r = emit(spec, 14);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), static_cast<std::size_t>(kEmitted));
  expectUniform(collect(r.particles, [](const Particle& p) { return p.temperature; }),
                spec.temperatureMin, spec.temperatureMax, "temperatures", input(spec, 14, kEmitted),
                "temperature = rng.uniform(spec.temperatureMin, spec.temperatureMax)");
}

TEST(Task5Particles, EmittedLifetimesAreUniformInTheirRange) {
  const EmitterSpec spec = emitterSpec();
  const auto r = emit(spec, 15);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), static_cast<std::size_t>(kEmitted));
  expectUniform(collect(r.particles, [](const Particle& p) { return p.lifetime; }),
                spec.lifetimeMin, spec.lifetimeMax, "lifetimes", input(spec, 15, kEmitted),
                "lifetime = rng.uniform(spec.lifetimeMin, spec.lifetimeMax)");
}

TEST(Task5Particles, EmittedQuantitiesAreDrawnIndependently) {
  const EmitterSpec spec = emitterSpec();
  const auto r = emit(spec, 16);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), static_cast<std::size_t>(kEmitted));
  const std::string in = input(spec, 16, kEmitted);
  // Independent draws have correlation 0, with standard error 1/sqrt(n).
  const double tol = 6 / std::sqrt(static_cast<double>(kEmitted));
  const auto get = [&](auto f) { return collect(r.particles, f); };
  const auto x = get([](const Particle& p) { return p.x.x(); });
  const auto vx = get([](const Particle& p) { return p.v.x(); });
  const auto vy = get([](const Particle& p) { return p.v.y(); });
  const auto temperature = get([](const Particle& p) { return p.temperature; });
  const auto lifetime = get([](const Particle& p) { return p.lifetime; });
  for (const auto* xs : {&x, &vx, &vy, &temperature, &lifetime}) {
    ASSERT_GT(variance(*xs), 0.0) << currentTask() << ": one of x, v.x, v.y, temperature, lifetime "
                                  << "is the same for every particle, " << in
                                  << hint(
                                         "draw each of them from rng; see the other emitter tests");
  }
  EXPECT_CLOSE(correlation(vx, vy), 0.0, modelError(tol, 1))
      << "correlation of the x and y velocities, " << in
      << hint("draw a new random number for each velocity component");
  EXPECT_CLOSE(correlation(temperature, lifetime), 0.0, modelError(tol, 1))
      << "correlation of temperature and lifetime, " << in
      << hint("draw a new random number for the temperature and for the lifetime");
  EXPECT_CLOSE(correlation(x, vx), 0.0, modelError(tol, 1))
      << "correlation of the x position and the x velocity, " << in
      << hint("position and velocity need random numbers of their own");
  EXPECT_CLOSE(correlation(vy, temperature), 0.0, modelError(tol, 1))
      << "correlation of the y velocity and the temperature, " << in
      << hint("velocity and temperature need random numbers of their own");
}

TEST(Task5Particles, EmittedParticlesHaveTheSpecMassAndAgeZero) {
  EmitterSpec spec = emitterSpec();
  spec.mass = 0.0037;
  // Collapsed ranges: every draw must give exactly the one value.
  spec.velocitySpread = 0;
  spec.temperatureMin = spec.temperatureMax = 750;
  spec.lifetimeMin = spec.lifetimeMax = 2.5;
  const auto r = emit(spec, 17, 50);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.particles.size(), 50u);
  const std::string in = input(spec, 17, 50);
  const int before = failures();
  for (const Particle& p : r.particles) {
    if (failures() > before) break;
    EXPECT_CLOSE(p.m, 0.0037, relativeTo(0.0037)) << "mass, " << in << hint("m = spec.mass");
    EXPECT_CLOSE(p.age, 0.0, relativeTo(p.lifetime, 0))
        << "age, " << in << hint("a new particle has age 0");
    EXPECT_VEC_NEAR(p.v, spec.velocity, relativeTo(spec.velocity.norm()))
        << "velocity with velocitySpread = 0, " << in
        << hint("v = spec.velocity + the offset in [-s, s]");
    EXPECT_CLOSE(p.temperature, 750, relativeTo(750))
        << "temperature with temperatureMin = temperatureMax = 750, " << in
        << hint("temperature = rng.uniform(spec.temperatureMin, spec.temperatureMax)");
    EXPECT_CLOSE(p.lifetime, 2.5, relativeTo(2.5))
        << "lifetime with lifetimeMin = lifetimeMax = 2.5, " << in
        << hint("lifetime = rng.uniform(spec.lifetimeMin, spec.lifetimeMax)");
    EXPECT_FALSE(p.pinned) << currentTask() << ": an emitted particle is pinned, " << in
                           << hint("particles of a particle system are free");
  }
}

TEST(Task5Particles, TheSeedDecidesTheParticles) {
  const EmitterSpec spec = emitterSpec();
  const auto a = emit(spec, 21, 200), again = emit(spec, 21, 200), b = emit(spec, 22, 200);
  A6_ASSERT_RAN(a);
  A6_ASSERT_RAN(again);
  A6_ASSERT_RAN(b);
  ASSERT_EQ(a.particles.size(), 200u);
  ASSERT_EQ(again.particles.size(), 200u);
  ASSERT_EQ(b.particles.size(), 200u);
  int same = 0, differ = 0;
  for (std::size_t k = 0; k < 200; ++k) {
    const Particle &p = a.particles[k], &q = again.particles[k];
    same += p.x == q.x && p.v == q.v && p.temperature == q.temperature && p.lifetime == q.lifetime;
    differ += a.particles[k].x != b.particles[k].x;
  }
  EXPECT_EQ(same, 200) << currentTask() << ": the same seed gave different particles, "
                       << input(spec, 21, 200)
                       << hint(
                              "draw every random number from rng (never std::rand, time or a "
                              "static generator): the seed must decide the whole run");
  EXPECT_GE(differ, 190)
      << currentTask() << ": seeds 21 and 22 gave the same positions, " << input(spec, 21, 200)
      << hint("draw the position from rng: x = spec.position + rng.inDisc(spec.radius)");
}

// ----------------------------------------------------------------------------------------------
// The update
// ----------------------------------------------------------------------------------------------

// A run without emission, without forces but gravity, on the 1/64 s step.
harness::ParticleRunRequest run(std::vector<Particle> initial, int steps) {
  harness::ParticleRunRequest r;
  r.emitter = emitterSpec();
  r.emitter.rate = 0;
  r.env = Environment{};
  r.env.gravity = Vec2(0, -9.81);
  r.coolingRate = 1;
  r.seed = 5;
  r.initial = std::move(initial);
  r.dt = kDt;
  r.steps = steps;
  r.referenceForces = true;
  return r;
}

Particle particle(Vec2 x, Vec2 v, double m, double temperature = 293.15, double lifetime = kInf) {
  Particle p;
  p.x = x;
  p.v = v;
  p.m = m;
  p.temperature = temperature;
  p.lifetime = lifetime;
  return p;
}

std::string input(const harness::ParticleRunRequest& r) {
  std::ostringstream out;
  out << "  input: " << r.steps << " update(dt = " << num(r.dt) << ") with emitter rate "
      << r.emitter.rate << ", gravity " << str(r.env.gravity) << ", buoyancy "
      << num(r.env.buoyancy) << ", drag " << num(r.env.drag) << ", T_air "
      << num(r.env.airTemperature) << ", coolingRate " << num(r.coolingRate);
  if (!r.env.planes.empty()) out << ", a floor y >= 0 with repulsion " << num(r.env.repulsion);
  out << ", " << r.initial.size() << " initial particles";
  for (std::size_t k = 0; k < r.initial.size() && k < 3; ++k) {
    out << (k ? ", " : ": ") << str(r.initial[k]) << " T=" << r.initial[k].temperature
        << " age=" << r.initial[k].age << " lifetime=" << r.initial[k].lifetime;
  }
  return out.str();
}

harness::ParticlesResult simulate(const harness::ParticleRunRequest& r) { return student().ask(r); }

TEST(Task5Particles, EmitsRateTimesDtParticlesPerStep) {
  auto r = run({}, 12);
  r.emitter.rate = 128;  // 128 * (1/64) = 2 per step, exactly
  r.emitter.lifetimeMin = 100, r.emitter.lifetimeMax = 200;
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  std::vector<int> expected;
  for (int k = 1; k <= 12; ++k) expected.push_back(2 * k);
  EXPECT_EQ(result.counts, expected)
      << currentTask() << ": live particles after each step, " << input(r)
      << hint(
             "each update emits emissionCount(dt) particles with emitParticle(emitter, rng) "
             "and pushes them onto `particles`");
}

TEST(Task5Particles, CarriesFractionalEmissionsOver) {
  for (double rate : {96.0, 40.0}) {  // 1.5 and 0.625 per step, exact in binary
    auto r = run({}, 16);
    r.emitter.rate = rate;
    r.emitter.lifetimeMin = 100, r.emitter.lifetimeMax = 200;
    const auto result = simulate(r);
    A6_ASSERT_RAN(result);
    std::vector<int> expected;
    for (int k = 1; k <= 16; ++k) expected.push_back(static_cast<int>(std::floor(rate * k * kDt)));
    EXPECT_EQ(result.counts, expected)
        << currentTask() << ": live particles after each step (floor(rate k dt)), " << input(r)
        << hint(
               "call emissionCount(dt) once per update: it carries the fraction of a particle "
               "over to the next step; (int)(rate * dt) loses it");
  }
}

// The slide's update emits first, then moves, cools and ages every particle: a particle born in
// an update is dt old after it (one emitted after the loop would still be 0 s old).
TEST(Task5Particles, ANewParticleIsAgedInItsFirstUpdate) {
  auto r = run({}, 1);
  r.emitter.rate = 64;  // one particle in the step of 1/64 s
  r.emitter.lifetimeMin = 100, r.emitter.lifetimeMax = 200;
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 1u)
      << currentTask() << ": live particles after one update, " << input(r)
      << hint("each update emits emissionCount(dt) particles and pushes them onto `particles`");
  EXPECT_CLOSE(result.particles[0].age, kDt, relativeTo(kDt))
      << currentTask() << ": the age of the particle born in this update, after it, " << input(r)
      << hint(
             "emit first, then move, cool and age every particle, the new ones too: a particle "
             "born in an update is dt old after it");
}

TEST(Task5Particles, OneStepIsSymplecticEuler) {
  const Vec2 x0(0.5, 2.0), v0(1.5, -0.25);
  auto r = run({particle(x0, v0, 2.5)}, 1);
  r.env.gravity = Vec2(0.75, -9.81);
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 1u)
      << currentTask() << ": " << input(r) << hint("a particle with an infinite lifetime stays");
  // By hand, h = 1/64: v1 = v0 + (m g / m) h = (1.5 + 0.75/64, -0.25 - 9.81/64)
  // = (1.51171875, -0.40328125); x1 = x0 + v1 h = (0.5 + 1.51171875/64, 2 - 0.40328125/64)
  // = (0.52362060546875, 1.99369873046875).
  const Vec2 v1(1.51171875, -0.40328125), x1(0.52362060546875, 1.99369873046875);
  EXPECT_VEC_NEAR(result.particles[0].v, v1, relativeTo(v0.norm() + 9.84 * kDt))
      << input(r)
      << hint("v += f / m * dt with f = externalForce(p) (here m g): divide by the mass");
  EXPECT_VEC_NEAR(result.particles[0].x, x1, relativeTo(x0.norm() + v1.norm() * kDt))
      << input(r)
      << hint("symplectic Euler: update v first, then x += v * dt with the NEW velocity");
}

TEST(Task5Particles, FreeFallMatchesTheDiscreteSum) {
  const Vec2 x0(-1.0, 3.0), v0(0.5, 2.0);
  const int steps = 40;
  const auto r = run({particle(x0, v0, 0.2)}, steps);
  const Vec2 g = r.env.gravity;
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 1u)
      << currentTask() << ": " << input(r) << hint("a particle with an infinite lifetime stays");
  // Symplectic Euler: x_n = x0 + v0 t + g t (t + h) / 2 (explicit Euler gives t (t - h)).
  const double t = steps * kDt;
  EXPECT_VEC_NEAR(result.particles[0].x, x0 + v0 * t + g * t * (t + kDt) / 2,
                  relativeTo(x0.norm() + v0.norm() * t + g.norm() * t * t, kManySteps))
      << input(r)
      << hint("x_n = x0 + v0 t + g t (t + h)/2 is symplectic Euler: velocity first, then position");
  EXPECT_VEC_NEAR(result.particles[0].v, v0 + g * t,
                  relativeTo(v0.norm() + g.norm() * t, kManySteps))
      << input(r) << hint("v_n = v0 + g t");
}

TEST(Task5Particles, HotParticlesRiseAndColdOnesSink) {
  const int steps = 30;
  const double t = steps * kDt, m = 0.001, b = 5e-5, air = 293.15;
  auto r = run({particle(Vec2(0, 0), Vec2(0, 0), m, air + 600),
                particle(Vec2(1, 0), Vec2(0, 0), m, air - 100)},
               steps);
  r.env.buoyancy = b;
  r.env.airTemperature = air;
  r.coolingRate = 0;  // constant temperatures: constant accelerations
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 2u)
      << currentTask() << ": " << input(r) << hint("particles with an infinite lifetime stay");
  // a = g + b (T - T_air) / m, by hand: hot 5e-5 * 600 / 0.001 - 9.81 = 20.19 up, cold
  // 5e-5 * (-100) / 0.001 - 9.81 = -14.81.
  const Vec2 accelerations[] = {Vec2(0, 20.19), Vec2(0, -14.81)};
  for (int k = 0; k < 2; ++k) {
    const double dT = r.initial[k].temperature - air;
    const Vec2 a = accelerations[k];
    const Particle& p = result.particles[k];
    EXPECT_VEC_NEAR(p.x, r.initial[k].x + a * t * (t + kDt) / 2,
                    relativeTo(r.initial[k].x.norm() + a.norm() * t * t, kManySteps))
        << "the " << (k == 0 ? "hot" : "cold") << " particle (T - T_air = " << num(dT)
        << " K, m = " << num(m) << " kg, b = " << num(b) << " N/K), " << input(r)
        << hint(
               "the force is externalForce(p) (gravity + buoyancy + drag + collisions), divided "
               "by the mass: a hot particle's buoyancy beats its weight and it rises");
  }
  EXPECT_GT(result.particles[0].x.y(), 0.0)
      << currentTask() << ": the hot particle did not rise, " << input(r);
  EXPECT_LT(result.particles[1].x.y(), 0.0)
      << currentTask() << ": the cold particle did not sink, " << input(r);
}

TEST(Task5Particles, DragReachesTerminalVelocity) {
  const double m = 0.01, kd = 0.05;
  auto r = run({particle(Vec2(0, 10), Vec2(2, 0), m)}, 192);  // 3 s = 15 time constants m/k_d
  r.env.drag = kd;
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 1u)
      << currentTask() << ": " << input(r) << hint("a particle with an infinite lifetime stays");
  // Terminal velocity m g / k_d = (0, -1.962) m/s; the step converges to it like (1 - k_d h/m)^n.
  EXPECT_VEC_NEAR(result.particles[0].v, m * r.env.gravity / kd,
                  modelError(1e-4, m * r.env.gravity.norm() / kd))
      << "velocity after 3 s (m = " << num(m) << " kg, k_d = " << num(kd) << " N·s/m), " << input(r)
      << hint("with drag the velocity settles at m g / k_d: the force comes from externalForce(p)");
}

// The temperature after one step must lie between the exact exponential and explicit Euler, or
// as close to the exponential on the other side (implicit Euler lands there).
// `euler` and `exact`: the two bounds, computed by hand.
void expectOneCoolingStep(double T0, double euler, double exact) {
  const double air = 293.15, kc = 3;
  auto r = run({particle(Vec2(0, 0), Vec2(0, 0), 1, T0)}, 1);
  r.env.airTemperature = air;
  r.coolingRate = kc;
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 1u)
      << currentTask() << ": " << input(r) << hint("a particle with an infinite lifetime stays");
  EXPECT_CLOSE(
      result.particles[0].temperature, exact,
      modelError(std::abs(exact - euler) * (1 + kOneComputation) + kOneComputation * T0, T0))
      << "temperature after one step (explicit Euler gives " << num(euler) << "), " << input(r)
      << hint(
             "cool towards the air: T += -coolingRate * (T - T_air) * dt (or the exact "
             "exponential T_air + (T - T_air) exp(-coolingRate dt))");
}

TEST(Task5Particles, OneCoolingStepFollowsNewtonsLaw) {
  // By hand, h = 1/64, k_c = 3, T_air = 293.15: explicit Euler T0 - 3 (T0 - 293.15) / 64, the
  // exact exponential 293.15 + (T0 - 293.15) exp(-3/64), exp(-3/64) = 0.954206...
  expectOneCoolingStep(900, 871.55390625, 872.210315243402);    // hot: cools
  expectOneCoolingStep(250, 252.02265625, 251.97598236342952);  // cold: warms up
}

TEST(Task5Particles, CoolingApproachesTheAirWithoutOvershoot) {
  const double air = 293.15, kc = 2;
  const std::vector<double> T0 = {900, 200};
  std::vector<double> previous = T0;
  for (int steps = 1; steps <= 160; ++steps) {
    auto r = run(
        {particle(Vec2(0, 0), Vec2(0, 0), 1, T0[0]), particle(Vec2(1, 0), Vec2(0, 0), 1, T0[1])},
        steps);
    r.env.gravity = Vec2(0, 0);
    r.env.airTemperature = air;
    r.coolingRate = kc;
    const auto result = simulate(r);
    A6_ASSERT_RAN(result);
    ASSERT_EQ(result.particles.size(), 2u)
        << currentTask() << ": " << input(r) << hint("particles with an infinite lifetime stay");
    for (int k = 0; k < 2; ++k) {
      const double T = result.particles[k].temperature;
      const double side = T0[k] > air ? 1 : -1;  // which side of T_air the particle starts on
      ASSERT_TRUE(side * (T - air) > 0 && side * (previous[k] - T) > 0)
          << currentTask() << ": after " << steps << " steps the particle that started at "
          << num(T0[k]) << " K is at " << num(T) << " K (the step before: " << num(previous[k])
          << " K), T_air " << num(air) << " K\n  " << input(r)
          << hint(
                 "every step must bring T closer to T_air without passing it: "
                 "T += -coolingRate * (T - T_air) * dt, subtracting the air temperature");
      previous[k] = T;
    }
    if (steps == 160) {  // 2.5 s = 5 time constants: e^-5 < 0.7% of the start difference left
      for (int k = 0; k < 2; ++k) {
        EXPECT_CLOSE(result.particles[k].temperature, air,
                     modelError(0.01 * std::abs(T0[k] - air), std::abs(T0[k] - air)))
            << "temperature after 2.5 s (coolingRate " << num(kc) << "/s) from " << num(T0[k])
            << " K, " << input(r) << hint("T approaches T_air like exp(-coolingRate t)");
      }
    }
  }
}

TEST(Task5Particles, AgeGrowsByDtEveryStep) {
  Particle young = particle(Vec2(0, 0), Vec2(0, 0), 1), old = particle(Vec2(1, 0), Vec2(0, 0), 1);
  old.age = 0.25;
  const auto r = run({young, old}, 7);
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.particles.size(), 2u)
      << currentTask() << ": " << input(r) << hint("particles with an infinite lifetime stay");
  EXPECT_CLOSE(result.particles[0].age, 7 * kDt, relativeTo(7 * kDt))
      << "age after 7 steps, from age 0, " << input(r) << hint("age += dt in every update");
  EXPECT_CLOSE(result.particles[1].age, 0.25 + 7 * kDt, relativeTo(0.25 + 7 * kDt))
      << "age after 7 steps, from age 0.25, " << input(r) << hint("age += dt in every update");
}

TEST(Task5Particles, ParticlesDieWhenTheirAgeReachesTheirLifetime) {
  // Lifetimes 1, 2, 2.5, 3, 5 steps and forever; ages are exact multiples of 1/64 s.
  std::vector<Particle> initial;
  for (double steps : {1.0, 2.0, 2.5, 3.0, 5.0}) {
    initial.push_back(particle(Vec2(steps, 0), Vec2(0, 0), 1, 293.15, steps * kDt));
  }
  initial.push_back(particle(Vec2(9, 0), Vec2(0, 0), 1));
  const auto r = run(initial, 8);
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  const std::vector<int> expected = {5, 4, 2, 2, 1, 1, 1, 1};
  EXPECT_EQ(result.counts, expected)
      << currentTask() << ": live particles after each step of dt = 1/64 s; lifetimes 1, 2, 2.5, "
      << "3, 5 steps and infinity, all of age 0 at the start\n  " << input(r)
      << hint(
             "after age += dt, remove every particle with age >= lifetime (>=, not >), "
             "e.g. with std::remove_if and erase");
  ASSERT_EQ(result.particles.size(), 1u);
  EXPECT_TRUE(std::isinf(result.particles[0].lifetime))
      << currentTask() << ": the survivor has lifetime " << result.particles[0].lifetime
      << hint("remove the particles that died, keep the others: erase the right ones");
}

TEST(Task5Particles, AParticleWithInfiniteLifetimeLivesForever) {
  const int steps = 2000;
  const auto r = run({particle(Vec2(0, 0), Vec2(0, 0), 1)}, steps);
  const auto result = simulate(r);
  A6_ASSERT_RAN(result);
  ASSERT_EQ(result.counts.size(), static_cast<std::size_t>(steps));
  EXPECT_EQ(*std::min_element(result.counts.begin(), result.counts.end()), 1)
      << currentTask() << ": the particle with lifetime infinity was removed, " << input(r)
      << hint("remove a particle only when age >= lifetime");
  ASSERT_EQ(result.particles.size(), 1u);
  EXPECT_CLOSE(result.particles[0].age, steps * kDt, relativeTo(steps * kDt, kManySteps))
      << "age after " << steps << " steps, " << input(r) << hint("age += dt in every update");
}

TEST(Task5Particles, AFloorStopsAFallingParticle) {
  // m = 0.01 kg from 0.5 m onto the floor y = 0 with k_r = 100 N/m: it hits at ~3.1 m/s and
  // sinks at most v sqrt(m/k_r) + m g / k_r ~ 0.032 m before bouncing back.
  const double m = 0.01;
  double lowest = kInf;
  harness::ParticleRunRequest last;
  for (int steps = 8; steps <= 512; steps += 8) {
    auto r = run({particle(Vec2(0, 0.5), Vec2(0, 0), m)}, steps);
    r.dt = 1.0 / 256;
    r.env.repulsion = 100;
    r.env.drag = 0.02;
    r.env.planes.push_back(HalfPlane{Vec2(0, 1), 0});
    const auto result = simulate(r);
    A6_ASSERT_RAN(result);
    ASSERT_EQ(result.particles.size(), 1u)
        << currentTask() << ": " << input(r) << hint("a particle with an infinite lifetime stays");
    lowest = std::min(lowest, result.particles[0].x.y());
    last = r;
  }
  EXPECT_LT(lowest, 0.01) << currentTask() << ": the particle never reached the floor in 2 s, "
                          << input(last)
                          << hint("apply externalForce(p) and integrate every particle");
  EXPECT_GT(lowest, -0.1) << currentTask() << ": the particle sank " << -lowest
                          << " m into the floor (expected at most ~0.032 m), " << input(last)
                          << hint(
                                 "the force must be externalForce(p): it includes the floor's "
                                 "repulsion k_r d n");
}

}  // namespace task5_particles
}  // namespace a6::test
