// Task 3 — MassSpringSystem::step and advance. Oracles: one step computed by hand, the exact
// discrete results of symplectic Euler (free fall, the oscillator's period and its invariant),
// conservation laws, equilibria (terminal velocity, resting contact), stability with substeps.
//
// Every request sets referenceForces, so the forces come from the graders' reference models and
// a bug in task 1 or 2 never fails these tests.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "scales.h"
#include "suite.h"

namespace a6::test {
namespace task3_time_stepping {

using harness::SimulateRequest;
using harness::SimulateResult;
using harness::SpringData;

Particle particle(Vec2 x, Vec2 v = Vec2::Zero(), double m = 1.0, bool pinned = false) {
  Particle p;
  p.x = x;
  p.v = v;
  p.m = m;
  p.pinned = pinned;
  return p;
}

SpringData spring(int i, int j, double restLength, double ks, double kd = 0) {
  SpringData s;
  s.i = i;
  s.j = j;
  s.restLength = restLength;
  s.ks = ks;
  s.kd = kd;
  return s;
}

// A request with no forces at all: tests switch on what they need.
SimulateRequest request(std::vector<Particle> particles, std::vector<SpringData> springs,
                        double frameDt, int frames) {
  SimulateRequest r;
  r.particles = std::move(particles);
  r.springs = std::move(springs);
  r.env.gravity = Vec2::Zero();
  r.env.drag = 0;
  r.env.buoyancy = 0;
  r.env.repulsion = 0;
  r.frameDt = frameDt;
  r.frames = frames;
  r.substeps = 1;
  r.recordEvery = 1;
  r.referenceForces = true;
  return r;
}

std::string input(const SimulateRequest& r) {
  std::ostringstream out;
  out << "  input: " << r.particles.size() << " particle(s)";
  const std::size_t shown = std::min<std::size_t>(r.particles.size(), 3);
  for (std::size_t k = 0; k < shown; ++k) out << (k == 0 ? " " : ", ") << str(r.particles[k]);
  if (shown < r.particles.size()) out << ", ...";
  out << "; " << r.springs.size() << " spring(s)";
  if (!r.springs.empty()) {
    const SpringData& s = r.springs[0];
    out << " (first: " << s.i << "-" << s.j << ", l0=" << num(s.restLength) << ", ks=" << num(s.ks)
        << ", kd=" << num(s.kd) << ")";
  }
  out << "; g=" << str(r.env.gravity) << ", k_d=" << num(r.env.drag)
      << ", k_r=" << num(r.env.repulsion) << "; " << r.frames << " frame(s) of " << num(r.frameDt)
      << " s, "
      << (r.stepOnly ? "step(frameDt) per frame"
                     : "advance(frameDt, " + std::to_string(r.substeps) + ") per frame");
  return out.str();
}

// The student's code ran, recorded `states` states of `particles` particles each.
::testing::AssertionResult recorded(const SimulateResult& result, std::size_t states,
                                    std::size_t particles) {
  if (!result.ok()) {
    return ::testing::AssertionFailure() << currentTask() << ": your code failed: " << result.error;
  }
  if (result.states.size() != states || result.recordedFrames.size() != states) {
    return ::testing::AssertionFailure() << currentTask() << ": expected " << states
                                         << " recorded states, got " << result.states.size();
  }
  for (const auto& state : result.states) {
    if (state.size() != particles) {
      return ::testing::AssertionFailure()
             << currentTask() << ": expected " << particles << " particles, got " << state.size()
             << hint("never add or remove particles in step()");
    }
  }
  return ::testing::AssertionSuccess();
}

// The largest position and speed in a request's initial state (with the rest lengths): the scales
// of its positions and velocities.
double positionScale(const SimulateRequest& r) {
  double scale = 0;
  for (const Particle& p : r.particles) scale = std::max(scale, p.x.norm());
  for (const SpringData& s : r.springs) scale = std::max(scale, s.restLength);
  return scale;
}
double speedScale(const SimulateRequest& r) {
  double scale = 0;
  for (const Particle& p : r.particles) scale = std::max(scale, p.v.norm());
  return scale;
}

// A position or velocity's tolerance: relative to the larger of the expected value and the
// request's own scale. One step is one computation; more steps accumulate rounding.
Tolerance positionTol(const SimulateRequest& r, const Vec2& expected, int steps) {
  return relativeTo(std::max(expected.norm(), positionScale(r)),
                    steps > 1 ? kManySteps : kOneComputation);
}
Tolerance velocityTol(const SimulateRequest& r, const Vec2& expected, int steps) {
  return relativeTo(std::max(expected.norm(), speedScale(r)),
                    steps > 1 ? kManySteps : kOneComputation);
}

// Runs the request and checks that every frame was recorded.
#define A6_SIMULATE(result, req)                                                            \
  const SimulateResult result = student().ask(req);                                         \
  ASSERT_TRUE(recorded(                                                                     \
      result,                                                                               \
      static_cast<std::size_t>(((req).frames + (req).recordEvery - 1) / (req).recordEvery), \
      (req).particles.size()))                                                              \
      << input(req)

// The oscillator used below: a particle of mass m on a spring (ks, rest length 1) to an anchor
// pinned at the origin, pulled out along x by u0, no gravity. omega = sqrt(ks / m).
SimulateRequest oscillator(double ks, double m, double u0, double dt, int frames, double kd = 0) {
  return request(
      {particle(Vec2(0, 0), Vec2::Zero(), 1.0, true), particle(Vec2(1 + u0, 0), Vec2::Zero(), m)},
      {spring(0, 1, 1.0, ks, kd)}, dt, frames);
}

// Stretch of the oscillator's spring, m.
double stretch(const std::vector<Particle>& state) {
  return (state[1].x - state[0].x).norm() - 1.0;
}

// Energy of the oscillator, J: kinetic + spring.
double oscillatorEnergy(const std::vector<Particle>& state, double ks) {
  const double u = stretch(state);
  return 0.5 * state[1].m * state[1].v.squaredNorm() + 0.5 * ks * u * u;
}

// The oscillator's anchor (particle 0) is pinned: it must stay at the origin, at rest.
::testing::AssertionResult anchorHeld(const SimulateResult& result) {
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const Particle& anchor = result.states[k][0];
    if (anchor.x != Vec2::Zero() || anchor.v != Vec2::Zero()) {
      return ::testing::AssertionFailure()
             << currentTask() << ": the pinned anchor moved to " << str(anchor) << " after frame "
             << result.recordedFrames[k]
             << hint("pinned particles never move: skip them when integrating");
    }
  }
  return ::testing::AssertionSuccess();
}

// Linear momentum (kg·m/s) and angular momentum about the origin (kg·m²/s).
// The momenta's scale: the sum of m |v| of the initial state.
// Momenta are conserved exactly (to rounding, which does not accumulate like a position's).
constexpr double kInvariant = 1e-6;
double momentumScale(const harness::SimulateRequest& r) {
  double scale = 0;
  for (const Particle& p : r.particles) scale += p.m * p.v.norm();
  return scale;
}
Vec2 momentum(const std::vector<Particle>& ps) {
  Vec2 P = Vec2::Zero();
  for (const Particle& p : ps) P += p.m * p.v;
  return P;
}
double angularMomentum(const std::vector<Particle>& ps) {
  double L = 0;
  for (const Particle& p : ps) L += p.m * (p.x.x() * p.v.y() - p.x.y() * p.v.x());
  return L;
}

// One step --------------------------------------------------------------------------------------

TEST(Task3TimeStepping, OneStepUpdatesVelocityFirstThenPosition) {
  // m = 2, x0 = (1, 2), v0 = (3, -1), g = (0, -10), k_d = 0.5, h = 0.1:
  //   f  = m g - k_d v0 = (0, -20) - (1.5, -0.5) = (-1.5, -19.5)
  //   v1 = v0 + f/m h   = (3, -1) + (-0.075, -0.975) = (2.925, -1.975)
  //   x1 = x0 + v1 h    = (1.2925, 1.8025)        (with the old v: (1.3, 1.9))
  auto r = request({particle(Vec2(1, 2), Vec2(3, -1), 2.0)}, {}, 0.1, 1);
  r.env.gravity = Vec2(0, -10);
  r.env.drag = 0.5;
  A6_SIMULATE(result, r);
  const Particle& p = result.states[0][0];
  EXPECT_VEC_NEAR(p.v, Vec2(2.925, -1.975), velocityTol(r, Vec2(2.925, -1.975), 1))
      << input(r) << hint("v += f / m dt: divide the force by the mass");
  EXPECT_VEC_NEAR(p.x, Vec2(1.2925, 1.8025), positionTol(r, Vec2(1.2925, 1.8025), 1))
      << input(r)
      << hint(
             "symplectic Euler: first v += f/m dt, THEN x += v dt with the new v "
             "(moving x with the old v is explicit Euler, which is unstable)");
}

TEST(Task3TimeStepping, OneStepOfASpringPushesBothEnds) {
  // p1 = (1, 1), m1 = 2; p2 = (2.2, 2.6), m2 = 0.5; l0 = 1, ks = 10, h = 0.1, no gravity.
  //   d = (1.2, 1.6), l = 2, e = (0.6, 0.8): f2 = -10 (2 - 1) e = (-6, -8), f1 = (6, 8)
  //   v1 = f1/m1 h = (0.3, 0.4),   x1 = (1.03, 1.04)
  //   v2 = f2/m2 h = (-1.2, -1.6), x2 = (2.08, 2.44)
  const auto r = request(
      {particle(Vec2(1, 1), Vec2::Zero(), 2.0), particle(Vec2(2.2, 2.6), Vec2::Zero(), 0.5)},
      {spring(0, 1, 1.0, 10)}, 0.1, 1);
  A6_SIMULATE(result, r);
  const auto& s = result.states[0];
  EXPECT_VEC_NEAR(s[1].v, Vec2(-1.2, -1.6), velocityTol(r, Vec2(-1.2, -1.6), 1))
      << input(r) << hint("p2 gets +springForce(s), and v += f / m dt with p2's own mass");
  EXPECT_VEC_NEAR(s[0].v, Vec2(0.3, 0.4), velocityTol(r, Vec2(-1.2, -1.6), 1))
      << input(r) << hint("p1 gets the opposite force: s.p1->f -= f");
  EXPECT_VEC_NEAR(s[1].x, Vec2(2.08, 2.44), positionTol(r, Vec2(2.08, 2.44), 1))
      << input(r) << hint("x += v dt, with the new v");
  EXPECT_VEC_NEAR(s[0].x, Vec2(1.03, 1.04), positionTol(r, Vec2(2.08, 2.44), 1))
      << input(r) << hint("x += v dt, with the new v");
}

TEST(Task3TimeStepping, WithoutForcesParticlesKeepTheirVelocity) {
  // No springs, no gravity: x(t) = x0 + v0 t, v(t) = v0.
  const Vec2 x0(0.1, 0.2), v0(1.5, -0.5);
  const double h = 0.02;
  auto r = request({particle(x0, v0, 0.25), particle(Vec2(-1, 3), Vec2::Zero(), 4.0)}, {}, h, 100);
  r.recordEvery = 25;
  A6_SIMULATE(result, r);
  ManyInputs moving("positions of the moving particle", kMetre),
      velocities("velocities", kMetrePerSecond),
      resting("positions of the resting particle", kMetre);
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const double t = result.recordedFrames[k] * h;
    const std::string when = "\n  at t = " + num(t) + " s; " + input(r);
    moving.expectNear(result.states[k][0].x, x0 + v0 * t, positionTol(r, x0 + v0 * t, r.frames),
                      when);
    velocities.expectNear(result.states[k][0].v, v0, velocityTol(r, v0, r.frames), when);
    resting.expectNear(result.states[k][1].x, Vec2(-1, 3), positionTol(r, Vec2(-1, 3), r.frames),
                       when);
  }
  moving.report(
      hint("with no force a particle moves in a straight line at constant speed: x += v dt"));
  velocities.report(hint("with no force, v must not change"));
  resting.report(hint("a particle at rest with no force stays put"));
}

