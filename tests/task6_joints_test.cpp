// Task 6 — Box2D 2.4 joints. Oracles: what each scene asks of its joints (type, bodies, world
// anchors, limits, motor, the stiffness b2LinearStiffness gives), and closed-form physics: the
// physical pendulum's period, the reaction force m g of a hanging bob, free fall while a rope is
// slack, a piston held at its limits, a car that drives forward, a mouse joint that pulls its
// body to the target and disappears when the drag ends.
//
// Box2D solves joints iteratively in single precision, so the dynamic checks compare with
// tolerances of a few percent or a few Box2D slops (b2_linearSlop = 0.005 m), never exactly.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scenes/box2d_scenes.h"
#include "suite.h"

namespace a6::test {
namespace task6_joints {

using harness::Box2DRequest;
using harness::Box2DResult;
using harness::DragEvent;
using harness::JointInfo;
namespace p = box2d_params;

constexpr double kDt = 1.0 / 60;  // s, the time step of every scene
const Vec2 kGravity(0, p::kGravity);
const Vec2 kPivot(p::kPivot.x, p::kPivot.y);
constexpr double kSlop = 0.02;  // m: a few b2_linearSlop, what Box2D lets a joint drift

Box2DResult runScene(const std::string& scene, int steps, std::vector<DragEvent> drag = {}) {
  Box2DRequest request;
  request.scene = scene;
  request.steps = steps;
  request.drag = std::move(drag);
  return student().ask(request);
}

std::string bodyName(const Box2DResult& r, int index) {
  if (index == -1) return "ground";
  if (index >= 0 && index < static_cast<int>(r.bodies.size())) {
    return r.bodies[index].name + " (" + std::to_string(index) + ")";
  }
  return "unknown body";
}

std::string describe(const Box2DResult& r, const JointInfo& j) {
  std::ostringstream out;
  out << j.type << " " << bodyName(r, j.bodyA) << " - " << bodyName(r, j.bodyB) << ", anchors "
      << str(j.anchorA) << " / " << str(j.anchorB);
  if (j.type == "prismatic" || j.type == "wheel") out << ", local axis " << str(j.localAxisA);
  if (j.type == "prismatic" || j.type == "revolute" || j.type == "wheel") {
    out << ", limit " << (j.enableLimit ? "on" : "off") << " [" << j.lower << ", " << j.upper
        << "], motor " << (j.enableMotor ? "on" : "off") << " speed " << j.motorSpeed << " max "
        << j.maxMotor;
  }
  if (j.type == "distance") {
    out << ", length " << j.length << " min " << j.minLength << " max " << j.maxLength;
  }
  if (j.type == "distance" || j.type == "wheel" || j.type == "mouse") {
    out << ", stiffness " << j.stiffness << " damping " << j.damping;
  }
  if (j.type == "mouse") out << ", target " << str(j.target) << ", maxForce " << j.maxForce;
  return out.str();
}

std::string describeAll(const Box2DResult& r, const std::vector<JointInfo>& joints) {
  if (joints.empty()) return "(no joints)";
  std::ostringstream out;
  for (const JointInfo& j : joints) out << "\n    " << describe(r, j);
  return out.str();
}

// "scene 'name': the joints it built ...", the input part of every message.
std::string built(const std::string& scene, const Box2DResult& r) {
  return "scene '" + scene + "', joints after building:" + describeAll(r, r.builtJoints);
}

// Checks a joint's type and bodies; the message names the joint and what the scene expected.
::testing::AssertionResult isJoint(const Box2DResult& r, const JointInfo& j, const char* type,
                                   int bodyA, int bodyB) {
  if (j.type == type && j.bodyA == bodyA && j.bodyB == bodyB) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << currentTask() << ": expected a " << type << " joint " << bodyName(r, bodyA) << " - "
         << bodyName(r, bodyB) << "\n  actual:   " << describe(r, j) << "\n  ";
}

// Box2D computes in float: every comparison allows a model's error (no float note), relative to
// the value itself or to the scene's size.
Tolerance relTol(double expected, double rel) {
  return modelError(std::abs(expected) * rel, expected);
}
constexpr double kSceneSize = 10;  // m: the scenes fit in 10 m
Tolerance inScene(double absolute) { return modelError(absolute, kSceneSize); }

// b2LinearStiffness (Box2D 2.4.1, b2_joint.cpp): m = mA mB / (mA + mB), or the one non-zero
// mass when a body is static; ω = 2π f; stiffness = m ω², damping = 2 m ζ ω.
struct StiffnessDamping {
  double stiffness, damping;
};
StiffnessDamping linearStiffness(double hertz, double ratio, double massA, double massB) {
  const double m =
      massA > 0 && massB > 0 ? massA * massB / (massA + massB) : (massA > 0 ? massA : massB);
  const double omega = 2 * M_PI * hertz;
  return {m * omega * omega, 2 * m * ratio * omega};
}

// Pendulum ------------------------------------------------------------------------------------

TEST(Task6Joints, PendulumIsAHingeAtThePivot) {
  const Box2DResult r = runScene("pendulum", 1);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.builtJoints.size(), 1u)
      << currentTask() << ": " << built("pendulum", r)
      << hint(
             "createHinge must create one b2RevoluteJoint with world.CreateJoint(&def) and "
             "return it");
  const JointInfo& j = r.builtJoints[0];
  EXPECT_TRUE(isJoint(r, j, "revolute", -1, 0))
      << hint("b2RevoluteJointDef::Initialize(a, b, worldAnchor): a becomes bodyA, b bodyB");
  EXPECT_VEC_NEAR(j.anchorA, kPivot, inScene(1e-5))
      << built("pendulum", r)
      << hint(
             "Initialize takes the anchor in WORLD coordinates: pass worldAnchor (the pivot), "
             "not a body's position");
  EXPECT_VEC_NEAR(j.anchorB, kPivot, inScene(1e-5))
      << built("pendulum", r) << hint("both bodies must meet at the pivot when the joint is made");
  EXPECT_FALSE(j.enableLimit || j.enableMotor)
      << currentTask() << ": " << built("pendulum", r)
      << hint("the hinge of a pendulum has no limit and no motor");
}

TEST(Task6Joints, PendulumPeriodMatchesThePhysicalPendulum) {
  // Released from rest at θ0 = 0.1 rad: T = 2π sqrt(I_pivot / (m g L)) (1 + θ0²/16), with
  // I_pivot = I_cm + m L² (parallel axes). The bob's x - x_pivot changes sign every half period;
  // the period is twice the mean spacing of its (interpolated) zero crossings.
  const int steps = 420;  // 7 s, three and a half periods
  const Box2DResult r = runScene("pendulum", steps);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), 1u);
  ASSERT_EQ(r.poses.size(), static_cast<std::size_t>(steps));
  const double m = r.bodies[0].mass, L = p::kPendulumLength, theta0 = p::kPendulumAngle;
  const double iPivot = r.bodies[0].inertia + m * L * L;
  const double expected =
      2 * M_PI * std::sqrt(iPivot / (m * -p::kGravity * L)) * (1 + theta0 * theta0 / 16);

  std::vector<double> crossings;  // s
  double previous = L * std::sin(theta0), tPrevious = 0;
  for (int s = 0; s < steps; ++s) {
    const double x = r.poses[s][0].position.x() - kPivot.x(), t = (s + 1) * kDt;
    if ((previous > 0) != (x > 0)) {
      crossings.push_back(tPrevious + (t - tPrevious) * previous / (previous - x));
    }
    previous = x;
    tPrevious = t;
  }
  ASSERT_GE(crossings.size(), 5u)
      << currentTask() << ": the bob crossed below the pivot " << crossings.size() << " times in "
      << num(steps * kDt) << " s; a pendulum of period " << num(expected) << " s crosses 7 times. "
      << built("pendulum", r) << "\n  bob at the end: " << str(r.poses.back()[0].position)
      << hint("the bob must swing about the pivot: createHinge(world, ground, bob, pivot)");
  const double period = 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  EXPECT_CLOSE(period, expected, relTol(expected, 0.01))
      << "  input: pendulum, m=" << num(m) << " kg, I_cm=" << r.bodies[0].inertia
      << " kg m², L=" << L << " m, θ0=" << num(theta0) << " rad"
      << hint(
             "the period of a hinged bob is fixed by the pivot: check the hinge's anchor is the "
             "pivot (world point), not the bob's centre");
}

