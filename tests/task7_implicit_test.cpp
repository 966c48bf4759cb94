// Task 7 (extra credit) — springJacobians and MassSpringSystem::stepImplicit. Oracles: Jacobians
// computed by hand, central finite differences of your own task 1 force, the closed form of
// backward Euler for a linear spring, its exact energy loss per step, and the limit of tiny steps.
//
// The steps set referenceForces, so a bug in task 1 or 2 never fails these checks; the Jacobians
// are your own (task 7's).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "suite.h"

namespace a6::test {
namespace task7_implicit {

using harness::JacobiansResult;
using harness::SimulateRequest;
using harness::SimulateResult;
using harness::SpringData;
using harness::SpringForceRequest;
using harness::SpringForceResult;

// --- Springs and their Jacobians -------------------------------------------------------------

Particle at(Vec2 x, Vec2 v = Vec2::Zero()) {
  Particle p;
  p.x = x;
  p.v = v;
  return p;
}

SpringForceRequest springOf(Vec2 x1, Vec2 x2, double restLength, double ks, double kd = 0,
                            Vec2 v1 = Vec2::Zero(), Vec2 v2 = Vec2::Zero()) {
  SpringForceRequest r;
  r.p1 = at(x1, v1);
  r.p2 = at(x2, v2);
  r.restLength = restLength;
  r.ks = ks;
  r.kd = kd;
  return r;
}

std::string input(const SpringForceRequest& r) {
  return "  input: x1=" + str(r.p1.x) + ", x2=" + str(r.p2.x) + ", v1=" + str(r.p1.v) +
         ", v2=" + str(r.p2.v) + ", l0=" + num(r.restLength) + ", ks=" + num(r.ks) +
         ", kd=" + num(r.kd);
}

std::string matrix(const Mat2& m) {
  return "[[" + num(m(0, 0)) + ", " + num(m(0, 1)) + "], [" + num(m(1, 0)) + ", " + num(m(1, 1)) +
         "]]";
}

JacobiansResult jacobiansOf(const SpringForceRequest& r) {
  return student().ask(harness::JacobiansRequest{r});
}

// |actual - hand| <= tol entry by entry; the message names the matrix, both values and the input.
::testing::AssertionResult sameMatrix(const char* what, const Mat2& actual, const Mat2& hand,
                                      double scale, const SpringForceRequest& r) {
  const double tol = std::max(scale, 1e-300) * kOneComputation;
  if (((actual - hand).array().abs() <= tol).all()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << currentTask() << ": " << what << " is " << matrix(actual)
                                       << ", the hand-computed value is " << matrix(hand) << "\n"
                                       << input(r);
}

constexpr char kSignHint[] =
    "dfdx = -ks (e eᵀ + (1 - l0/l) (I - e eᵀ)): along the spring its stiffness is -ks, across it "
    "-ks (1 - l0/l); dfdv = -kd e eᵀ. Both are NEGATIVE: a spring pulls back";

// Runs the Jacobians of r and compares them with hand-computed values.
void expectJacobians(const SpringForceRequest& r, const Mat2& dfdx, const Mat2& dfdv,
                     const std::string& hintText) {
  const JacobiansResult j = jacobiansOf(r);
  A6_ASSERT_RAN(j) << "\n" << input(r);
  EXPECT_TRUE(sameMatrix("dfdx", j.dfdx, dfdx, r.ks, r)) << hint(hintText);
  EXPECT_TRUE(sameMatrix("dfdv", j.dfdv, dfdv, r.kd, r)) << hint(hintText);
}

TEST(Task7Implicit, JacobianOfAStretchedSpringAlongX) {
  // l = 1.5, l0 = 1: along x the stiffness is -ks, across it -ks (1 - 1/1.5) = -ks / 3.
  const SpringForceRequest r = springOf(Vec2(0, 0), Vec2(1.5, 0), 1.0, 90);
  Mat2 dfdx;
  dfdx << -90, 0, 0, -30;
  expectJacobians(r, dfdx, Mat2::Zero(),
                  "across the spring a stretched spring pulls sideways with -ks (1 - l0/l): the "
                  "(1 - l0/l) (I - e eᵀ) term");
}

TEST(Task7Implicit, JacobianOfADiagonalSpring) {
  // e = (0.6, 0.8), l = 2, l0 = 1: dfdx = -ks (e eᵀ + ½ (I - e eᵀ)) = -ks/2 (I + e eᵀ).
  const SpringForceRequest r = springOf(Vec2(1, 1), Vec2(2.2, 2.6), 1.0, 100);
  Mat2 dfdx;
  dfdx << -50 * 1.36, -50 * 0.48, -50 * 0.48, -50 * 1.64;
  expectJacobians(r, dfdx, Mat2::Zero(), "e eᵀ is the 2x2 matrix e * e.transpose()");
}

TEST(Task7Implicit, JacobianOfASpringAtRest) {
  // l = l0 = 0.5, e = (-0.6, 0.8): only the term along the spring is left, -ks e eᵀ.
  const SpringForceRequest r = springOf(Vec2(0, 0), Vec2(-0.3, 0.4), 0.5, 50);
  Mat2 dfdx;
  dfdx << -50 * 0.36, 50 * 0.48, 50 * 0.48, -50 * 0.64;
  expectJacobians(r, dfdx, Mat2::Zero(),
                  "at rest the spring is still stiff along e: the -ks e eᵀ term does not vanish "
                  "with l - l0");
}

TEST(Task7Implicit, JacobianOfACompressedSpring) {
  // l = 0.5, l0 = 1, e = (0, 1): across the spring -ks (1 - 2) = +ks (a compressed spring pushes
  // sideways), along it -ks.
  const SpringForceRequest r = springOf(Vec2(0, 0), Vec2(0, 0.5), 1.0, 10);
  Mat2 dfdx;
  dfdx << 10, 0, 0, -10;
  expectJacobians(r, dfdx, Mat2::Zero(),
                  "1 - l0/l is negative for a compressed spring: keep its sign, do not clamp it");
}

TEST(Task7Implicit, DampingJacobianActsOnlyAlongTheSpring) {
  // e = (1, 0), kd = 4: dfdv = -kd e eᵀ, whatever the velocities; the spring is at rest.
  const SpringForceRequest r =
      springOf(Vec2(0, 0), Vec2(2, 0), 2.0, 10, 4, Vec2(0.5, -1), Vec2(1, 3));
  Mat2 dfdx, dfdv;
  dfdx << -10, 0, 0, 0;
  dfdv << -4, 0, 0, 0;
  expectJacobians(r, dfdx, dfdv,
                  "the damping force -kd ((v2 - v1)·e) e changes with v2 by -kd e eᵀ: only along "
                  "the spring");
}

TEST(Task7Implicit, CoincidentParticlesGiveZeroJacobians) {
  const SpringForceRequest r = springOf(Vec2(1, 1), Vec2(1, 1), 0.5, 100, 2);
  const JacobiansResult j = jacobiansOf(r);
  A6_ASSERT_RAN(j) << "\n" << input(r);
  EXPECT_TRUE(j.dfdx.allFinite() && j.dfdv.allFinite() && j.dfdx.isZero() && j.dfdv.isZero())
      << currentTask() << ": dfdx " << matrix(j.dfdx) << ", dfdv " << matrix(j.dfdv)
      << ": expected zero (no direction, as in task 1)\n"
      << input(r) << hint("return zero Jacobians when l < 1e-12, before dividing by l");
}

// --- Finite differences of your own force -----------------------------------------------------

// Hand-computed springs and their forces on p2, each at rest in velocity (v1 = v2, so dfdx is
// the whole derivative by position); for a damped one, also the force with p2 moving by `dv2`.
struct KnownSpring {
  SpringForceRequest request;
  Vec2 force;                                      // on p2, N, computed by hand
  std::vector<std::pair<Vec2, Vec2>> moving = {};  // (dv2, the force on p2 then), by hand
};

std::vector<KnownSpring> knownSprings() {
  // The damped spring: e = (0.6, 0.8); p2 moving along e at 1 m/s adds -kd e = (-1.8, -2.4),
  // across e nothing. No spring is 1 m long: there d = e, and a force that uses d for e is right
  // at the spring but not in its derivatives (task 1's mistake, not task 7's).
  return {{springOf(Vec2(0, 0), Vec2(1.5, 0), 1.0, 100), Vec2(-50, 0)},
          {springOf(Vec2(1, 1), Vec2(1.9, 2.2), 0.5, 40), Vec2(-24, -32)},
          {springOf(Vec2(0, 0), Vec2(0, 0.5), 1.0, 10), Vec2(0, 5)},
          {springOf(Vec2(2, -1), Vec2(2.3, -0.6), 1.0, 20, 3, Vec2(1, 2), Vec2(1, 2)),
           Vec2(6, 8),
           {{Vec2(0.6, 0.8), Vec2(4.2, 5.6)}, {Vec2(-0.8, 0.6), Vec2(6, 8)}}}};
}

// The spring turned by `angle` about the origin and moved by `shift`: its forces turn alike.
KnownSpring turned(KnownSpring k, double angle, const Vec2& shift) {
  Mat2 turn;
  turn << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  for (Particle* p : {&k.request.p1, &k.request.p2}) {
    p->x = turn * p->x + shift;
    p->v = turn * p->v;
  }
  k.force = turn * k.force;
  for (auto& [dv2, force] : k.moving) {
    dv2 = turn * dv2;
    force = turn * force;
  }
  return k;
}

// Whether your task 1 force is the hand-computed one at the spring, and with p2 moving.
bool forceIsRight(const KnownSpring& s) {
  const SpringForceRequest& r = s.request;
  const double scale = r.ks * std::max((r.p2.x - r.p1.x).norm(), r.restLength) + r.kd;
  const auto right = [&](const SpringForceRequest& q, const Vec2& force) {
    const SpringForceResult own = student().ask(q);
    return own.ok() && (own.force - force).norm() <= 1e-9 * scale;
  };
  bool ok = right(r, s.force);
  for (const auto& [dv2, force] : s.moving) {
    SpringForceRequest q = r;
    q.p2.v += dv2;
    ok = ok && right(q, force);
  }
  return ok;
}

// Your force on p2 with `change` applied to the request.
template <typename Change>
Vec2 forceAfter(SpringForceRequest r, Change&& change, bool& ran) {
  change(r);
  const SpringForceResult f = student().ask(r);
  ran = ran && f.ok();
  return f.force;
}

// Central differences of your force by p2's and p1's position and velocity, column by column.
struct Differences {
  Mat2 byX2, byX1, byV2, byV1;
};
Differences differencesOf(const SpringForceRequest& r, double h, bool& ran) {
  Differences d;
  for (int c = 0; c < 2; ++c) {
    const auto column = [&](auto member) {
      const Vec2 plus = forceAfter(
          r, [&](SpringForceRequest& q) { member(q)[c] += h; }, ran);
      const Vec2 minus = forceAfter(
          r, [&](SpringForceRequest& q) { member(q)[c] -= h; }, ran);
      return Vec2((plus - minus) / (2 * h));
    };
    d.byX2.col(c) = column([](SpringForceRequest& q) -> Vec2& { return q.p2.x; });
    d.byX1.col(c) = column([](SpringForceRequest& q) -> Vec2& { return q.p1.x; });
    d.byV2.col(c) = column([](SpringForceRequest& q) -> Vec2& { return q.p2.v; });
    d.byV1.col(c) = column([](SpringForceRequest& q) -> Vec2& { return q.p1.v; });
  }
  return d;
}

TEST(Task7Implicit, JacobiansMatchFiniteDifferencesOfYourForce) {
  // Where your task 1 force is right (checked against the hand-computed value), your Jacobians
  // must be its derivatives: ∂f2/∂x2 = dfdx, ∂f2/∂x1 = -dfdx, and the same for v. Where it is
  // wrong, task 1's checks say so and this check does not blame task 7 for it.
  // (A spring where your force is wrong is skipped: the check passes when none is left.)
  std::string first;
  for (const KnownSpring& base : knownSprings()) {
    for (int k = 0; k < 6; ++k) {
      const KnownSpring s = turned(base, 0.9 * k, Vec2(0.3 * k, -0.2 * k));
      const SpringForceRequest& r = s.request;
      if (!forceIsRight(s)) continue;
      const JacobiansResult j = jacobiansOf(r);
      A6_ASSERT_RAN(j) << "\n" << input(r);
      bool ran = true;
      const Differences d = differencesOf(r, 1e-3 * std::max(r.restLength, 1.0), ran);
      ASSERT_TRUE(ran) << currentTask() << ": your task 1 force failed on a nearby input\n"
                       << input(r);
      // Central differences: O(h²) of the scale, and a float force's rounding over h.
      const double tol = 1e-3 * (r.ks + r.kd);
      const std::pair<const char*, Mat2> pairs[] = {{"∂f2/∂x2 - dfdx", d.byX2 - j.dfdx},
                                                    {"∂f2/∂x1 + dfdx", d.byX1 + j.dfdx},
                                                    {"∂f2/∂v2 - dfdv", d.byV2 - j.dfdv},
                                                    {"∂f2/∂v1 + dfdv", d.byV1 + j.dfdv}};
      for (const auto& [what, difference] : pairs) {
        if (first.empty() && !(difference.array().abs() <= tol).all()) {
          first = std::string(what) + " = " + matrix(difference) + ", expected zero (your dfdx " +
                  matrix(j.dfdx) + ", dfdv " + matrix(j.dfdv) + ")\n" + input(r);
        }
      }
    }
  }
  EXPECT_TRUE(first.empty())
      << currentTask() << ": your Jacobians are not the derivatives of your own force: " << first
      << hint("differentiate f2 = -ks (l - l0) e - kd v_rel e: by x2 it is dfdx, by x1 -dfdx");
}

// --- Steps -------------------------------------------------------------------------------------

SimulateRequest implicitRequest(std::vector<Particle> particles, std::vector<SpringData> springs,
                                double dt, int frames) {
  SimulateRequest r;
  r.particles = std::move(particles);
  r.springs = std::move(springs);
  r.env.gravity = Vec2::Zero();
  r.env.drag = 0;
  r.env.buoyancy = 0;
  r.env.repulsion = 0;
  r.frameDt = dt;
  r.frames = frames;
  r.stepOnly = true;
  r.implicit = true;
  r.referenceForces = true;
  return r;
}

Particle body(Vec2 x, Vec2 v, double m, bool pinned = false) {
  Particle p = at(x, v);
  p.m = m;
  p.pinned = pinned;
  return p;
}

SpringData springData(int i, int j, double restLength, double ks, double kd) {
  SpringData s;
  s.i = i;
  s.j = j;
  s.restLength = restLength;
  s.ks = ks;
  s.kd = kd;
  return s;
}

std::string input(const SimulateRequest& r) {
  std::string out = "  input: " + std::to_string(r.particles.size()) + " particle(s)";
  for (std::size_t k = 0; k < std::min<std::size_t>(r.particles.size(), 2); ++k)
    out += (k == 0 ? " " : ", ") + str(r.particles[k]);
  if (!r.springs.empty()) {
    const SpringData& s = r.springs[0];
    out += "; spring " + std::to_string(s.i) + "-" + std::to_string(s.j) +
           " l0=" + num(s.restLength) + " ks=" + num(s.ks) + " kd=" + num(s.kd);
  }
  return out + "; g=" + str(r.env.gravity) + "; " + std::to_string(r.frames) + " stepImplicit(" +
         num(r.frameDt) + ")";
}

// Runs the request; fails the check unless every frame came back with every particle.
::testing::AssertionResult ranAll(const SimulateRequest& r, const SimulateResult& result) {
  if (!result.ok()) {
    return ::testing::AssertionFailure()
           << currentTask() << ": your code failed: " << result.error << "\n"
           << input(r);
  }
  if (result.states.size() != static_cast<std::size_t>(r.frames)) {
    return ::testing::AssertionFailure()
           << currentTask() << ": expected " << r.frames << " states, got " << result.states.size();
  }
  for (const auto& state : result.states) {
    if (state.size() != r.particles.size()) {
      return ::testing::AssertionFailure()
             << currentTask() << ": expected " << r.particles.size() << " particles, got "
             << state.size() << hint("never add or remove particles in stepImplicit()");
    }
  }
  return ::testing::AssertionSuccess();
}

// A mass m on a spring (ks, kd, rest length 1) to an anchor pinned at the origin, u0 beyond its
// rest length along x, moving at w0 along x: a linear spring, so one linearised step is exact
// backward Euler.
SimulateRequest anchored(double m, double ks, double kd, double u0, double w0, double dt,
                         int frames) {
  return implicitRequest(
      {body(Vec2(0, 0), Vec2::Zero(), 1.0, true), body(Vec2(1 + u0, 0), Vec2(w0, 0), m)},
      {springData(0, 1, 1.0, ks, kd)}, dt, frames);
}

constexpr char kStepHint[] =
    "solve (M - h dfdv - h² dfdx) Δv = h (f + h dfdx v), then v += Δv and x += h v with the new "
    "v; fix() the pinned particles so that the others are solved against an anchor that stays";

TEST(Task7Implicit, OneStepOfALinearSpringIsBackwardEuler) {
  // Backward Euler: m v1 = m v0 + h (-ks (u0 + h v1) - kd v1), so
  //   v1 = (m v0 - h ks u0) / (m + h kd + h² ks),   x1 = x0 + h v1.
  struct Case {
    double m, ks, kd, u0, w0, dt;
  };
  const Case cases[] = {{1, 100, 0, 0.3, 0, 0.01},
                        {2, 400, 3, -0.2, 1.5, 0.05},
                        {0.5, 50, 0.5, 0.1, -2, 0.2},
                        {0.01, 1000, 0.5, 0.05, 0.4, 1.0 / 60}};
  ManyInputs inputs("the particle after one stepImplicit", kMetre);
  for (const Case& c : cases) {
    const SimulateRequest r = anchored(c.m, c.ks, c.kd, c.u0, c.w0, c.dt, 1);
    const SimulateResult result = student().ask(r);
    ASSERT_TRUE(ranAll(r, result));
    const double v1 = (c.m * c.w0 - c.dt * c.ks * c.u0) / (c.m + c.dt * c.kd + c.dt * c.dt * c.ks);
    const Particle& p = result.states[0][1];
    const double scale = std::abs(c.w0) + c.dt * c.ks * std::abs(c.u0) / c.m + std::abs(v1);
    inputs.expectNear(p.v, Vec2(v1, 0), relativeTo(scale), "velocity; " + input(r));
    inputs.expectNear(p.x, Vec2(1 + c.u0 + c.dt * v1, 0), relativeTo(1 + std::abs(c.u0)),
                      "position; " + input(r));
    inputs.expectNear(result.states[0][0].x, Vec2(0, 0), relativeTo(1),
                      "the pinned anchor; " + input(r));
  }
  inputs.report(hint(kStepHint));
}

TEST(Task7Implicit, TheUndampedOscillatorLosesEnergyByTheExactFactor) {
  // Backward Euler on an undamped oscillator never gains energy: each step multiplies
  // E = ½ m v² + ½ ks u² by exactly 1 / (1 + (h ω)²). Here h ω = 0.5 (0.8 per step) and
  // h ω = 3, beyond task 3's stability limit of 2 (0.1 per step).
  for (const double hOmega : {0.5, 3.0}) {
    const double m = 0.5, ks = 200, omega = std::sqrt(ks / m), h = hOmega / omega;
    SimulateRequest r = anchored(m, ks, 0, 0.2, 1.0, h, 12);
    const SimulateResult result = student().ask(r);
    ASSERT_TRUE(ranAll(r, result));
    const auto energy = [&](const Particle& p) {
      const double u = p.x.x() - 1;
      return 0.5 * p.m * p.v.squaredNorm() + 0.5 * ks * u * u;
    };
    double before = energy(r.particles[1]);
    const double factor = 1 / (1 + hOmega * hOmega);
    ManyInputs inputs("the energy after each step, for h ω = " + num(hOmega), Unit{"J"});
    for (int k = 0; k < r.frames; ++k) {
      const double after = energy(result.states[k][1]);
      inputs.expectNear(after, before * factor, relativeTo(before, kManySteps),
                        "step " + std::to_string(k + 1) + "; " + input(r));
      before = after;
    }
    inputs.report(
        hint("backward Euler damps: if your energy grows, check the signs of the "
             "Jacobians and that A = M - h dfdv - h² dfdx"));
  }
}

TEST(Task7Implicit, PinnedParticlesStay) {
  // A chain of four under gravity, its first particle pinned (and moving: it keeps its v and x),
  // the others free: they must fall, so a step that moves nothing does not pass.
  SimulateRequest r = implicitRequest(
      {body(Vec2(0, 0), Vec2(0.5, 0), 1.0, true), body(Vec2(0.3, 0), Vec2::Zero(), 0.2),
       body(Vec2(0.6, 0), Vec2::Zero(), 0.2), body(Vec2(0.9, 0), Vec2::Zero(), 0.2)},
      {springData(0, 1, 0.3, 500, 1), springData(1, 2, 0.3, 500, 1), springData(2, 3, 0.3, 500, 1)},
      1.0 / 60, 10);
  r.env.gravity = Vec2(0, -9.81);
  const SimulateResult result = student().ask(r);
  ASSERT_TRUE(ranAll(r, result));
  ManyInputs inputs("the pinned particle", kMetre);
  for (int k = 0; k < r.frames; ++k) {
    inputs.expectNear(result.states[k][0].x, Vec2(0, 0), relativeTo(1),
                      "x after step " + std::to_string(k + 1) + "; " + input(r));
    inputs.expectNear(result.states[k][0].v, Vec2(0.5, 0), relativeTo(1),
                      "v after step " + std::to_string(k + 1) + "; " + input(r));
  }
  inputs.report(hint("a pinned particle never moves: skip it when you apply Δv and x += v h"));
  // Free fall alone would take it 15 cm in the 10 steps (55 h² g); the chain holds it back.
  const double moved = (result.states.back()[3].x - r.particles[3].x).norm();
  EXPECT_GT(moved, 1e-2) << currentTask() << ": the free particle 3 moved " << num(moved)
                         << " m in " << r.frames << " steps; " << input(r)
                         << hint(
                                "only pinned particles stay put: stepImplicit must apply Δv "
                                "and x += v h to every other particle");
}

// --- Laws of the step on a free system -----------------------------------------------------------

// Three particles of different masses, moving, on three springs that are stretched or compressed
// and turned away from the axes; no pins, gravity or drag: only the springs' internal forces.
SimulateRequest freeTriangle(double kd, double dt, int frames) {
  return implicitRequest(
      {body(Vec2(0, 0), Vec2(0.4, -0.3), 0.6), body(Vec2(0.9, 0.3), Vec2(-0.2, 0.5), 1.5),
       body(Vec2(0.2, 0.8), Vec2(0.3, 0.1), 1.0)},
      {springData(0, 1, 0.8, 60, kd), springData(1, 2, 0.9, 45, kd), springData(2, 0, 0.7, 80, kd)},
      dt, frames);
}

Vec2 momentumOf(const std::vector<Particle>& ps) {
  Vec2 p = Vec2::Zero();
  for (const Particle& q : ps) p += q.m * q.v;
  return p;
}

TEST(Task7Implicit, AFreeSystemKeepsItsMomentum) {
  // Each spring adds -K to the blocks (i, i) and (j, j) and +K to (i, j) and (j, i), and to b
  // +h² dfdx (v_j - v_i) at j and the opposite at i: so Σ m Δv = h Σ f = 0, the linear momentum
  // stays to round-off, and the centre of mass moves in a straight line (x_cm += h P / M at each
  // step, exactly). The springs are damped and the particles move, so a one-sided term shows.
  // (The angular momentum is no law of the linearised step: the across-the-spring part of dfdx
  // turns the forces.)
  SimulateRequest r = freeTriangle(2, 0.05, 30);
  const SimulateResult result = student().ask(r);
  ASSERT_TRUE(ranAll(r, result));
  const Vec2 p0 = momentumOf(r.particles);
  double mass = 0, scale = 0;
  Vec2 centre0 = Vec2::Zero();
  for (const Particle& p : r.particles) mass += p.m, centre0 += p.m * p.x;
  centre0 /= mass;
  ManyInputs momenta("the linear momentum Σ m v", kMomentum), centres("the centre of mass", kMetre);
  bool changed = false;
  for (int k = 0; k < r.frames; ++k) {
    const std::vector<Particle>& s = result.states[k];
    Vec2 centre = Vec2::Zero();
    for (std::size_t i = 0; i < s.size(); ++i) {
      scale = std::max(scale, s[i].m * s[i].v.norm());
      centre += s[i].m * s[i].x / mass;
      changed = changed || (s[i].v - r.particles[i].v).norm() > 1e-2;
    }
    const std::string when = "after step " + std::to_string(k + 1) + "; " + input(r);
    momenta.expectNear(momentumOf(s), p0, relativeTo(3 * std::max(scale, p0.norm())), when);
    centres.expectNear(centre, centre0 + p0 / mass * (r.frameDt * (k + 1)),
                       relativeTo(2, kManySteps), when);
  }
  momenta.report(
      hint("what a spring adds to one particle it takes from the other: -K on both diagonal "
           "blocks, +K on both off-diagonal ones, and h² dfdx (v_j - v_i) to b_j with the "
           "opposite to b_i"));
  centres.report(hint("x += h v with the NEW v, for every particle"));
  EXPECT_TRUE(changed) << currentTask() << ": no velocity changed in " << r.frames
                       << " steps of stretched springs; " << input(r)
                       << hint("stepImplicit must solve for Δv and apply it");
}

// Your step's velocity after one step from the triangle's positions with velocities v (2n long):
// an affine function of v, since A does not depend on v and b does linearly.
Eigen::VectorXd velocityAfterOneStep(const SimulateRequest& base, const Eigen::VectorXd& v,
                                     bool& ran) {
  SimulateRequest r = base;
  for (std::size_t i = 0; i < r.particles.size(); ++i) r.particles[i].v = v.segment<2>(2 * i);
  const SimulateResult result = student().ask(r);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(v.size());
  ran = ran && ranAll(r, result);
  if (!ran) return out;
  for (std::size_t i = 0; i < r.particles.size(); ++i)
    out.segment<2>(2 * i) = result.states[0][i].v;
  return out;
}

// The springs' part of M - A assembled from YOUR springJacobians (undamped springs): +h² dfdx on
// both diagonal blocks, -h² dfdx on both off-diagonal ones.
Eigen::MatrixXd yourSpringsPart(const SimulateRequest& r, bool& ran) {
  const double h = r.frameDt;
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(2 * r.particles.size(), 2 * r.particles.size());
  for (const SpringData& spring : r.springs) {
    SpringForceRequest q = springOf(r.particles[spring.i].x, r.particles[spring.j].x,
                                    spring.restLength, spring.ks, spring.kd);
    const JacobiansResult j = jacobiansOf(q);
    ran = ran && j.ok();
    const Mat2 k = h * h * j.dfdx;
    s.block<2, 2>(2 * spring.i, 2 * spring.i) += k;
    s.block<2, 2>(2 * spring.j, 2 * spring.j) += k;
    s.block<2, 2>(2 * spring.i, 2 * spring.j) -= k;
    s.block<2, 2>(2 * spring.j, 2 * spring.i) -= k;
  }
  return s;
}

TEST(Task7Implicit, TheStepSolvesTheSymmetricSystemOfYourSprings) {
  // One step gives v' = v + A⁻¹ b, with A = M - h² K and b = h (f + h K v) (undamped springs,
  // K assembled from your dfdx): v' = c + W v with W = A⁻¹ M. Your step's W, measured column by
  // column from steps that differ in one velocity, gives back the system your code solved:
  // M - M W⁻¹ = M - A = h² K. It must be symmetric, as the physics makes it (∂f_i/∂x_j =
  // ∂f_j/∂x_i), and it must be the one your own springJacobians give (so a wrong Jacobian is the
  // Jacobian checks' to blame, not this one). Any correct way to assemble and solve it passes.
  const SimulateRequest base = freeTriangle(0, 0.05, 1);
  const int n = static_cast<int>(base.particles.size());
  bool ran = true;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(2 * n);
  const Eigen::VectorXd c = velocityAfterOneStep(base, zero, ran);
  Eigen::MatrixXd w(2 * n, 2 * n), mass = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (int k = 0; k < 2 * n && ran; ++k) {
    w.col(k) = velocityAfterOneStep(base, Eigen::VectorXd::Unit(2 * n, k), ran) - c;
    mass(k, k) = base.particles[k / 2].m;
  }
  const Eigen::MatrixXd expected = yourSpringsPart(base, ran);
  ASSERT_TRUE(ran) << currentTask() << ": your code failed on one of the steps\n" << input(base);
  ASSERT_GT(c.norm(), 1e-3) << currentTask()
                            << ": one step from rest with stretched springs changed no velocity; "
                            << input(base) << hint("stepImplicit must solve for Δv and apply it");
  const Eigen::MatrixXd solved = mass - mass * w.inverse();
  // Inverting W amplifies a float solution's rounding (to a few 1e-6 of the masses): the
  // tolerance of many computations; a block missing or of the wrong sign is off by about 1e-2.
  const double tol = kManySteps * (mass.maxCoeff() + expected.cwiseAbs().maxCoeff());
  const double asymmetry = (solved - solved.transpose()).cwiseAbs().maxCoeff();
  EXPECT_LE(asymmetry, tol)
      << currentTask() << ": the system your step solves, M - A, is not symmetric: its entries "
      << "differ from their mirror images by up to " << num(asymmetry) << " kg\n"
      << input(base)
      << hint(
             "add every spring's block at (i, j) AND at (j, i), with the same sign, and both "
             "diagonal blocks");
  const double off = (solved - expected).cwiseAbs().maxCoeff();
  EXPECT_LE(off, tol) << currentTask() << ": the system your step solves differs by up to "
                      << num(off) << " kg from the one your own springJacobians give (M - h² "
                      << "dfdx on the diagonal blocks, + h² dfdx off them)\n"
                      << input(base)
                      << hint(
                             "A = M - h dfdv - h² dfdx and b = h (f + h dfdx v): check each "
                             "power of h and the term h dfdx v in b");
}

// A cloth of n x n cells of `size` m with structural and shear springs, pinned at its top left
// corner only, so that it swings down: the stiff cloth of the scenes (ks 1000 N/m on 10 g
// particles).
SimulateRequest stiffCloth(int n, double dt, int frames) {
  const double size = 1.0, cell = size / n, m = 0.01, ks = 1000, kd = 0.5;
  std::vector<Particle> particles;
  for (int row = 0; row <= n; ++row) {
    for (int col = 0; col <= n; ++col) {
      const bool corner = row == 0 && col == 0;
      particles.push_back(
          body(Vec2(col * cell - size / 2, 1 - row * cell), Vec2::Zero(), m, corner));
    }
  }
  const auto id = [n](int row, int col) { return row * (n + 1) + col; };
  std::vector<SpringData> springs;
  for (int row = 0; row <= n; ++row) {
    for (int col = 0; col <= n; ++col) {
      if (col < n) springs.push_back(springData(id(row, col), id(row, col + 1), cell, ks, kd));
      if (row < n) springs.push_back(springData(id(row, col), id(row + 1, col), cell, ks, kd));
      if (row < n && col < n) {
        springs.push_back(
            springData(id(row, col), id(row + 1, col + 1), cell * std::sqrt(2.0), ks, kd));
        springs.push_back(
            springData(id(row, col + 1), id(row + 1, col), cell * std::sqrt(2.0), ks, kd));
      }
    }
  }
  SimulateRequest r = implicitRequest(std::move(particles), std::move(springs), dt, frames);
  r.env.gravity = Vec2(0, -9.81);
  return r;
}

TEST(Task7Implicit, TheStiffClothStaysTogetherInOneStepPerFrame) {
  // ω h = sqrt(1000 / 0.01) / 60 = 5.3: one symplectic step per frame explodes (task 3's
  // stiff_cloth_1); one implicit step per frame must not. After 2 s the cloth has swung down
  // from its corner: every particle within 3 m of where it started (the cloth is 1 m wide), every
  // speed below 10 m/s, every spring within 50 % of its rest length, and its centre of mass at
  // least 5 cm lower than it started (the solution: 10 cm).
  SimulateRequest r = stiffCloth(8, 1.0 / 60, 120);
  r.recordEvery = 1;
  const SimulateResult result = student().ask(r);
  ASSERT_TRUE(ranAll(r, result));
  ManyInputs inputs("the stiff cloth after 2 s of one stepImplicit(1/60 s) per frame", kMetre);
  const std::vector<Particle>& last = result.states.back();
  for (std::size_t k = 0; k < last.size(); ++k) {
    const double moved = (last[k].x - r.particles[k].x).norm();
    if (!(moved <= 3) || !(last[k].v.norm() <= 10)) {
      inputs.fail("particle " + std::to_string(k) + " ended at " + str(last[k].x) +
                  " with v = " + str(last[k].v) + ": it moved " + num(moved) + " m");
    }
  }
  // ...and it swung down.
  Vec2 start = Vec2::Zero(), end = Vec2::Zero();
  for (std::size_t k = 0; k < last.size(); ++k) {
    start += r.particles[k].x / static_cast<double>(last.size());
    end += last[k].x / static_cast<double>(last.size());
  }
  if (!(end.y() <= start.y() - 0.05)) {
    inputs.fail("the cloth's centre went from " + str(start) + " to " + str(end) +
                ": gravity should have pulled it down by more than 5 cm");
  }
  for (const SpringData& s : r.springs) {
    const double l = (last[s.j].x - last[s.i].x).norm();
    if (!(std::abs(l - s.restLength) <= 0.5 * s.restLength)) {
      inputs.fail("spring " + std::to_string(s.i) + "-" + std::to_string(s.j) + " is " + num(l) +
                  " m long, its rest length " + num(s.restLength) + " m");
      break;
    }
  }
  inputs.report(
      hint("an implicit step is stable at any step size: if the cloth explodes, check "
           "the Jacobians' signs and that you solve for Δv with dt² dfdx"));
}

TEST(Task7Implicit, TinyStepsAgreeWithSymplecticEulerToFirstOrder) {
  // Springs at rest and gravity: the force is m g, so symplectic Euler gives Δv = g h exactly.
  // Implicit Euler agrees to first order: |Δv / h - g| shrinks in proportion to h.
  const auto run = [](double h) {
    SimulateRequest r = implicitRequest(
        {body(Vec2(0, 0), Vec2(0.4, -0.2), 0.3), body(Vec2(0.5, 0.1), Vec2(-0.3, 0.6), 0.2),
         body(Vec2(0.2, 0.6), Vec2(0.1, 0.2), 0.5)},
        {springData(0, 1, std::sqrt(0.26), 300, 0), springData(1, 2, std::sqrt(0.34), 300, 0),
         springData(0, 2, std::sqrt(0.4), 300, 0)},
        h, 1);
    r.env.gravity = Vec2(0, -9.81);
    return r;
  };
  std::vector<double> errors;
  ManyInputs positions("x1 - x0, which must be h v1 (the NEW velocity)", kMetre);
  for (const double h : {1e-3, 5e-4, 2.5e-4}) {
    const SimulateRequest r = run(h);
    const SimulateResult result = student().ask(r);
    ASSERT_TRUE(ranAll(r, result));
    double error = 0;
    for (std::size_t k = 0; k < r.particles.size(); ++k) {
      const Vec2 dv = result.states[0][k].v - r.particles[k].v;
      error = std::max(error, (dv / h - r.env.gravity).norm());
      const Vec2 dx = result.states[0][k].x - r.particles[k].x;
      positions.expectNear(dx, Vec2(h * result.states[0][k].v), relativeTo(h * 10),
                           "particle " + std::to_string(k) + "; " + input(r));
    }
    errors.push_back(error);
  }
  positions.report(hint(kStepHint));
  // First order: the error halves with h (and is small: below g itself at h = 1 ms).
  EXPECT_LE(errors[0], 9.81) << currentTask() << ": at h = 1e-3 s, |Δv/h - g| is " << num(errors[0])
                             << " m/s², expected it near 0"
                             << hint("Δv is the CHANGE of velocity: v += Δv, b = h (f + h dfdx v)");
  for (std::size_t k = 1; k < errors.size(); ++k) {
    EXPECT_TRUE(errors[k] <= 0.6 * errors[k - 1] && errors[k] >= 0.4 * errors[k - 1])
        << currentTask() << ": |Δv/h - g| went from " << num(errors[k - 1]) << " to "
        << num(errors[k]) << " m/s² when h halved; first order halves it"
        << hint("b = h (f + h dfdx v) and A = M - h dfdv - h² dfdx: check each power of h");
  }
}

}  // namespace task7_implicit
}  // namespace a6::test