// Exact discrete results --------------------------------------------------------------------------

TEST(Task3TimeStepping, FreeFallMatchesTheDiscreteSum) {
  // Symplectic Euler: x_n = x0 + v0 t_n + g t_n (t_n + h) / 2, v_n = v0 + g t_n, exactly.
  const Vec2 x0(0.5, 10), v0(2, 3), g(0, -9.81);
  const double h = 0.01;
  auto r = request({particle(x0, v0, 0.3)}, {}, h, 200);
  r.env.gravity = g;
  r.recordEvery = 20;
  A6_SIMULATE(result, r);
  ManyInputs velocities("velocities", kMetrePerSecond), positions("positions", kMetre);
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const double t = result.recordedFrames[k] * h;
    const Particle& p = result.states[k][0];
    const std::string when =
        "\n  after " + std::to_string(result.recordedFrames[k]) + " steps; " + input(r);
    const Vec2 x = x0 + v0 * t + g * (t * (t + h) / 2);
    velocities.expectNear(p.v, v0 + g * t, velocityTol(r, v0 + g * t, r.frames), when);
    positions.expectNear(p.x, x, positionTol(r, x, r.frames), when);
  }
  velocities.report(hint("v += f / m dt with f = m g: the velocity grows by g dt per step"));
  positions.report(
      hint("symplectic Euler gives g t (t + h) / 2; g t (t - h) / 2 means x moved "
           "with the old velocity (explicit Euler): update v first, then x"));
}