TEST(Task6Joints, HangingBobFeelsMinusMTimesGravityAndStaysAtRest) {
  // A bob hanging straight down is in equilibrium: the hinge pulls it up with -m g.
  const int steps = 120;
  const Box2DResult r = runScene("hanging", steps);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), 1u);
  ASSERT_EQ(r.joints.size(), 1u) << currentTask() << ": scene 'hanging', joints after " << steps
                                 << " steps:" << describeAll(r, r.joints)
                                 << hint("createHinge must create and return a revolute joint");
  ASSERT_TRUE(isJoint(r, r.joints[0], "revolute", -1, 0))
      << hint("Initialize(ground, bob, pivot): the bob is bodyB, whose reaction force we read");
  const double m = r.bodies[0].mass;
  const Vec2 expected = -m * kGravity;
  EXPECT_VEC_NEAR(r.joints[0].reactionForce, expected,
                  modelError(0.01 * expected.norm(), expected.norm()))
      << "  input: hanging bob, m=" << num(m) << " kg, gravity " << str(kGravity)
      << ", reaction force on the bob (GetReactionForce) after " << steps << " steps"
      << hint("at rest the hinge carries the bob's whole weight: check the anchor is the pivot");
  const Vec2 start = kPivot - Vec2(0, p::kPendulumLength);
  for (int s = 0; s < steps; ++s) {
    ASSERT_VEC_NEAR(r.poses[s][0].position, start, inScene(1e-3))
        << "step " << s + 1 << " of the hanging bob, which starts at rest right below the pivot"
        << hint("a bob hanging straight below its hinge must not move");
  }
}

// Rope ----------------------------------------------------------------------------------------

