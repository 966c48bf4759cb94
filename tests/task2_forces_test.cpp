// Task 2 — the forces of the slide "Some forces". Oracles: each formula on tiny inputs with
// values computed by hand (the arithmetic in a comment), in several directions, and properties
// (proportional to m, opposite to v, zero outside an obstacle). Never a second copy of the
// formulas: the expected values of externalForce are sums done by hand too.
#include <cmath>

#include "scales.h"
#include "suite.h"

namespace a6::test {
namespace task2_forces {

// A particle at x with velocity v, mass m and temperature T.
Particle particle(Vec2 x, Vec2 v = Vec2::Zero(), double m = 1.0, double T = 293.15) {
  Particle p;
  p.x = x;
  p.v = v;
  p.m = m;
  p.temperature = T;
  return p;
}

// An environment with every force switched off: tests switch on what they check.
Environment quiet() {
  Environment env;
  env.gravity = Vec2::Zero();
  env.airTemperature = 293.15;
  env.buoyancy = 0;
  env.drag = 0;
  env.repulsion = 0;
  return env;
}

std::string input(const harness::ForcesRequest& r) {
  const Particle& p = r.particle;
  const Environment& env = r.env;
  std::string out = "  input: particle " + str(p) + " T=" + num(p.temperature) +
                    "; env g=" + str(env.gravity) + ", T_air=" + num(env.airTemperature) +
                    ", b=" + num(env.buoyancy) + ", k_d=" + num(env.drag) +
                    ", k_r=" + num(env.repulsion);
  for (const HalfPlane& plane : env.planes) {
    out += ", half-plane{n=" + str(plane.normal) + ", offset=" + num(plane.offset) + "}";
  }
  for (const CircleObstacle& c : env.circles) {
    out += ", circle{c=" + str(c.center) + ", r=" + num(c.radius) + "}";
  }
  return out + "; contact{depth=" + num(r.contact.depth) + ", n=" + str(r.contact.normal) + "}";
}

// A force's tolerance: relative to the scale of everything that acts on the particle (scales.h).
Tolerance tol(const harness::ForcesRequest& r) {
  return relativeTo(externalForceScale(r.particle, r.env, r.contact.depth));
}

harness::ForcesResult forcesOf(const harness::ForcesRequest& r) {
  harness::ForcesResult result = student().ask(r);
  A6_EXPECT_RAN(result);
  return result;
}

// The parts of a particle's force, computed by hand for one test's input.
struct Parts {
  Vec2 gravity, buoyancy, drag;
};

// The hint of a check of externalForce's total: when one of the parts it adds is itself off
// (its own checks fail too), that part, not `sumHint`. `expected`: the test's hand-computed
// parts; the repulsion asked for with no contact must be zero.
std::string totalHint(const harness::ForcesResult& got, const harness::ForcesRequest& r,
                      const Parts& expected, const std::string& sumHint) {
  const Tolerance t = tol(r);
  const struct {
    const char* name;
    Vec2 actual, expected;
  } parts[] = {
      {"gravity (m g)", got.gravity, expected.gravity},
      {"buoyancy (b (T - T_air) (0, 1))", got.buoyancy, expected.buoyancy},
      {"drag (-k_d v)", got.drag, expected.drag},
      {"repulsion for no contact (zero while d <= 0)", got.repulsion, Vec2::Zero()},
  };
  for (const auto& part : parts) {
    if (!finite(part.actual) ||
        (part.actual - part.expected).cwiseAbs().maxCoeff() > t.absolute()) {
      return hint(std::string("your ") + part.name +
                  " is off for this particle: " + str(part.actual) + " instead of " +
                  str(part.expected) + "; fix that part first (its own checks fail too)");
    }
  }
  return hint(sumHint);
}

harness::ForcesRequest request(const Particle& p, const Environment& env,
                               const Contact& contact = Contact{-1, Vec2(0, 1)}) {
  harness::ForcesRequest r;
  r.particle = p;
  r.env = env;
  r.contact = contact;
  return r;
}

// Gravity ---------------------------------------------------------------------------------------

TEST(Task2Forces, GravityIsMassTimesG) {
  // m = 2.5 kg, g = (0, -9.81): f = (0, -24.525) N.
  Environment env = quiet();
  env.gravity = Vec2(0, -9.81);
  const auto r = request(particle(Vec2(0.3, 0.4), Vec2::Zero(), 2.5), env);
  EXPECT_VEC_NEAR(forcesOf(r).gravity, Vec2(0, -24.525), tol(r))
      << input(r) << hint("gravity is a force, m g: multiply g by the particle's mass p.m");
}

TEST(Task2Forces, GravityIsProportionalToMass) {
  Environment env = quiet();
  env.gravity = Vec2(0.5, -9.81);
  const auto light = request(particle(Vec2(0, 0), Vec2::Zero(), 0.2), env);
  const auto heavy = request(particle(Vec2(0, 0), Vec2::Zero(), 5.0), env);
  const Vec2 fLight = forcesOf(light).gravity;
  const Vec2 fHeavy = forcesOf(heavy).gravity;
  EXPECT_VEC_NEAR(fLight, Vec2(0.1, -1.962), tol(light))
      << input(light) << hint("gravity is m g, with the particle's own mass");
  EXPECT_VEC_NEAR(fHeavy, 25.0 * fLight, tol(heavy))
      << input(heavy) << " vs. " << input(light)
      << hint("a 25 times heavier particle feels a 25 times larger gravity force: f = m g");
}

TEST(Task2Forces, GravityFollowsGInAnyDirection) {
  ManyInputs directions("directions of g", kNewton);
  for (int k = 0; k < 8; ++k) {
    const double angle = 2 * M_PI * k / 8 + 0.1;
    Environment env = quiet();
    const Vec2 u(std::cos(angle), std::sin(angle));
    env.gravity = 3.7 * u;
    const auto r = request(particle(Vec2(1, -2), Vec2(0.5, 0.5), 1.7), env);
    // By hand: 1.7 kg * 3.7 m/s² = 6.29 N along u.
    directions.expectNear(forcesOf(r).gravity, 6.29 * u, tol(r), input(r));
  }
  directions.report(hint("use the whole vector g (both components), not just its y component"));
}

// Buoyancy --------------------------------------------------------------------------------------

TEST(Task2Forces, HotParticlesRise) {
  // b = 0.02 N/K, T - T_air = 400 - 300 = 100 K: f = (0, 2) N.
  Environment env = quiet();
  env.buoyancy = 0.02;
  env.airTemperature = 300;
  const auto r = request(particle(Vec2(0, 0), Vec2::Zero(), 3.0, 400), env);
  EXPECT_VEC_NEAR(forcesOf(r).buoyancy, Vec2(0, 2), tol(r))
      << input(r)
      << hint(
             "buoyancy is b (T - T_air) (0, 1): a particle hotter than the air is "
             "pushed up, whatever its mass");
}

TEST(Task2Forces, ColdParticlesSink) {
  // b = 0.02 N/K, T - T_air = 250 - 300 = -50 K: f = (0, -1) N.
  Environment env = quiet();
  env.buoyancy = 0.02;
  env.airTemperature = 300;
  const auto r = request(particle(Vec2(0, 0), Vec2::Zero(), 1.0, 250), env);
  EXPECT_VEC_NEAR(forcesOf(r).buoyancy, Vec2(0, -1), tol(r))
      << input(r)
      << hint(
             "b (T - T_air) (0, 1) keeps its sign: colder than the air means a "
             "downward force (no abs, no clamping)");
}

TEST(Task2Forces, NoBuoyancyAtAirTemperature) {
  Environment env = quiet();
  env.buoyancy = 0.05;
  env.airTemperature = 350;
  const auto r = request(particle(Vec2(0, 0), Vec2(1, 1), 2.0, 350), env);
  EXPECT_VEC_NEAR(forcesOf(r).buoyancy, Vec2(0, 0), tol(r))
      << input(r)
      << hint(
             "buoyancy depends on the difference T - T_air (use the airTemperature "
             "parameter): a particle at the air's temperature floats");
}

// Drag ------------------------------------------------------------------------------------------

TEST(Task2Forces, DragOpposesVelocityInAnyDirection) {
  ManyInputs velocities("velocities (2 k_d, 12 directions)", kNewton);
  // By hand, |v| = 2.5 m/s: k_d = 0.7 gives 1.75 N against v, k_d = 2 gives 5 N.
  for (const auto& [kd, against] : {std::pair{0.7, 1.75}, {2.0, 5.0}}) {
    for (int k = 0; k < 12; ++k) {
      const double angle = 2 * M_PI * k / 12 + 0.3;
      Environment env = quiet();
      env.drag = kd;
      const Vec2 u(std::cos(angle), std::sin(angle));
      const auto r = request(particle(Vec2(0.2, 0.1), 2.5 * u, 1.5), env);
      velocities.expectNear(forcesOf(r).drag, -against * u, tol(r), input(r));
    }
  }
  velocities.report(
      hint("drag is -k_d v: against the velocity, proportional to it (not to the "
           "mass, not to the speed squared)"));
}

// Repulsion -------------------------------------------------------------------------------------

TEST(Task2Forces, RepulsionPushesOutOfAFloor) {
  // A floor contact: depth 0.05 m, normal (0, 1), k_r = 400 N/m: f = (0, 20) N.
  Environment env = quiet();
  env.repulsion = 400;
  const auto r = request(particle(Vec2(0, -0.05)), env, Contact{0.05, Vec2(0, 1)});
  EXPECT_VEC_NEAR(forcesOf(r).repulsion, Vec2(0, 20), tol(r))
      << input(r) << hint("repulsion is k_r d n: along the contact normal, out of the obstacle");
}

TEST(Task2Forces, RepulsionFollowsADiagonalNormal) {
  // depth 0.1 m, normal (0.6, -0.8), k_r = 250 N/m: f = 25 (0.6, -0.8) = (15, -20) N.
  Environment env = quiet();
  env.repulsion = 250;
  const auto r = request(particle(Vec2(0, 0)), env, Contact{0.1, Vec2(0.6, -0.8)});
  EXPECT_VEC_NEAR(forcesOf(r).repulsion, Vec2(15, -20), tol(r))
      << input(r) << hint("use the contact's own normal n (both components), not (0, 1)");
}

TEST(Task2Forces, NoRepulsionOutsideOrOnTheSurface) {
  Environment env = quiet();
  env.repulsion = 1000;
  ManyInputs contacts("contacts (3 depths, 2 normals)", kNewton);
  for (const double depth : {-0.3, -1e-6, 0.0}) {
    for (const Vec2& n : {Vec2(0, 1), Vec2(-0.8, 0.6)}) {
      const auto r = request(particle(Vec2(0, 0)), env, Contact{depth, n});
      // Relative to the force the depth would give if it counted.
      contacts.expectNear(forcesOf(r).repulsion, Vec2(0, 0),
                          relativeTo(env.repulsion * std::abs(depth)), input(r));
    }
  }
  contacts.report(
      hint("repulsion acts only while the particle is inside (depth > 0); outside, "
           "a negative depth would pull it into the obstacle"));
}

// externalForce ---------------------------------------------------------------------------------

TEST(Task2Forces, ExternalForceAddsGravityBuoyancyAndDrag) {
  // m = 0.5, g = (0, -10): (0, -5); b = 0.01, T - T_air = 200: (0, 2);
  // k_d = 0.25, v = (2, -4): (-0.5, 1). Sum: (-0.5, -2).
  Environment env = quiet();
  env.gravity = Vec2(0, -10);
  env.buoyancy = 0.01;
  env.airTemperature = 300;
  env.drag = 0.25;
  const auto r = request(particle(Vec2(0, 5), Vec2(2, -4), 0.5, 500), env);
  const harness::ForcesResult got = forcesOf(r);
  EXPECT_VEC_NEAR(got.total, Vec2(-0.5, -2), tol(r))
      << input(r)
      << totalHint(got, r, {Vec2(0, -5), Vec2(0, 2), Vec2(-0.5, 1)},
                   "externalForce is the sum gravity + buoyancy + drag (+ repulsion)");
}

TEST(Task2Forces, ExternalForceAddsEveryObstacleItIsIn) {
  // A particle inside a floor and a circle at once, outside a wall and another circle.
  // m = 0.4, g = (0, -9.81): (0, -3.924); b = 0.002, T - T_air = 20: (0, 0.04);
  // k_d = 0.3, v = (0.5, -1.5): (-0.15, 0.45).
  // Floor (n = (0, 1), offset 0) at y = -0.04: d = 0.04, k_r d n = 500 * 0.04 * (0, 1) = (0, 20).
  // Circle at (0.14, -0.12), r = 0.25: x - c = (0.06, 0.08), |x - c| = 0.1, so d = 0.15 and
  // n = (0.6, 0.8): 500 * 0.15 * (0.6, 0.8) = (45, 60).
  // Sum: (-0.15 + 45, -3.924 + 0.04 + 0.45 + 20 + 60) = (44.85, 76.566).
  Environment env = quiet();
  env.gravity = Vec2(0, -9.81);
  env.buoyancy = 0.002;
  env.airTemperature = 300;
  env.drag = 0.3;
  env.repulsion = 500;
  env.planes.push_back({Vec2(0, 1), 0.0});        // floor y < 0
  env.planes.push_back({Vec2(-0.6, 0.8), -3.0});  // a tilted wall far to the right
  env.circles.push_back({Vec2(0.14, -0.12), 0.25});
  env.circles.push_back({Vec2(-2, 1), 0.5});
  const Particle p = particle(Vec2(0.2, -0.04), Vec2(0.5, -1.5), 0.4, 320);

  // The set-up puts the particle in exactly one plane and one circle.
  ASSERT_GT(contactWith(env.planes[0], p.x).depth, 0);
  ASSERT_LE(contactWith(env.planes[1], p.x).depth, 0);
  ASSERT_GT(contactWith(env.circles[0], p.x).depth, 0);
  ASSERT_LE(contactWith(env.circles[1], p.x).depth, 0);

  const auto r = request(p, env);
  const harness::ForcesResult got = forcesOf(r);
  EXPECT_VEC_NEAR(got.total, Vec2(44.85, 76.566), tol(r))
      << input(r)
      << totalHint(got, r, {Vec2(0, -3.924), Vec2(0, 0.04), Vec2(-0.15, 0.45)},
                   "add repulsionForce(contactWith(obstacle, p.x), env.repulsion) for "
                   "EVERY half-plane and EVERY circle in env, on top of gravity, "
                   "buoyancy and drag");
}

TEST(Task2Forces, ExternalForceAddsTwoOverlappingCircles) {
  // Inside two circles and a diagonal half-plane: three repulsions add up.
  // Half-plane n = (0.6, 0.8), offset 0.3, at x = (0.3, -0.1): n.x = 0.1, d = 0.2:
  // 200 * 0.2 * (0.6, 0.8) = (24, 32).
  // Circle at (0.06, -0.42), r = 0.5: x - c = (0.24, 0.32), distance 0.4, d = 0.1,
  // n = (0.6, 0.8): (12, 16). Circle at (0.6, -0.1), r = 0.5: x - c = (-0.3, 0), d = 0.2,
  // n = (-1, 0): (-40, 0). Gravity: 1.2 * (0, -9.81) = (0, -11.772).
  // Sum: (24 + 12 - 40, 32 + 16 - 11.772) = (-4, 36.228).
  Environment env = quiet();
  env.gravity = Vec2(0, -9.81);
  env.repulsion = 200;
  env.planes.push_back({Vec2(0.6, 0.8), 0.3});
  env.circles.push_back({Vec2(0.06, -0.42), 0.5});
  env.circles.push_back({Vec2(0.6, -0.1), 0.5});
  const Particle p = particle(Vec2(0.3, -0.1), Vec2::Zero(), 1.2);
  ASSERT_GT(contactWith(env.planes[0], p.x).depth, 0);
  ASSERT_GT(contactWith(env.circles[0], p.x).depth, 0);
  ASSERT_GT(contactWith(env.circles[1], p.x).depth, 0);

  const auto r = request(p, env);
  const harness::ForcesResult got = forcesOf(r);
  EXPECT_VEC_NEAR(got.total, Vec2(-4, 36.228), tol(r))
      << input(r)
      << totalHint(got, r, {Vec2(0, -11.772), Vec2::Zero(), Vec2::Zero()},
                   "every obstacle the particle is inside pushes on its own: sum them "
                   "all, using each obstacle's own depth and normal from contactWith");

  // The two circles alone, without the half-plane: (12 - 40, 16 - 11.772) = (-28, 4.228). (A
  // sum that skips the circles, and one that stops at the first obstacle, differ here.)
  env.planes.clear();
  const auto circles = request(p, env);
  const harness::ForcesResult alone = forcesOf(circles);
  EXPECT_VEC_NEAR(alone.total, Vec2(-28, 4.228), tol(circles))
      << input(circles)
      << totalHint(alone, circles, {Vec2(0, -11.772), Vec2::Zero(), Vec2::Zero()},
                   "every circle the particle is inside pushes on its own, after the "
                   "half-planes: sum them all, never stop at the first");
}

TEST(Task2Forces, ObstaclesOutsideAddNothing) {
  // Outside every obstacle, with a strong k_r: only gravity and drag remain.
  // m = 2, g = (0, -10): (0, -20); k_d = 0.5, v = (1, 2): (-0.5, -1). Sum: (-0.5, -21).
  Environment env = quiet();
  env.gravity = Vec2(0, -10);
  env.drag = 0.5;
  env.repulsion = 1e4;
  env.planes.push_back({Vec2(0, 1), -1.0});
  env.planes.push_back({Vec2(0.8, -0.6), -2.0});
  env.circles.push_back({Vec2(3, 3), 1.0});
  const auto r = request(particle(Vec2(0.5, 0.5), Vec2(1, 2), 2.0), env);
  const harness::ForcesResult got = forcesOf(r);
  EXPECT_VEC_NEAR(got.total, Vec2(-0.5, -21), tol(r))
      << input(r)
      << totalHint(got, r, {Vec2(0, -20), Vec2::Zero(), Vec2(-0.5, -1)},
                   "an obstacle the particle is not inside (depth <= 0) adds nothing: "
                   "check the depth before adding k_r d n");
}

}  // namespace task2_forces
}  // namespace a6::test