TEST(Task3TimeStepping, OscillatorPeriodMatchesTheDiscreteFormula) {
  // omega = sqrt(50 / 0.5) = 10 rad/s, h = 0.01 s: T_h = 2 pi h / arccos(1 - (omega h)^2 / 2).
  const double ks = 50, m = 0.5, h = 0.01, omega = std::sqrt(ks / m);
  const double expected = 2 * M_PI * h / std::acos(1 - omega * h * omega * h / 2);
  const auto r = oscillator(ks, m, 0.2, h, 290);
  A6_SIMULATE(result, r);
  ASSERT_TRUE(anchorHeld(result)) << input(r);

  // Downward zero crossings of the stretch, linearly interpolated between frames.
  std::vector<double> crossings;
  double uPrev = stretch(r.particles);
  double tPrev = 0;
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const double u = stretch(result.states[k]);
    const double t = result.recordedFrames[k] * h;
    if (uPrev > 0 && u <= 0) crossings.push_back(tPrev + (t - tPrev) * uPrev / (uPrev - u));
    uPrev = u;
    tPrev = t;
  }
  ASSERT_GE(crossings.size(), 3u) << currentTask() << ": the mass crossed its rest position "
                                  << crossings.size() << " time(s) in " << num(r.frames * h)
                                  << " s; expected about 4 oscillations of " << num(expected)
                                  << " s; " << input(r)
                                  << hint("the spring should make the particle oscillate");
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  EXPECT_CLOSE(period, expected, modelError(h, expected))
      << "(period in s, from " << crossings.size()
      << " zero crossings; continuous 2 pi/omega = " << 2 * M_PI / omega << ") " << input(r)
      << hint(
             "a mass m on a spring ks oscillates with omega = sqrt(ks / m): check v += f / m dt "
             "and that each step advances by exactly dt");
}