TEST(Task6Joints, RopeIsADistanceJointThatCanGoSlack) {
  const Box2DResult r = runScene("rope", 1);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.builtJoints.size(), 1u)
      << currentTask() << ": " << built("rope", r)
      << hint("createRope must create one b2DistanceJoint and return it");
  const JointInfo& j = r.builtJoints[0];
  EXPECT_TRUE(isJoint(r, j, "distance", -1, 0)) << hint(
      "Box2D 2.4 has no rope joint: use b2DistanceJointDef::Initialize(a, b, anchorA, "
      "anchorB)");
  EXPECT_VEC_NEAR(j.anchorA, kPivot, inScene(1e-5))
      << built("rope", r) << hint("anchorA is the pivot");
  EXPECT_VEC_NEAR(j.anchorB, kPivot + Vec2(0.5, 0), inScene(1e-5))
      << built("rope", r) << hint("anchorB is the bob's centre, 0.5 m right of the pivot");
  // Box2D stores max(minLength, b2_linearSlop): a minLength of 0 reads back as 0.005 m.
  const double shortest = b2_linearSlop;
  EXPECT_LE(j.minLength, shortest + 1e-6)
      << currentTask() << ": " << built("rope", r)
      << hint(
             "a rope may get shorter: set def.minLength = 0 after Initialize (which sets "
             "minLength = maxLength = the current distance)");
  EXPECT_CLOSE(j.maxLength, p::kRopeMaxLength, inScene(1e-6))
      << built("rope", r) << hint("def.maxLength = maxLength: the rope's full length");
  EXPECT_TRUE(j.stiffness == 0 && j.damping == 0)
      << currentTask() << ": " << built("rope", r)
      << hint("a rope is no spring: stiffness = damping = 0");
}

TEST(Task6Joints, RopeBobFallsFreelyWhileTheRopeIsSlack) {
  // The bob starts 0.5 m from the pivot on a 1.5 m rope: for its first 25 steps (about 1 m of
  // fall) the rope is slack, and Box2D's symplectic Euler gives exactly
  // y_n = y0 + g t_n (t_n + h) / 2, with x unchanged.
  const Box2DResult r = runScene("rope", 25);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.builtJoints.size(), 1u)
      << currentTask() << ": " << built("rope", r) << hint("createRope must create the joint");
  const Vec2 start = kPivot + Vec2(0.5, 0);
  ASSERT_EQ(r.poses.size(), 25u);
  ManyInputs steps("steps");
  for (int s = 0; s < 25; ++s) {
    const double t = (s + 1) * kDt;
    const Vec2 expected = start + kGravity * t * (t + kDt) / 2;
    steps.expectNear(r.poses[s][0].position, expected, inScene(1e-3),
                     "\n  bob after step " + std::to_string(s + 1) + " (t=" + num(t) +
                         " s), distance to the pivot " +
                         num((r.poses[s][0].position - kPivot).norm()) + " m, rope of max length " +
                         num(p::kRopeMaxLength) + " m. " + built("rope", r));
  }
  steps.report(
      hint("a slack rope pulls nothing: minLength = 0, maxLength = the rope's length (a "
           "distance joint with min = max is a rigid rod)"));
}

TEST(Task6Joints, RopeGoesTautButNeverStretches) {
  const int steps = 300;
  const Box2DResult r = runScene("rope", steps);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.builtJoints.size(), 1u)
      << currentTask() << ": " << built("rope", r) << hint("createRope must create the joint");
  double longest = 0;
  int at = 0;
  for (int s = 0; s < steps; ++s) {
    const double d = (r.poses[s][0].position - kPivot).norm();
    if (d > longest) {
      longest = d;
      at = s + 1;
    }
  }
  EXPECT_LE(longest, p::kRopeMaxLength + kSlop)
      << currentTask() << ": longest pivot-bob distance " << num(longest) << " m at step " << at
      << ", rope max length " << p::kRopeMaxLength << " m. " << built("rope", r)
      << hint("maxLength is the rope's length: the bob must never get farther than that");
  EXPECT_GE(longest, p::kRopeMaxLength - kSlop)
      << currentTask() << ": longest pivot-bob distance " << num(longest) << " m in " << steps
      << " steps, rope max length " << p::kRopeMaxLength << " m. " << built("rope", r)
      << hint(
             "the falling bob must pull the rope taut: maxLength = the rope's length, not "
             "the initial distance");
}

// Bridge --------------------------------------------------------------------------------------

TEST(Task6Joints, BridgeChainsThePlanksWithHingesAtTheirEnds) {
  // Planks 0.5 m long from x = -N/4 to N/4 at y = 1: hinge k joins plank k-1 (the ground for
  // k = 0) to plank k at the left end of plank k; the last one joins plank N-1 to the ground.
  const int n = p::kBridgePlanks;
  const Box2DResult r = runScene("bridge", 1);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.builtJoints.size(), static_cast<std::size_t>(n + 1))
      << currentTask() << ": " << built("bridge", r)
      << hint("createHinge must create and return a revolute joint for every call");
  for (int k = 0; k <= n; ++k) {
    const JointInfo& j = r.builtJoints[k];
    const Vec2 end(-0.25 * n + 0.5 * k, 1.0);
    EXPECT_TRUE(isJoint(r, j, "revolute", k == 0 ? -1 : k - 1, k == n ? -1 : k))
        << "hinge " << k << hint("Initialize(a, b, worldAnchor): a becomes bodyA, b bodyB");
    EXPECT_VEC_NEAR(j.anchorA, end, inScene(1e-5))
        << "hinge " << k << ": " << describe(r, j)
        << hint("the hinge is at the planks' shared end, the world point passed as worldAnchor");
    EXPECT_VEC_NEAR(j.anchorB, end, inScene(1e-5)) << "hinge " << k << ": " << describe(r, j);
    if (HasFailure()) break;  // one wrong hinge says it all
  }
}

