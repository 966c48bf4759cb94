// Task 6 measured: the joints of the piston, rope and car scenes as Box2D holds them right after
// building, and the mouse joint of a drag, each parameter set beside what the scene's constants
// (scenes/box2d_scenes.h) and Box2D's rules (reference/joints.h: b2LinearStiffness, the mouse
// joint's 1000 N/kg and 5 Hz) make it. Box2D keeps its joints in float: a parameter differs when
// it is off by more than 1e-3 of its size.
#include "reference/joints.h"

#include <cmath>

#include "mistakes/library/measured/tasks.h"
#include "scenes/box2d_scenes.h"

namespace a6::grader::measured {
namespace {

namespace params = box2d_params;

// One parameter: its name, the student's value, Box2D's, and where Box2D's comes from.
struct Parameter {
  const char* name;
  double yours, physics;
  const char* why;
};

double massOf(const harness::Box2DResult& r, int body) {
  return body >= 0 && body < static_cast<int>(r.bodies.size())
             ? r.bodies[static_cast<std::size_t>(body)].mass
             : 0;
}

std::vector<Parameter> pistonParameters(const harness::JointInfo& j, int k) {
  const double sign = k == 0 ? 1 : -1;  // the second piston is driven down into its lower limit
  return {{"enableLimit", j.enableLimit ? 1.0 : 0.0, 1, "the piston has limits"},
          {"lowerTranslation", j.lower, k == 0 ? params::kPistonLower : -params::kPistonUpper,
           "the scene's limits"},
          {"upperTranslation", j.upper, k == 0 ? params::kPistonUpper : params::kPistonLower,
           "the scene's limits"},
          {"enableMotor", j.enableMotor ? 1.0 : 0.0, 1, "the piston is driven"},
          {"motorSpeed", j.motorSpeed, sign * params::kPistonSpeed, "the scene's speed"},
          {"maxMotorForce", j.maxMotor, params::kPistonMaxForce, "the scene's force"}};
}

std::vector<Parameter> ropeParameters(const harness::JointInfo& j, int) {
  return {{"minLength", j.minLength, b2_linearSlop,
           "a rope goes slack: minLength 0, which Box2D keeps as b2_linearSlop"},
          {"maxLength", j.maxLength, params::kRopeMaxLength, "the scene's rope length"}};
}

std::vector<Parameter> wheelParameters(const harness::Box2DResult& r, const harness::JointInfo& j) {
  const double a = massOf(r, j.bodyA), b = massOf(r, j.bodyB);
  const char* spring = "b2LinearStiffness at the scene's 4 Hz and damping ratio 0.7";
  return {{"stiffness", j.stiffness, reference::referenceJointStiffness(a, b, params::kWheelHertz),
           spring},
          {"damping", j.damping,
           reference::referenceJointDamping(a, b, params::kWheelHertz, params::kWheelDampingRatio),
           spring},
          {"enableMotor", j.enableMotor ? 1.0 : 0.0, 1, "the wheels are driven"},
          {"motorSpeed", j.motorSpeed, params::kCarMotorSpeed, "the scene's speed"},
          {"maxMotorTorque", j.maxMotor, params::kCarMaxTorque, "the scene's torque"}};
}

std::vector<Parameter> mouseParameters(const harness::Box2DResult& r, const harness::JointInfo& j) {
  const double m = massOf(r, j.bodyB);
  const char* spring = "b2LinearStiffness at 5 Hz and damping ratio 0.7, as the testbed";
  return {{"maxForce", j.maxForce, reference::kMouseForcePerKilogram * m,
           "1000 N per kilogram of the body, as the testbed"},
          {"stiffness", j.stiffness,
           reference::referenceJointStiffness(0, m, reference::kMouseHertz), spring},
          {"damping", j.damping,
           reference::referenceJointDamping(0, m, reference::kMouseHertz,
                                            reference::kMouseDampingRatio),
           spring}};
}

// The parameters that differ, in one finding for the joint.
Finding jointFinding(const std::string& tag, const std::string& joint,
                     const std::vector<Parameter>& ps) {
  Finding f;
  f.tag = tag, f.part = joint;
  f.verdict = Verdict::Right;
  for (const Parameter& p : ps) {
    if (std::abs(p.yours - p.physics) <= 1e-3 * std::max(1.0, std::abs(p.physics))) continue;
    f.verdict = Verdict::Differs;
    f.how += std::string(f.how.empty() ? "holds " : "; ") + p.name + " = " + number(p.yours) +
             " where Box2D should hold " + number(p.physics) + " (" + p.why + ")";
  }
  return f;
}

harness::Box2DRequest sceneRequest(const char* scene, int steps) {
  harness::Box2DRequest r;
  r.scene = scene;
  r.steps = steps;
  return r;
}

}  // namespace

void designJoints(std::vector<Designed>& out) {
  out.push_back(designed("t6.built", sceneRequest("piston", 1)));
  out.push_back(designed("t6.built", sceneRequest("rope", 1)));
  out.push_back(designed("t6.built", sceneRequest("car", 1)));
  harness::Box2DRequest drag = sceneRequest("mouse_drag", 2);
  drag.drag = {{harness::DragEvent::Kind::Begin, 0, Vec2(0, 0.25)}};  // the box's centre
  out.push_back(designed("t6.drag", drag));
}

std::vector<Finding> measureJoints(const Transcript& t) {
  std::vector<Finding> out;
  for (const auto& x : answersTo<harness::Box2DRequest>(t, "t6.built")) {
    int pistons = 0;
    for (const harness::JointInfo& j : x.result.builtJoints) {
      if (x.request.scene == "piston" && j.type == "prismatic" && pistons < 2)
        out.push_back(jointFinding("piston",
                                   "piston's prismatic joint " + std::to_string(pistons + 1),
                                   pistonParameters(j, pistons))),
            ++pistons;
      if (x.request.scene == "rope" && j.type == "distance")
        out.push_back(jointFinding("rope", "rope's distance joint", ropeParameters(j, 0)));
      if (x.request.scene == "car" && j.type == "wheel")
        out.push_back(jointFinding("wheel", "car's wheel joint", wheelParameters(x.result, j)));
    }
  }
  for (const auto& x : answersTo<harness::Box2DRequest>(t, "t6.drag")) {
    for (const harness::JointInfo& j : x.result.dragJoints)
      out.push_back(jointFinding("mouse", "mouse joint", mouseParameters(x.result, j)));
  }
  // One finding per kind of joint: the first that differs (the car's two wheels are alike).
  std::vector<Finding> kept;
  for (const Finding& f : out) {
    bool seen = false;
    for (const Finding& k : kept) seen = seen || k.tag == f.tag;
    if (!seen || f.verdict == Verdict::Differs) {
      if (seen) {
        for (Finding& k : kept) {
          if (k.tag == f.tag && k.verdict == Verdict::Right) k = f;
        }
      } else {
        kept.push_back(f);
      }
    }
  }
  return kept;
}

}  // namespace a6::grader::measured