TEST(Task3TimeStepping, UndampedEnergyStaysBounded) {
  // omega h = 0.1 for about 20 periods. Symplectic Euler's energy wobbles by about omega h / 2
  // (5 %) and never drifts; explicit Euler's grows by (1 + (omega h)^2) per step.
  const double ks = 50, m = 0.5, h = 0.01;
  auto r = oscillator(ks, m, 0.2, h, 1260);
  r.recordEvery = 5;
  A6_SIMULATE(result, r);
  ASSERT_TRUE(anchorHeld(result)) << input(r);
  const double e0 = 0.5 * ks * 0.2 * 0.2;
  double lowest = e0, highest = e0, lowestStretch = 0.2;
  for (const auto& state : result.states) {
    const double e = oscillatorEnergy(state, ks);
    lowest = std::isfinite(e) ? std::min(lowest, e) : -1;
    highest = std::isfinite(e) ? std::max(highest, e) : INFINITY;
    lowestStretch = std::min(lowestStretch, stretch(state));
  }
  ASSERT_LT(lowestStretch, -0.1) << currentTask() << ": the mass never swung past its rest length; "
                                 << input(r)
                                 << hint("the spring should make the particle oscillate");
  EXPECT_LE(highest, 1.08 * e0)
      << currentTask() << ": the energy (J) grew from " << num(e0) << " to " << num(highest) << "; "
      << input(r)
      << hint(
             "growing energy is the signature of explicit Euler: update v first, "
             "then x with the NEW v");
  EXPECT_GE(lowest, 0.92 * e0)
      << currentTask() << ": the energy (J) fell from " << num(e0) << " to " << num(lowest)
      << " without any damping; " << input(r)
      << hint("with no damping the energy must not decay: v += f/m dt, x += v dt, nothing more");
}

TEST(Task3TimeStepping, DampedEnergyDecreases) {
  // The same oscillator with kd = 0.5 (damping ratio 0.05): the energy shrinks every period.
  const double ks = 50, m = 0.5, h = 0.01, kd = 0.5;
  auto r = oscillator(ks, m, 0.2, h, 252, kd);
  r.recordEvery = 63;  // about one period
  A6_SIMULATE(result, r);
  ASSERT_TRUE(anchorHeld(result)) << input(r);
  double previous = 0.5 * ks * 0.2 * 0.2;
  const double e0 = previous;
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const double e = oscillatorEnergy(result.states[k], ks);
    EXPECT_LT(e, previous) << currentTask() << ": energy (J) " << num(e)
                           << " at t = " << result.recordedFrames[k] * h << " s, one period after "
                           << num(previous) << "; " << input(r)
                           << hint("a damped spring must lose energy: check the integration order");
    previous = std::isfinite(e) ? e : INFINITY;
    if (HasFailure()) break;  // the first failure says enough
  }
  EXPECT_LT(previous, 0.5 * e0) << currentTask() << ": after " << num(r.frames * h)
                                << " s the energy " << num(previous)
                                << " J is not below half of the initial " << num(e0) << " J; "
                                << input(r);
}

// Conservation ----------------------------------------------------------------------------------