TEST(Task6Joints, BridgeHoldsTheLoad) {
  // A box dropped on the middle: the hinges stay joined, the bridge sags a little and carries
  // the box, nothing falls through.
  const int n = p::kBridgePlanks, steps = 240;
  const Box2DResult r = runScene("bridge", steps);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), static_cast<std::size_t>(n + 1));
  ASSERT_EQ(r.joints.size(), static_cast<std::size_t>(n + 1))
      << currentTask() << ": " << built("bridge", r) << hint("createHinge must create the joints");
  for (int k = 0; k <= n; ++k) {
    const JointInfo& j = r.joints[k];
    EXPECT_LE((j.anchorA - j.anchorB).norm(), 0.05)
        << currentTask() << ": hinge " << k << " after " << steps
        << " steps came apart: " << describe(r, j)
        << hint("both bodies' anchors must be the same world point at build");
  }
  double lowest = 1e9, lowestLoad = 1e9;
  for (int s = 0; s < steps; ++s) {
    for (int k = 0; k < n; ++k) lowest = std::min(lowest, r.poses[s][k].position.y());
    lowestLoad = std::min(lowestLoad, r.poses[s][n].position.y());
  }
  EXPECT_GE(lowest, 0.0)
      << currentTask() << ": lowest plank centre y=" << num(lowest)
      << " m (the bridge hangs at y=1)"
      << hint("a hinged bridge sags, it does not collapse: check every hinge's anchor");
  EXPECT_GE(lowestLoad, 0.3)
      << currentTask() << ": lowest load y=" << num(lowestLoad) << " m, dropped from y=2"
      << hint("the load must land on the bridge: check the planks are hinged to each other");
  const std::vector<harness::BodyPose>& last = r.poses.back();
  const double middle = std::max(last[n / 2 - 1].position.y(), last[n / 2].position.y());
  EXPECT_LT(middle, 0.99) << currentTask() << ": middle planks at y=" << num(middle) << " m after "
                          << steps << " steps, the bridge was built at y=1"
                          << hint("the loaded bridge must sag");
  EXPECT_GT(last[n].position.y(), middle)
      << currentTask() << ": load at " << str(last[n].position)
      << ", middle planks at y=" << num(middle) << hint("the load must rest on top of the bridge");
}

// Piston --------------------------------------------------------------------------------------

TEST(Task6Joints, PistonsArePrismaticWithLimitsAndMotor) {
  const Box2DResult r = runScene("piston", 1);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.builtJoints.size(), 2u)
      << currentTask() << ": " << built("piston", r)
      << hint("createPiston must create one b2PrismaticJoint per call and return it");
  const double lower[2] = {p::kPistonLower, -p::kPistonUpper};
  const double upper[2] = {p::kPistonUpper, p::kPistonLower};
  const double speed[2] = {p::kPistonSpeed, -p::kPistonSpeed};
  for (int k = 0; k < 2; ++k) {
    const JointInfo& j = r.builtJoints[k];
    const std::string which = "piston " + std::to_string(k) + ": " + describe(r, j);
    EXPECT_TRUE(isJoint(r, j, "prismatic", -1, k))
        << hint("b2PrismaticJointDef::Initialize(ground, piston, worldAnchor, axis)");
    EXPECT_VEC_NEAR(j.anchorB, j.anchorA, inScene(1e-5))
        << which << hint("pass the world anchor to Initialize; it computes both local anchors");
    EXPECT_VEC_NEAR(j.localAxisA, Vec2(0, 1), inScene(1e-6))
        << which << hint("the pistons slide along the axis passed in, (0, 1)");
    EXPECT_TRUE(j.enableLimit) << currentTask() << ": " << which << hint("def.enableLimit = true");
    EXPECT_CLOSE(j.lower, lower[k], inScene(1e-6)) << which << hint("def.lowerTranslation = lower");
    EXPECT_CLOSE(j.upper, upper[k], inScene(1e-6)) << which << hint("def.upperTranslation = upper");
    EXPECT_TRUE(j.enableMotor) << currentTask() << ": " << which << hint("def.enableMotor = true");
    EXPECT_CLOSE(j.motorSpeed, speed[k], inScene(1e-6))
        << which << hint("def.motorSpeed = motorSpeed");
    EXPECT_CLOSE(j.maxMotor, p::kPistonMaxForce, relTol(p::kPistonMaxForce, 1e-5))
        << which << hint("def.maxMotorForce = maxMotorForce");
  }
}

