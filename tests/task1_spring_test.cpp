// Task 1 — Spring::computeForce. Oracles: the slide's formula on tiny inputs with values
// computed by hand, and its invariants (direction, sign, Newton's third law).
#include <cmath>

#include "scales.h"
#include "suite.h"

namespace a6::test {
namespace task1_spring {

// A spring from p1 at x1 to p2 at x2, both with the given velocities.
harness::SpringForceRequest spring(Vec2 x1, Vec2 x2, double l0, double ks, double kd,
                                   Vec2 v1 = Vec2::Zero(), Vec2 v2 = Vec2::Zero()) {
  harness::SpringForceRequest r;
  r.p1.x = x1;
  r.p2.x = x2;
  r.p1.v = v1;
  r.p2.v = v2;
  r.restLength = l0;
  r.ks = ks;
  r.kd = kd;
  return r;
}

std::string input(const harness::SpringForceRequest& r) {
  return "  input: p1 " + str(r.p1) + ", p2 " + str(r.p2) + ", l0=" + num(r.restLength) +
         ", ks=" + num(r.ks) + ", kd=" + num(r.kd);
}

// The force's tolerance: relative to ks·max(l, l0) + kd·|Δv| (suite.h).
Tolerance tol(const harness::SpringForceRequest& r) {
  return relativeTo(springForceScale(r.p1.x, r.p2.x, r.p1.v, r.p2.v, r.restLength, r.ks, r.kd));
}

Vec2 forceOf(const harness::SpringForceRequest& r) {
  const harness::SpringForceResult result = student().ask(r);
  A6_EXPECT_RAN(result);
  return result.force;
}

TEST(Task1Spring, AtRestGivesZeroForce) {
  const auto r = spring(Vec2(0, 0), Vec2(0.6, 0.8), 1.0, 50, 2);
  EXPECT_VEC_NEAR(forceOf(r), Vec2(0, 0), tol(r))
      << input(r) << hint("at l = l0 with no relative motion the spring is relaxed: f = 0");
}

TEST(Task1Spring, StretchedPullsP2TowardsP1) {
  // l = 2, l0 = 1, ks = 10: |f| = 10, along -e = (-1, 0).
  const auto r = spring(Vec2(0, 0), Vec2(2, 0), 1.0, 10, 0);
  EXPECT_VEC_NEAR(forceOf(r), Vec2(-10, 0), tol(r))
      << input(r) << hint("the spring pulls p2 back towards p1: check the sign of -ks (l - l0) e");
}

TEST(Task1Spring, CompressedPushesP2Away) {
  // l = 0.5, l0 = 1, ks = 10: f = -10 (0.5 - 1) e = 5 e with e = (0, 1).
  const auto r = spring(Vec2(1, 1), Vec2(1, 1.5), 1.0, 10, 0);
  EXPECT_VEC_NEAR(forceOf(r), Vec2(0, 5), tol(r))
      << input(r)
      << hint("a compressed spring pushes p2 away from p1: f = -ks (l - l0) e with l < l0");
}

TEST(Task1Spring, DiagonalMatchesHandComputedValue) {
  // d = (3, 4), l = 5, e = (0.6, 0.8), l0 = 2, ks = 7: f = -7 * 3 * e = (-12.6, -16.8).
  const auto r = spring(Vec2(1, -1), Vec2(4, 3), 2.0, 7, 0);
  EXPECT_VEC_NEAR(forceOf(r), Vec2(-12.6, -16.8), tol(r))
      << input(r)
      << hint("e = d / |d| with d = x2 - x1; the force is along e, its size ks |l - l0|");
}

TEST(Task1Spring, FormulaHoldsInEveryDirection) {
  const double l0 = 0.7, ks = 13;
  ManyInputs springs("springs (16 directions, 3 lengths)", kNewton);
  // What the failing inputs have in common, for the hint: the exact opposite, or the right size
  // in a wrong direction.
  bool allOpposite = true, allRightSize = true;
  for (int k = 0; k < 16; ++k) {
    const double angle = 2 * M_PI * k / 16;
    const Vec2 e(std::cos(angle), std::sin(angle));
    // By hand, along e: l = 0.3 pushes p2 away with 13 * 0.4 = 5.2 N, l = 0.7 is at rest,
    // l = 1.9 pulls p2 back with 13 * 1.2 = 15.6 N.
    for (const auto& [l, along] : {std::pair{0.3, 5.2}, {0.7, 0.0}, {1.9, -15.6}}) {
      const auto r = spring(Vec2(0.25, -0.5), Vec2(0.25, -0.5) + l * e, l0, ks, 0);
      const Vec2 f = forceOf(r), expected = along * e;
      if (springs.expectNear(f, expected, tol(r), input(r))) continue;
      const double slack = tol(r).absolute();
      allOpposite = allOpposite && finite(f) && (f + expected).cwiseAbs().maxCoeff() <= slack;
      allRightSize = allRightSize && finite(f) && std::abs(f.norm() - expected.norm()) <= slack;
    }
  }
  springs.report(hint(
      allOpposite    ? "every failing force is the exact opposite: f2 = -ks (l - l0) e pulls p2 "
                       "back towards p1 when the spring is stretched (and e = (x2 - x1) / l)"
      : allRightSize ? "the size ks |l - l0| is right but the direction is not: e = d / |d| with "
                       "d = x2 - x1, both components, whatever the spring's angle"
                     : "the size is off: |f2| = ks |l - l0|, with l = |x2 - x1| and l0 the rest "
                       "length"));
}

TEST(Task1Spring, ForceScalesWithStiffness) {
  const auto soft = spring(Vec2(0, 0), Vec2(0, 1.5), 1.0, 10, 0);
  const auto stiff = spring(Vec2(0, 0), Vec2(0, 1.5), 1.0, 30, 0);
  EXPECT_VEC_NEAR(forceOf(stiff), 3.0 * forceOf(soft), tol(stiff))
      << input(stiff) << hint("the force is proportional to ks");
}

TEST(Task1Spring, DampingOpposesSeparation) {
  // At rest length, p2 moving away along e at 2 m/s, kd = 3: f = -3 * 2 * e = (-6, 0).
  const auto r = spring(Vec2(0, 0), Vec2(1, 0), 1.0, 100, 3, Vec2(0, 0), Vec2(2, 0));
  EXPECT_VEC_NEAR(forceOf(r), Vec2(-6, 0), tol(r))
      << input(r) << hint("damping: -kd v_rel e with v_rel = (v2 - v1)·e; it slows the separation");
}

TEST(Task1Spring, DampingUsesRelativeVelocity) {
  // Both particles move together: no relative motion, no damping force.
  const auto r = spring(Vec2(0, 0), Vec2(1, 0), 1.0, 100, 3, Vec2(5, -2), Vec2(5, -2));
  EXPECT_VEC_NEAR(forceOf(r), Vec2(0, 0), tol(r))
      << input(r)
      << hint(
             "damping depends on v2 - v1, not on v2 alone: a spring moving rigidly feels no "
             "damping");
}

TEST(Task1Spring, DampingFollowsTheFirstParticleToo) {
  // At rest length, p1 moving away from p2 at 2 m/s while p2 stays: e = (1, 0), v1 = (-2, 0),
  // v_rel = (v2 - v1)·e = 2, so f = -3 * 2 * e = (-6, 0).
  const auto r = spring(Vec2(0, 0), Vec2(1, 0), 1.0, 100, 3, Vec2(-2, 0), Vec2(0, 0));
  EXPECT_VEC_NEAR(forceOf(r), Vec2(-6, 0), tol(r))
      << input(r) << hint("v_rel = (v2 - v1)·e: when p1 moves away, the spring is separating too");
}

TEST(Task1Spring, DampingActsOnlyAlongTheSpring) {
  // p2 moves perpendicular to the spring: v_rel = 0, so no force at all.
  const auto r = spring(Vec2(0, 0), Vec2(1, 0), 1.0, 100, 3, Vec2(0, 0), Vec2(0, 4));
  EXPECT_VEC_NEAR(forceOf(r), Vec2(0, 0), tol(r))
      << input(r)
      << hint("project the relative velocity on e first: -kd ((v2 - v1)·e) e, not -kd (v2 - v1)");
}

TEST(Task1Spring, StiffnessAndDampingAddUp) {
  // d = (0, 2), e = (0, 1), l0 = 1.5, ks = 4, kd = 0.5, v_rel = (1, -3)·e = -3:
  // f = -4 * 0.5 e - 0.5 * (-3) e = (-2 + 1.5) e = (0, -0.5).
  const auto r = spring(Vec2(2, 0), Vec2(2, 2), 1.5, 4, 0.5, Vec2(0, 0), Vec2(1, -3));
  EXPECT_VEC_NEAR(forceOf(r), Vec2(0, -0.5), tol(r))
      << input(r) << hint("f2 = -ks (l - l0) e - kd v_rel e: both terms, both along e");
}

TEST(Task1Spring, ForceIsAlongTheSpring) {
  const auto r =
      spring(Vec2(0.1, 0.2), Vec2(1.3, -0.4), 0.5, 20, 1.5, Vec2(0.3, 0.7), Vec2(-1.1, 2.0));
  const Vec2 f = forceOf(r);
  const Vec2 d = r.p2.x - r.p1.x;
  // The cross product d × f, of size |d| |f|: zero when f is along d.
  EXPECT_CLOSE(d.x() * f.y() - d.y() * f.x(), 0.0,
               relativeTo(d.norm() * springForceScale(r.p1.x, r.p2.x, r.p1.v, r.p2.v, r.restLength,
                                                      r.ks, r.kd)))
      << input(r) << ", force " << str(f)
      << hint("a spring force (with its damping) is always parallel to d = x2 - x1");
}

TEST(Task1Spring, NewtonsThirdLaw) {
  // Swapping the particles gives the force on the other one: it must be the opposite.
  const auto r =
      spring(Vec2(0.1, 0.2), Vec2(1.3, -0.4), 0.5, 20, 1.5, Vec2(0.3, 0.7), Vec2(-1.1, 2.0));
  auto swapped = r;
  std::swap(swapped.p1, swapped.p2);
  EXPECT_VEC_NEAR(forceOf(swapped), -forceOf(r), tol(r))
      << input(r) << hint("the force on p1 is -f2: swapping p1 and p2 must flip the force");
}

// Worth points: most springs divide by l = 0 here, and a NaN force spreads to every particle of
// a cloth in one step. The ordinary spring beside it keeps a stub that returns zero from passing:
// it only has to give some force (a wrong formula is charged by the other checks, not twice).
// Any guard up to 1 mm is right (no other check has a spring that short).
TEST(Task1Spring, CoincidentParticlesGiveZeroNotNaN) {
  const auto ordinary = spring(Vec2(0.5, 0.5), Vec2(2.5, 0.5), 1.0, 10, 0);
  const Vec2 pull = forceOf(ordinary);
  EXPECT_TRUE(finite(pull) && pull.norm() > 0)
      << currentTask() << ": force " << str(pull) << " for a stretched spring, " << input(ordinary)
      << hint("a stretched spring pulls p2 back: f2 = -ks (l - l0) e, not zero");
  const auto r = spring(Vec2(0.5, 0.5), Vec2(0.5, 0.5), 1.0, 10, 1, Vec2(0, 1), Vec2(1, 0));
  const Vec2 f = forceOf(r);
  EXPECT_TRUE(finite(f)) << currentTask() << ": force " << str(f) << " for " << input(r)
                         << hint(
                                "l = 0 makes e = d / l divide by zero: return zero when l is tiny "
                                "(below 1e-12, or 1 mm)");
  if (finite(f)) {
    EXPECT_VEC_NEAR(f, Vec2(0, 0), tol(r))
        << input(r) << hint("coincident particles give zero force");
  }
}

TEST(Task1Spring, DoesNotChangeTheParticles) {
  // computeForce is const and the request's particles are copies; the force must not depend on
  // earlier calls either.
  const auto r = spring(Vec2(0, 0), Vec2(2, 0), 1.0, 10, 1, Vec2(0, 0), Vec2(1, 0));
  const Vec2 first = forceOf(r);
  const Vec2 second = forceOf(r);
  EXPECT_VEC_NEAR(second, first, relativeTo(tol(r).scale, 0))
      << input(r)
      << hint("the same spring must give the same force every time: keep no state between calls");
}

}  // namespace task1_spring
}  // namespace a6::test