TEST(Task3TimeStepping, TwoParticlesOnASpringKeepTheirMomentum) {
  // Spring forces are internal: p2 gets +f, p1 gets -f, so total momentum never changes and the
  // centre of mass moves in a straight line: x_cm(t) = x_cm(0) + P / M t (exact for symplectic
  // Euler).
  const double h = 0.01;
  auto r = request(
      {particle(Vec2(0, 0), Vec2(0.5, -0.2), 1.0), particle(Vec2(1.5, 0.5), Vec2(-0.1, 0.4), 3.0)},
      {spring(0, 1, 1.0, 30, 0.4)}, h, 300);
  r.recordEvery = 10;
  A6_SIMULATE(result, r);
  const Vec2 P0 = momentum(r.particles);
  const double M = 4.0;
  const Vec2 cm0 = (1.0 * r.particles[0].x + 3.0 * r.particles[1].x) / M;
  bool moved = false;
  ManyInputs momenta("momenta (m1 v1 + m2 v2)", kMomentum), centres("centres of mass", kMetre);
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const auto& s = result.states[k];
    const double t = result.recordedFrames[k] * h;
    const std::string when = "\n  at t = " + num(t) + " s; " + input(r);
    // Rounding grows with the values summed: the scales include the state's own sizes.
    const double speeds = 1.0 * s[0].v.norm() + 3.0 * s[1].v.norm();
    const double extent = std::max(s[0].x.norm(), s[1].x.norm());
    momenta.expectNear(momentum(s), P0, relativeTo(std::max(momentumScale(r), speeds), kInvariant),
                       when);
    centres.expectNear((1.0 * s[0].x + 3.0 * s[1].x) / M, cm0 + P0 / M * t,
                       relativeTo(std::max(positionScale(r), extent), kManySteps), when);
  }
  momenta.report(
      hint("add the spring force to p2 and SUBTRACT it from p1 (s.p2->f += f; s.p1->f -= f)"));
  centres.report(
      hint("the spring's two forces must cancel, and each particle moves with its own mass"));
  for (const auto& s : result.states) moved = moved || (s[1].v - r.particles[1].v).norm() > 1e-2;
  EXPECT_TRUE(moved) << currentTask() << ": the stretched spring never changed p2's velocity; "
                     << input(r) << hint("step() must apply the spring forces and integrate");
}

TEST(Task3TimeStepping, SpringsConserveLinearAndAngularMomentum) {
  // Five particles, seven damped springs, no gravity: sum m v and sum m x × v stay constant to
  // round-off (spring forces are internal and central), through advance() with four substeps.
  const std::vector<Particle> ps = {
      particle(Vec2(0, 0), Vec2(0.3, -0.2), 1.0), particle(Vec2(1, 0.2), Vec2(-0.4, 0.1), 0.5),
      particle(Vec2(0.4, 1), Vec2(0.2, 0.5), 2.0), particle(Vec2(-0.6, 0.7), Vec2(0, -0.3), 0.8),
      particle(Vec2(1.3, 1.1), Vec2(-0.2, 0.2), 1.5)};
  const std::vector<SpringData> springs = {spring(0, 1, 0.8, 40, 0.2), spring(1, 2, 1.0, 25, 0.1),
                                           spring(2, 0, 1.3, 30, 0.3), spring(3, 0, 0.7, 20, 0.0),
                                           spring(3, 2, 1.0, 35, 0.2), spring(4, 2, 0.6, 50, 0.1),
                                           spring(1, 4, 1.0, 20, 0.4)};
  auto r = request(ps, springs, 0.02, 100);
  r.substeps = 4;
  r.recordEvery = 5;
  A6_SIMULATE(result, r);
  const Vec2 P0 = momentum(ps);
  const double L0 = angularMomentum(ps);
  double largestChange = 0;
  ManyInputs linear("linear momenta", kMomentum),
      angular("angular momenta about the origin", kAngularMomentum);
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    const auto& s = result.states[k];
    const std::string when =
        "\n  at t = " + num(result.recordedFrames[k] * r.frameDt) + " s; " + input(r);
    linear.expectNear(momentum(s), P0, relativeTo(momentumScale(r), kInvariant), when);
    angular.expectNear(angularMomentum(s), L0,
                       relativeTo(positionScale(r) * momentumScale(r), kInvariant), when);
  }
  linear.report(
      hint("every spring adds +f to p2 and -f to p1, and nothing else changes the forces"));
  angular.report(
      hint("symplectic Euler conserves it exactly: compute all forces first, then for "
           "each particle v += f/m dt and x += v dt with the new v"));
  for (const auto& s : result.states) {
    for (std::size_t i = 0; i < ps.size(); ++i) {
      largestChange = std::max(largestChange, (s[i].v - ps[i].v).norm());
    }
  }
  EXPECT_GT(largestChange, 0.05) << currentTask() << ": no particle's velocity changed; "
                                 << input(r) << hint("step() must apply the spring forces");
}