TEST(Task6Joints, PistonsStopAtTheirLimits) {
  // Piston 0 is driven up into its upper limit, piston 1 down into its lower one (at 1 m/s,
  // 0.5 m away: both arrive after 0.5 s). Translation = (anchorB - anchorA)·axis, with anchorA
  // fixed on the ground.
  const int steps = 90;
  const Box2DResult r = runScene("piston", steps);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), 2u);
  ASSERT_EQ(r.joints.size(), 2u) << currentTask() << ": " << built("piston", r)
                                 << hint("createPiston must create the joints");
  const double limit[2] = {p::kPistonUpper, -p::kPistonUpper};
  for (int k = 0; k < 2; ++k) {
    const JointInfo& j = r.joints[k];
    ASSERT_TRUE(isJoint(r, j, "prismatic", -1, k));
    const double sign = limit[k] > 0 ? 1 : -1;  // +1: upper limit, -1: lower limit
    double farthest = 0;
    int at = 0;
    for (int s = 0; s < steps; ++s) {
      const double translation = r.poses[s][k].position.y() + j.localAnchorB.y() - j.anchorA.y();
      if (sign * translation > sign * farthest) {
        farthest = translation;
        at = s + 1;
      }
    }
    EXPECT_LE(sign * farthest, sign * limit[k] + kSlop)
        << currentTask() << ": piston " << k << " reached translation " << num(farthest)
        << " m at step " << at << ", its limit is " << num(limit[k]) << " m. " << built("piston", r)
        << hint("enableLimit = true with lowerTranslation and upperTranslation stops the piston");
    const double reached = (j.anchorB - j.anchorA).y();
    EXPECT_CLOSE(reached, limit[k], inScene(kSlop))
        << "piston " << k << " translation after " << steps << " steps (" << num(steps * kDt)
        << " s), driven at " << sign * p::kPistonSpeed << " m/s. " << built("piston", r)
        << hint("the motor (enableMotor, motorSpeed, maxMotorForce) drives it to the limit");
  }
}

// Car -----------------------------------------------------------------------------------------

TEST(Task6Joints, CarWheelsAreSprungMotorisedWheelJoints) {
  const Box2DResult r = runScene("car", 1);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), 3u);
  ASSERT_EQ(r.builtJoints.size(), 2u)
      << currentTask() << ": " << built("car", r)
      << hint("createWheel must create one b2WheelJoint per call and return it");
  const StiffnessDamping expected =
      linearStiffness(p::kWheelHertz, p::kWheelDampingRatio, r.bodies[0].mass, r.bodies[1].mass);
  for (int k = 0; k < 2; ++k) {
    const JointInfo& j = r.builtJoints[k];
    const std::string which = "wheel joint " + std::to_string(k) + ": " + describe(r, j);
    EXPECT_TRUE(isJoint(r, j, "wheel", 0, k + 1))
        << hint("b2WheelJointDef::Initialize(chassis, wheel, wheel->GetPosition(), axis)");
    EXPECT_VEC_NEAR(j.anchorA, j.anchorB, inScene(1e-5))
        << which << hint("anchor the wheel joint at the wheel's centre, wheel->GetPosition()");
    EXPECT_VEC_NEAR(j.localAnchorB, Vec2(0, 0), inScene(1e-5))
        << which << hint("the anchor is the wheel's centre, so it is (0, 0) in the wheel's frame");
    EXPECT_VEC_NEAR(j.localAxisA, Vec2(0, 1), inScene(1e-6))
        << which << hint("the suspension slides along the axis passed in, (0, 1)");
    EXPECT_CLOSE(j.stiffness, expected.stiffness, relTol(expected.stiffness, 1e-4))
        << which << ", masses chassis " << r.bodies[0].mass << " kg, wheel " << r.bodies[k + 1].mass
        << " kg, " << p::kWheelHertz << " Hz"
        << hint(
               "b2LinearStiffness(def.stiffness, def.damping, hertz, dampingRatio, chassis, "
               "wheel): stiffness = m ω², m = mA mB / (mA + mB), ω = 2π f");
    EXPECT_CLOSE(j.damping, expected.damping, relTol(expected.damping, 1e-4))
        << which << ", damping ratio " << p::kWheelDampingRatio
        << hint("b2LinearStiffness gives the damping too: 2 m ζ ω");
    EXPECT_TRUE(j.enableMotor) << currentTask() << ": " << which << hint("def.enableMotor = true");
    EXPECT_CLOSE(j.motorSpeed, p::kCarMotorSpeed, inScene(1e-5))
        << which << hint("def.motorSpeed = motorSpeed, unchanged (negative turns clockwise)");
    EXPECT_CLOSE(j.maxMotor, p::kCarMaxTorque, relTol(p::kCarMaxTorque, 1e-5))
        << which << hint("def.maxMotorTorque = maxMotorTorque");
  }
}

TEST(Task6Joints, CarDrivesForwardUprightOnItsSuspension) {
  // Wheels turning clockwise at 15 rad/s (r = 0.4 m: up to 6 m/s) drive the car to +x. Each
  // wheel stays below the chassis, under its anchor, within a wheel radius of travel.
  const int steps = 180;  // 3 s
  const Box2DResult r = runScene("car", steps);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), 3u);
  ASSERT_EQ(r.builtJoints.size(), 2u)
      << currentTask() << ": " << built("car", r) << hint("createWheel must create the joints");
  const Vec2 start = r.poses[0][0].position - kDt * r.poses[0][0].velocity;
  const double travel = r.poses.back()[0].position.x() - start.x();
  EXPECT_GE(travel, 3.0)
      << currentTask() << ": the chassis moved " << num(travel) << " m along x in "
      << num(steps * kDt) << " s. " << built("car", r)
      << hint(
             "motorSpeed < 0 turns the wheels clockwise, which rolls the car to +x; the "
             "motor needs enableMotor and maxMotorTorque");
  for (int s = 0; s < steps; ++s) {
    const harness::BodyPose& chassis = r.poses[s][0];
    ASSERT_LT(std::abs(chassis.angle), 0.5)
        << currentTask() << ": chassis angle " << num(chassis.angle) << " rad at step " << s + 1
        << hint("the car must stay upright: check the suspension's spring (b2LinearStiffness)");
    const double c = std::cos(chassis.angle), sn = std::sin(chassis.angle);
    for (int k = 0; k < 2; ++k) {
      // The wheel's centre in the chassis frame, against its anchor there (where it was built).
      const Vec2 d = r.poses[s][k + 1].position - chassis.position;
      const Vec2 local(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y());
      const Vec2 anchor = r.builtJoints[k].localAnchorA;
      ASSERT_TRUE(std::abs(local.x() - anchor.x()) < 0.05 &&
                  std::abs(local.y() - anchor.y()) < 0.4 && local.y() < 0)
          << currentTask() << ": wheel " << k << " at step " << s + 1 << " is at " << str(local)
          << " in the chassis frame, its anchor at " << str(anchor)
          << hint(
                 "the wheel slides only along the axis and its spring keeps it near the "
                 "anchor: stiffness and damping from b2LinearStiffness");
    }
  }
}

// Joints on turned bodies --------------------------------------------------------------------

// The world point and axis each builder was given, against the joint it built. In the other
// scenes the first body is the ground or not turned, so a point or axis taken in the wrong frame
// (a world axis stored as bodyA's, an offset not turned into the body) cannot show there.
Vec2 toVec(const b2Vec2& v) { return Vec2(v.x, v.y); }
// A world vector in the frame of a body turned by `angle`.
Vec2 intoBody(const Vec2& world, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * world.x() + s * world.y(), -s * world.x() + c * world.y());
}

TEST(Task6Joints, JointsOnTurnedBodiesKeepTheirWorldAnchorsAndAxes) {
  namespace t = p::turned;
  const Box2DResult r = runScene("turned", 1);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.bodies.size(), 5u);
  struct Expected {
    const char* type;
    int bodyA, bodyB;  // frame 0, slider 1, chassis 2, wheel 3, arm 4
    Vec2 anchorA, anchorB;
    Vec2 axis;         // world; zero: no axis
    double angleA;     // bodyA's angle as built
    const char* call;  // the builder, for the hint
  };
  const Expected expected[] = {
      {"prismatic", 0, 1, toVec(t::kSliderAt), toVec(t::kSliderAt), toVec(t::kPistonAxis),
       t::kFrameAngle, "createPiston(world, frame, slider, slider's position, axis, ...)"},
      {"wheel", 2, 3, toVec(t::kWheelAt), toVec(t::kWheelAt), toVec(t::kWheelAxis),
       t::kChassisAngle, "createWheel(world, chassis, wheel, axis, ...)"},
      {"revolute", 0, 4, toVec(t::kHingeAt), toVec(t::kHingeAt), Vec2::Zero(), t::kFrameAngle,
       "createHinge(world, frame, arm, anchor)"},
      {"distance", 2, 4, toVec(t::kRopeFrom), toVec(t::kRopeTo), Vec2::Zero(), t::kChassisAngle,
       "createRope(world, chassis, arm, anchorA, anchorB, maxLength)"},
  };
  const char* frames =
      "Initialize(...) turns the world anchors and axis into each body's frame; set by hand, "
      "use body->GetLocalPoint(worldAnchor) and bodyA->GetLocalVector(axis)";
  for (const Expected& e : expected) {
    const JointInfo* j = nullptr;
    for (const JointInfo& candidate : r.builtJoints) {
      if (candidate.type == e.type && candidate.bodyA == e.bodyA && candidate.bodyB == e.bodyB) {
        j = &candidate;
      }
    }
    if (j == nullptr) {
      ADD_FAILURE() << currentTask() << ": no " << e.type << " joint " << bodyName(r, e.bodyA)
                    << " - " << bodyName(r, e.bodyB) << " from " << e.call << ". "
                    << built("turned", r);
      continue;
    }
    const std::string which = std::string(e.call) + " on turned bodies built: " + describe(r, *j);
    EXPECT_VEC_NEAR(j->anchorA, e.anchorA, inScene(1e-5)) << which << hint(frames);
    EXPECT_VEC_NEAR(j->anchorB, e.anchorB, inScene(1e-5)) << which << hint(frames);
    if (e.axis == Vec2::Zero()) continue;
    const double length = j->localAxisA.norm();
    // Compared as a direction: Box2D normalises a prismatic axis, not a wheel axis.
    const Vec2 localAxisA = length > 0 ? Vec2(j->localAxisA / length) : j->localAxisA;
    EXPECT_VEC_NEAR(localAxisA, intoBody(e.axis, e.angleA), inScene(1e-5))
        << which << ", the world axis " << str(e.axis) << ", bodyA turned by " << num(e.angleA)
        << " rad" << hint(frames);
  }
}

// Mouse joint ---------------------------------------------------------------------------------

// Where the mouse_drag scene's box is after one step: a point on the box to grab.
Vec2 boxPosition() {
  const Box2DResult r = runScene("mouse_drag", 1);
  return r.ok() && !r.poses.empty() && !r.poses[0].empty() ? r.poses[0][0].position : Vec2(0, 0.25);
}