TEST(Task3TimeStepping, PinnedParticlesNeverMove) {
  // A rope between two pinned ends, under gravity, with stretched springs pulling on the pins,
  // through advance() with three substeps. The pins were given velocities: a pinned particle
  // keeps its x and its v whatever they are, so skipping only the velocity update still shows.
  const std::vector<Particle> ps = {particle(Vec2(0, 0), Vec2(0.6, -0.4), 1.0, true),
                                    particle(Vec2(0.5, -0.3), Vec2(1, 0), 0.2),
                                    particle(Vec2(1.2, -0.5), Vec2::Zero(), 0.2),
                                    particle(Vec2(2, 0), Vec2(-0.3, 0.5), 1.0, true)};
  auto r = request(
      ps, {spring(0, 1, 0.3, 40, 0.2), spring(1, 2, 0.3, 40, 0.2), spring(2, 3, 0.3, 40, 0.2)},
      0.03, 17);
  r.substeps = 3;
  r.env.gravity = Vec2(0, -9.81);
  r.env.drag = 0.1;
  r.recordEvery = 10;
  A6_SIMULATE(result, r);
  for (std::size_t k = 0; k < result.states.size(); ++k) {
    for (const int i : {0, 3}) {
      const Particle& p = result.states[k][i];
      EXPECT_VEC_NEAR(p.x, ps[i].x, relativeTo(positionScale(r), 0))
          << "(pinned particle " << i << ") after frame " << result.recordedFrames[k] << "; "
          << input(r) << hint("skip pinned particles when integrating: if (p.pinned) continue;");
      EXPECT_VEC_NEAR(p.v, ps[i].v, relativeTo(speedScale(r), 0))
          << "(pinned particle " << i << ") after frame " << result.recordedFrames[k] << "; "
          << input(r) << hint("a pinned particle's velocity must not change either");
    }
    if (HasFailure()) break;  // the first failure says enough
  }
  EXPECT_GT((result.states.back()[1].x - ps[1].x).norm(), 1e-2)
      << currentTask() << ": the free particle 1 did not move; " << input(r)
      << hint("only pinned particles stay put");
}

// Equilibria ------------------------------------------------------------------------------------

TEST(Task3TimeStepping, TerminalVelocityIsMgOverKd) {
  // m = 0.2, k_d = 0.5, g = (0, -9.81): v -> (0, -m g / k_d) = (0, -3.924) m/s (time constant
  // m / k_d = 0.4 s; 10 s is 25 time constants).
  auto r = request({particle(Vec2(0, 0), Vec2(1, 0), 0.2)}, {}, 0.01, 1000);
  r.env.gravity = Vec2(0, -9.81);
  r.env.drag = 0.5;
  r.recordEvery = 1000;
  A6_SIMULATE(result, r);
  EXPECT_VEC_NEAR(result.states.back()[0].v, Vec2(0, -0.2 * 9.81 / 0.5),
                  relativeTo(0.2 * 9.81 / 0.5, kManySteps))
      << "after 10 s; " << input(r)
      << hint("gravity and drag balance at v = m g / k_d: the velocity must settle there");
}

TEST(Task3TimeStepping, PenaltyContactRestsAtDepthMgOverKr) {
  // A particle dropped on a floor (y < 0 solid) with k_r = 1000 N/m and drag: at rest,
  // k_r d = m g, so it sinks to d = 0.1 * 9.81 / 1000 = 9.81e-4 m.
  auto r = request({particle(Vec2(0.3, 0.01), Vec2::Zero(), 0.1)}, {}, 0.001, 3000);
  r.env.gravity = Vec2(0, -9.81);
  r.env.drag = 2.0;
  r.env.repulsion = 1000;
  r.env.planes.push_back({Vec2(0, 1), 0.0});
  r.recordEvery = 3000;
  A6_SIMULATE(result, r);
  const Particle& p = result.states.back()[0];
  const double depth = 0.1 * 9.81 / 1000;
  EXPECT_VEC_NEAR(p.x, Vec2(0.3, -depth), modelError(1e-3 * depth, depth))
      << "after 3 s; " << input(r)
      << hint("at rest the floor's push k_r d balances the weight m g; check v += f / m dt");
  EXPECT_VEC_NEAR(p.v, Vec2(0, 0), relativeTo(std::sqrt(2 * 9.81 * 0.01), kManySteps))
      << "after 3 s; " << input(r);
}