// The mouse joint as beginDrag returned it, grabbed at the box's centre; stops the check when
// there is none.
#define A6_GRAB_THE_BOX(r, j, grab)                                                               \
  const Vec2 grab = boxPosition();                                                                \
  const Box2DResult r = runScene("mouse_drag", 2, {{DragEvent::Kind::Begin, 0, grab}});           \
  A6_ASSERT_RAN(r);                                                                               \
  ASSERT_EQ(r.bodies.size(), 1u);                                                                 \
  ASSERT_EQ(r.dragJoints.size(), 1u)                                                              \
      << currentTask() << ": beginDrag at " << str(grab) << " returned no joint"                  \
      << hint("beginDrag must create a b2MouseJoint with world.CreateJoint(&def) and return it"); \
  const JointInfo& j = r.dragJoints[0]

std::string grabbed(const Box2DResult& r, const JointInfo& j) {
  return "mouse joint as beginDrag returned it: " + describe(r, j) + ", box mass " +
         num(r.bodies[0].mass) + " kg";
}

// The mouse joint's set-up, a part each: a drag that works with other constants loses only the
// constant that is off.
TEST(Task6Joints, MouseJointHoldsTheBoxAtTheTarget) {
  A6_GRAB_THE_BOX(r, j, grab);
  EXPECT_TRUE(isJoint(r, j, "mouse", -1, 0))
      << hint("b2MouseJointDef has no Initialize(): set def.bodyA = ground, def.bodyB = body");
  EXPECT_VEC_NEAR(j.target, grab, inScene(1e-5)) << grabbed(r, j) << hint("def.target = target");
}

TEST(Task6Joints, MouseJointMaxForceScalesWithTheMass) {
  A6_GRAB_THE_BOX(r, j, grab);
  const double m = r.bodies[0].mass;
  EXPECT_CLOSE(j.maxForce, 1000 * m, relTol(1000 * m, 1e-5))
      << grabbed(r, j)
      << hint("def.maxForce = 1000 * body->GetMass(): a force that scales with the body");
}

TEST(Task6Joints, MouseJointIsAFiveHertzSpringWithDampingRatio07) {
  A6_GRAB_THE_BOX(r, j, grab);
  // The ground is static (mass 0): b2LinearStiffness uses the box's mass alone.
  const StiffnessDamping expected = linearStiffness(5.0, 0.7, 0.0, r.bodies[0].mass);
  EXPECT_CLOSE(j.stiffness, expected.stiffness, relTol(expected.stiffness, 1e-4))
      << grabbed(r, j)
      << hint(
             "b2LinearStiffness(def.stiffness, def.damping, 5.0f, 0.7f, ground, body): with a "
             "static ground, m = the body's mass, stiffness = m (2π 5 Hz)²");
  EXPECT_CLOSE(j.damping, expected.damping, relTol(expected.damping, 1e-4))
      << grabbed(r, j) << hint("damping = 2 m 0.7 (2π 5 Hz), from the same b2LinearStiffness call");
}

TEST(Task6Joints, MouseDragWakesASleepingBody) {
  // The box rests on the floor (a static body of its own) until Box2D puts it to sleep; a drag
  // begun then (at its centre, the target never moved) must wake it, or the joint does nothing
  // until the mouse moves. The scene runs no joint of the student's before the drag.
  const int sleepy = 150;  // 2.5 s: Box2D sleeps a body after 0.5 s at rest
  const Box2DResult rest = runScene("mouse_drag", sleepy);
  A6_ASSERT_RAN(rest);
  ASSERT_FALSE(rest.poses.empty() || rest.poses.back().empty());
  ASSERT_FALSE(rest.poses.back()[0].awake)
      << "the box should be asleep after " << sleepy << " steps";
  const Vec2 grab = rest.poses.back()[0].position;
  const Box2DResult r =
      runScene("mouse_drag", sleepy + 1, {{DragEvent::Kind::Begin, sleepy, grab}});
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.dragJoints.size(), 1u) << currentTask() << ": beginDrag returned no joint";
  EXPECT_TRUE(r.poses.back()[0].awake)
      << currentTask() << ": a drag begun on the sleeping box at " << str(grab) << " left it asleep"
      << hint("beginDrag must wake the body: body->SetAwake(true)");
}

TEST(Task6Joints, EndDragSetsTheCallersPointerToNull) {
  const Vec2 grab = boxPosition();
  const Box2DResult r = runScene(
      "mouse_drag", 3, {{DragEvent::Kind::Begin, 0, grab}, {DragEvent::Kind::End, 1, grab}});
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.dragJoints.size(), 1u) << currentTask() << ": beginDrag returned no joint";
  ASSERT_EQ(r.endDragCleared.size(), 1u);
  EXPECT_EQ(r.endDragCleared[0], 1)
      << currentTask() << ": after endDrag the caller's pointer still points at the destroyed "
      << "joint"
      << hint(
             "endDrag takes the pointer by reference: joint = nullptr after "
             "world.DestroyJoint(joint), so the caller never uses a dead joint");
}