// What failed when a run with n substeps per frame blew up, from a second run of the same
// request as n calls of step(frameDt / n) per frame (`holds` says whether a state is sound): if
// those hold, advance's loop is to blame; if not, the step itself.
std::string substepHint(const SimulateRequest& r,
                        const std::function<bool(const std::vector<Particle>&)>& holds) {
  SimulateRequest steps = r;
  steps.stepOnly = true;
  steps.frameDt = r.frameDt / r.substeps;
  steps.frames = r.frames * r.substeps;
  steps.recordEvery = steps.frames;
  const SimulateResult stepped = student().ask(steps);
  if (!stepped.ok() || stepped.states.empty()) {
    return hint(
        "advance(frameDt, n) must take n steps of frameDt / n, and each step must be "
        "symplectic Euler (n calls of step(frameDt / n) could not be run to tell which: " +
        (stepped.ok() ? std::string("no state") : stepped.error) + ")");
  }
  if (stepped.ok() && !stepped.states.empty() && holds(stepped.states.back())) {
    return hint(
        "n calls of step(frameDt / n) hold, advance(frameDt, n) does not: advance must "
        "take n steps of frameDt / n (not n steps of frameDt, nor one)");
  }
  return hint(
      "even n calls of step(frameDt / n) blow up, so the step itself is unstable: update "
      "v first, then x with the new v (symplectic Euler), add each spring's force to both "
      "ends, and reset the forces every step");
}

// Stability and substeps ------------------------------------------------------------------------

TEST(Task3TimeStepping, StableJustBelowTheStabilityLimit) {
  // omega h = 1.9 < 2: symplectic Euler keeps u² - a u w + w² constant (a = omega h,
  // w = v / omega), so |u| never exceeds 2 u0 / sqrt(4 - a²) = 3.2 u0.
  const double ks = 50, m = 0.5, omega = 10, a = 1.9, u0 = 0.1;
  const auto r = oscillator(ks, m, u0, a / omega, 300);
  A6_SIMULATE(result, r);
  ASSERT_TRUE(anchorHeld(result)) << input(r);
  const double bound = 2 * u0 / std::sqrt(4 - a * a);
  double largest = 0, smallest = 0;
  for (const auto& state : result.states) {
    const double u = stretch(state);
    largest = std::isfinite(u) ? std::max(largest, std::abs(u)) : INFINITY;
    smallest = std::min(smallest, u);
  }
  EXPECT_LE(largest, bound * 1.001)
      << currentTask() << ": the largest stretch (m) over " << r.frames
      << " steps with omega h = 1.9; " << input(r)
      << hint(
             "symplectic Euler is stable while omega h < 2; explicit Euler (x moved with the "
             "old v) is not: update v first, then x");
  EXPECT_LT(smallest, -0.5 * u0) << currentTask() << ": the mass never swung past its rest length; "
                                 << input(r)
                                 << hint("the spring should make the particle oscillate");
}

TEST(Task3TimeStepping, StiffSpringExplodesWithOneSubstepAndHoldsWithTen) {
  // frameDt = 0.25 s, omega = 10: omega h = 2.5 with 1 substep (unstable), 0.25 with 10.
  const double ks = 50, m = 0.5, u0 = 0.1;
  auto one = oscillator(ks, m, u0, 0.25, 40);
  auto ten = one;
  ten.substeps = 10;
  A6_SIMULATE(exploded, one);
  A6_SIMULATE(held, ten);
  ASSERT_TRUE(anchorHeld(held)) << input(ten);
  const double u1 = stretch(exploded.states.back());
  EXPECT_FALSE(std::isfinite(u1) && std::abs(u1) < 100 * u0)
      << currentTask() << ": with omega h = 2.5 symplectic Euler must blow up, but after "
      << one.frames << " frames the stretch is " << num(u1) << " m; " << input(one)
      << hint("advance(frameDt, 1) is one step of the whole frameDt");
  const double bound = 2 * u0 / std::sqrt(4 - 0.25 * 0.25);
  auto within = [&](const std::vector<Particle>& state) {
    const double u = stretch(state);
    return std::isfinite(u) && std::abs(u) <= bound * 1.001;
  };
  for (const auto& state : held.states) {
    const double u = stretch(state);
    ASSERT_TRUE(within(state)) << currentTask()
                               << ": with 10 substeps (omega h = 0.25) the stretch reached "
                               << num(u) << " m, more than " << num(bound) << " m; " << input(ten)
                               << substepHint(ten, within);
  }
}