TEST(Task6Joints, MouseDragPullsTheBoxToTheTarget) {
  // Grab the box at its centre, move the target 1 m right and 2 m up: after 2 s the box hangs
  // at the target (a 5 Hz spring sags by g / ω² = 1 cm).
  const Vec2 grab = boxPosition(), target = grab + Vec2(1, 2);
  const int steps = 120;
  const Box2DResult r = runScene(
      "mouse_drag", steps, {{DragEvent::Kind::Begin, 0, grab}, {DragEvent::Kind::Move, 1, target}});
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.dragJoints.size(), 1u)
      << currentTask() << ": beginDrag at " << str(grab) << " returned no joint"
      << hint("beginDrag must create a b2MouseJoint and return it");
  EXPECT_VEC_NEAR(r.poses.back()[0].position, target, inScene(0.05))
      << "box after " << num(steps * kDt) << " s of a drag grabbed at " << str(grab)
      << " and moved to " << str(target) << "; " << describe(r, r.dragJoints[0])
      << hint(
             "moveDrag must call joint->SetTarget(target); beginDrag needs maxForce, "
             "stiffness and damping set, and must wake the body");
}

TEST(Task6Joints, MouseDragMovesThePointItGrabbed) {
  // Grab the box 20 cm right of and 15 cm above its centre: the joint holds the box there. Move
  // the target 1 m right and 2 m up: after 2 s the box hangs from the point it was grabbed at,
  // and that point is at the target (the solution: 1.3 cm off, the 5 Hz spring's sag and swing; a
  // joint anchored at the box's centre leaves the grabbed point 20 cm away).
  const Vec2 centre = boxPosition(), offset(0.2, 0.15), grab = centre + offset,
             target = grab + Vec2(1, 2);
  const int steps = 120;
  const Box2DResult r = runScene(
      "mouse_drag", steps, {{DragEvent::Kind::Begin, 0, grab}, {DragEvent::Kind::Move, 1, target}});
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.dragJoints.size(), 1u)
      << currentTask() << ": beginDrag at " << str(grab) << " returned no joint"
      << hint("beginDrag must create a b2MouseJoint and return it");
  // Where the joint holds the box, as beginDrag returned it (before any step): the grabbed point.
  EXPECT_VEC_NEAR(r.dragJoints[0].anchorB, grab, inScene(1e-5))
      << "the mouse joint's anchor on the box; " << grabbed(r, r.dragJoints[0])
      << hint(
             "def.target = target before world.CreateJoint(&def): Box2D anchors the joint on the "
             "body where the target is when the joint is made");
  const auto& box = r.poses.back()[0];
  const double c = std::cos(box.angle), sn = std::sin(box.angle);
  const Vec2 grabbedPoint =
      box.position + Vec2(c * offset.x() - sn * offset.y(), sn * offset.x() + c * offset.y());
  EXPECT_VEC_NEAR(grabbedPoint, target, inScene(0.05))
      << "the point of the box grabbed at " << str(grab) << " (" << str(offset)
      << " from its centre), after " << num(steps * kDt) << " s of a drag moved to " << str(target)
      << "; the box's centre is at " << str(box.position) << "; " << describe(r, r.dragJoints[0])
      << hint(
             "def.target = target in beginDrag: Box2D anchors the joint on the body where the "
             "target is when the joint is made, so set it before CreateJoint, not after");
}

TEST(Task6Joints, MouseJointIsDestroyedWhenTheDragEnds) {
  // Two drags one after the other: the world holds one more joint only while a drag lasts, and
  // the box falls back once released.
  const Vec2 grab = boxPosition(), lifted = grab + Vec2(0, 2);
  const int steps = 130;
  const std::vector<DragEvent> script = {{DragEvent::Kind::Begin, 10, grab},
                                         {DragEvent::Kind::Move, 11, lifted},
                                         {DragEvent::Kind::End, 70, lifted},
                                         {DragEvent::Kind::Begin, 100, grab},
                                         {DragEvent::Kind::End, 110, grab}};
  const Box2DResult r = runScene("mouse_drag", steps, script);
  A6_ASSERT_RAN(r);
  ASSERT_EQ(r.dragJoints.size(), 2u)
      << currentTask() << ": two drags (steps 10-70 and 100-110, 0-based), beginDrag returned "
      << r.dragJoints.size() << " joints" << hint("beginDrag must create and return the joint");
  ASSERT_EQ(r.jointCounts.size(), static_cast<std::size_t>(steps));
  const int before = static_cast<int>(r.builtJoints.size());
  for (int s = 0; s < steps; ++s) {
    const bool dragging = (s >= 10 && s < 70) || (s >= 100 && s < 110);
    ASSERT_EQ(r.jointCounts[s], before + (dragging ? 1 : 0))
        << currentTask() << ": world joint count after " << s + 1 << " steps, with drags "
        << "begun at the start of steps 10 and 100 and ended at the start of steps 70 and 110 "
        << "(0-based); the scene has " << before << " joints of its own"
        << hint("endDrag must destroy the joint: world.DestroyJoint(joint); joint = nullptr");
  }
  const double held = r.poses[69][0].position.y(), released = r.poses[99][0].position.y();
  EXPECT_LT(released, held - 1.0) << currentTask() << ": box at y=" << num(held)
                                  << " m when released (after 70 steps), at y=" << num(released)
                                  << " m 0.5 s later"
                                  << hint("once the drag ends nothing may hold the box");
}

}  // namespace task6_joints
}  // namespace a6::test