TEST(Task3TimeStepping, AdvanceEqualsNStepsOfFrameDtOverN) {
  // advance(T, 3) per frame must equal step(T / 3) three times per frame.
  const double T = 0.03;
  const int n = 3;
  auto sub = request(
      {particle(Vec2(0, 0), Vec2::Zero(), 1.0, true), particle(Vec2(0.4, -0.2), Vec2(0.5, 0), 0.3),
       particle(Vec2(0.9, -0.5), Vec2::Zero(), 0.2)},
      {spring(0, 1, 0.4, 80, 0.3), spring(1, 2, 0.4, 80, 0.3)}, T, 20);
  sub.env.gravity = Vec2(0, -9.81);
  sub.env.drag = 0.1;
  sub.substeps = n;
  auto steps = sub;
  steps.stepOnly = true;
  steps.frameDt = T / n;
  steps.frames = sub.frames * n;
  steps.recordEvery = n;
  A6_SIMULATE(advanced, sub);
  A6_SIMULATE(stepped, steps);
  ManyInputs states("positions and velocities");
  for (std::size_t k = 0; k < advanced.states.size(); ++k) {
    for (std::size_t i = 1; i < 3; ++i) {
      const Particle& a = advanced.states[k][i];
      const Particle& b = stepped.states[k][i];
      const std::string which = "\n  particle " + std::to_string(i) + " after " +
                                std::to_string(advanced.recordedFrames[k]) + " frames: advance(" +
                                num(T) + ", " + std::to_string(n) + ") vs " +
                                std::to_string(n * advanced.recordedFrames[k]) + " calls of step(" +
                                num(T / n) + "); " + input(sub);
      states.expectNear(a.x, b.x, positionTol(sub, b.x, sub.frames), which);
      states.expectNear(a.v, b.v,
                        relativeTo(std::max(b.v.norm(), 9.81 * T * sub.frames), kManySteps), which);
    }
  }
  states.report(hint("advance(frameDt, n) is exactly n calls of step(frameDt / n)"));
  EXPECT_GT((advanced.states.back()[2].x - sub.particles[2].x).norm(), 1e-2)
      << currentTask() << ": particle 2 did not move; " << input(sub);
}

TEST(Task3TimeStepping, StiffChainExplodesWithOneSubstepAndHoldsWithTen) {
  // A chain of 6 particles 0.2 m apart (1 m in all, 10 g each), both ends pinned, joined by
  // stiff springs (1000 N/m), sagging under gravity for 1 s at 60 frames/s. Its fastest mode
  // has omega about 2 sqrt(k/m) = 2 sqrt(1000/0.01) = 632 rad/s: omega h = 10.5 with one
  // substep of 1/60 s (far past the limit of 2: it explodes), 1.05 with ten (it holds).
  const int n = 5;
  const double size = 1.0, h = size / n;
  std::vector<Particle> ps;
  for (int k = 0; k <= n; ++k) {
    ps.push_back(particle(Vec2(k * h, 0), Vec2::Zero(), 0.01, k == 0 || k == n));
  }
  std::vector<SpringData> springs;
  for (int k = 0; k < n; ++k) springs.push_back(spring(k, k + 1, h, 1000, 0.02));
  auto one = request(ps, springs, 1.0 / 60, 60);
  one.env.gravity = Vec2(0, -9.81);
  one.recordEvery = 60;
  auto ten = one;
  ten.substeps = 10;
  A6_SIMULATE(exploded, one);
  A6_SIMULATE(held, ten);

  // Farthest any particle got from its start (infinite once anything is not finite).
  auto farthest = [&](const std::vector<Particle>& state) {
    double d = 0;
    for (std::size_t k = 0; k < state.size(); ++k) {
      const double dk = (state[k].x - ps[k].x).norm();
      d = std::isfinite(dk) ? std::max(d, dk) : INFINITY;
    }
    return d;
  };
  for (const int end : {0, n}) {
    EXPECT_VEC_NEAR(held.states.back()[end].x, ps[end].x, relativeTo(size, 0))
        << "(pinned end, particle " << end << ", after 1 s with 10 substeps); " << input(ten)
        << hint("pinned particles never move: skip them when integrating");
  }
  const double d1 = farthest(exploded.states.back());
  const double d10 = farthest(held.states.back());
  EXPECT_GT(d1, 10 * size) << currentTask() << ": with 1 substep of 1/60 s (omega h >> 2) the "
                           << "stiff chain should explode, but its farthest particle moved only "
                           << num(d1) << " m; " << input(one)
                           << hint("advance(frameDt, 1) is one step of the whole frameDt");
  if (d10 > 2 * size) {
    ADD_FAILURE() << currentTask() << ": with 10 substeps the stiff chain should hold, but a "
                  << "particle moved " << num(d10) << " m from its start; " << input(ten)
                  << substepHint(ten, [&](const std::vector<Particle>& state) {
                       return farthest(state) <= 2 * size;
                     });
  }
}

}  // namespace task3_time_stepping
}  // namespace a6::test
