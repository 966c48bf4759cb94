// Task 6, Box2D joints. Box2D runs in the probe only, so these mistakes are recognised by what
// the student's joints show in the answer, beside what the scene asks of them (its parameters,
// scenes/box2d_scenes.h, and the bodies' masses the answer lists): a limit left off, a motor
// turned the wrong way, a spring of the wrong frequency, a joint left in the world.
#include <cmath>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"
#include "reference/joints.h"
#include "scenes/box2d_scenes.h"

namespace a6::grader::mistakes {
namespace {

using harness::Box2DResult;
using harness::DragEvent;
using harness::JointInfo;
namespace p = box2d_params;

constexpr double kFloat = 1e-3;  // Box2D keeps its joints in float: relative closeness

bool close(double a, double b) { return std::abs(a - b) <= kFloat * std::max(1.0, std::abs(b)); }

using JointLikeness = std::function<Likeness(const Box2DResult&, const JointInfo&)>;

// One likeness per joint of `type` built in `scene` (or, for "mouse", per drag joint).
MistakeModel jointModel(const char* id, const char* scene, const char* type, JointLikeness judge,
                        const char* text) {
  std::string sceneName = scene, typeName = type;
  auto all = [sceneName, typeName, judge](const Transcript& t) {
    std::vector<Likeness> out;
    for (const auto& x : t.of<harness::Box2DRequest>()) {
      if (x.request.scene != sceneName) continue;
      const auto& joints = typeName == "mouse" ? x.result.dragJoints : x.result.builtJoints;
      for (const JointInfo& j : joints) {
        if (j.type == typeName) out.push_back(judge(x.result, j));
      }
    }
    return out;
  };
  return MistakeModel{id, 6, text, all};
}

double massOf(const Box2DResult& r, int body) {
  return body >= 0 && body < static_cast<int>(r.bodies.size())
             ? r.bodies[static_cast<std::size_t>(body)].mass
             : 0;
}

// The stiffness of a spring of `hertz` between the joint's two bodies (reference/joints.h).
double stiffnessOf(const Box2DResult& r, const JointInfo& j, double hertz) {
  return reference::referenceJointStiffness(massOf(r, j.bodyA), massOf(r, j.bodyB), hertz);
}

Likeness hingeAtCentre(const Box2DResult&, const JointInfo& j) {
  const Vec2 pivot(p::kPivot.x, p::kPivot.y);
  return shows(j.localAnchorB.norm() < 1e-4, (j.anchorA - pivot).norm() < 1e-3);
}
Likeness pistonLimits(const Box2DResult&, const JointInfo& j) {
  return shows(!j.enableLimit,
               j.enableLimit && close(j.lower, p::kPistonLower) && close(j.upper, p::kPistonUpper));
}
Likeness ropeRigid(const Box2DResult&, const JointInfo& j) {
  return shows(std::abs(j.maxLength - j.minLength) < 1e-4,
               j.minLength < 1e-4 && close(j.maxLength, p::kRopeMaxLength));
}
Likeness motorSign(const Box2DResult&, const JointInfo& j) {
  return shows(close(j.motorSpeed, -p::kCarMotorSpeed), close(j.motorSpeed, p::kCarMotorSpeed));
}
Likeness wheelSpring(const Box2DResult& r, const JointInfo& j) {
  return shows(j.stiffness == 0 && j.damping == 0,
               close(j.stiffness, stiffnessOf(r, j, p::kWheelHertz)));
}
// The "turned" scene: bodyA turned by `angle`; a world vector in its frame, and the closeness of
// two vectors.
Vec2 intoBody(const b2Vec2& world, float angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * world.x + s * world.y, -s * world.x + c * world.y);
}
bool closeVec(const Vec2& a, const Vec2& b) { return (a - b).norm() <= kFloat; }
Likeness axisInWorldFrame(const Box2DResult&, const JointInfo& j) {
  namespace t = p::turned;
  const Vec2 world(t::kPistonAxis.x, t::kPistonAxis.y);
  return shows(closeVec(j.localAxisA, world),
               closeVec(j.localAxisA, intoBody(t::kPistonAxis, t::kFrameAngle)));
}
Likeness offsetsNotTurned(const Box2DResult&, const JointInfo& j) {
  namespace t = p::turned;
  const b2Vec2 offset = t::kHingeAt - t::kFrameAt;
  return shows(closeVec(j.localAnchorA, Vec2(offset.x, offset.y)),
               closeVec(j.localAnchorA, intoBody(offset, t::kFrameAngle)));
}
Likeness mouseMaxForce(const Box2DResult& r, const JointInfo& j) {
  const double mass = massOf(r, j.bodyB);
  if (close(mass, 1)) return Likeness::Uninformative;
  const double perKilogram = reference::kMouseForcePerKilogram;
  return shows(close(j.maxForce, perKilogram), close(j.maxForce, perKilogram * mass));
}
Likeness mouseFrequency(const Box2DResult& r, const JointInfo& j) {
  const double expected = stiffnessOf(r, j, reference::kMouseHertz);
  return shows(j.stiffness > 0 && !close(j.stiffness, expected), close(j.stiffness, expected));
}

// Drags whose end the answer shows: the world's joint count at the step an end came, against
// the step before (one fewer), and the caller's pointer after each endDrag (null).
// How many joints step `step` of the run added (+1) or removed (-1): jointCounts[k] holds the
// joints after step k, builtJoints those before step 0. 0 where it cannot tell.
int jointChange(const harness::Box2DResult& r, int step) {
  const auto s = static_cast<std::size_t>(step);
  if (step < 0 || s >= r.jointCounts.size()) return 0;
  const int before = step == 0 ? static_cast<int>(r.builtJoints.size()) : r.jointCounts[s - 1];
  return r.jointCounts[s] - before;
}
// A drag's end where its beginning made a joint: one joint less after it (the stubs of the
// starter make none, so they neither destroy nor forget one).
std::vector<Likeness> jointsDestroyed(const Transcript& t) {
  std::vector<Likeness> out;
  for (const auto& x : t.of<harness::Box2DRequest>()) {
    bool made = false;
    for (const DragEvent& e : x.request.drag) {
      if (e.kind == DragEvent::Kind::Begin) made = jointChange(x.result, e.step) == 1;
      if (e.kind != DragEvent::Kind::End || !made) continue;
      const int change = jointChange(x.result, e.step);
      out.push_back(shows(change == 0, change == -1));
    }
  }
  return out;
}
std::vector<Likeness> pointersCleared(const Transcript& t) {
  std::vector<Likeness> out;
  for (const auto& x : t.of<harness::Box2DRequest>()) {
    for (const int cleared : x.result.endDragCleared)
      out.push_back(shows(cleared == 0, cleared == 1));
  }
  return out;
}
// A drag begun on a sleeping body: awake after that step.
std::vector<Likeness> bodiesWoken(const Transcript& t) {
  std::vector<Likeness> out;
  for (const auto& x : t.of<harness::Box2DRequest>()) {
    std::size_t drag = 0;
    for (const DragEvent& e : x.request.drag) {
      if (e.kind != DragEvent::Kind::Begin || drag >= x.result.dragJoints.size()) continue;
      const int body = x.result.dragJoints[drag++].bodyB;
      const auto s = static_cast<std::size_t>(e.step);
      const auto& poses = x.result.poses;
      if (e.step < 1 || s >= poses.size() || body < 0) continue;
      const auto b = static_cast<std::size_t>(body);
      if (b >= poses[s].size() || b >= poses[s - 1].size() || poses[s - 1][b].awake) continue;
      out.push_back(shows(!poses[s][b].awake, poses[s][b].awake));
    }
  }
  return out;
}

}  // namespace

std::vector<MistakeModel> task6Mistakes() {
  return {
      jointModel("t6_hinge_anchor_at_body_center", "pendulum", "revolute", hingeAtCentre,
                 "Your hinge behaves exactly like one anchored at body b's centre, "
                 "b->GetPosition(), instead of the world anchor passed in: the pendulum's bob is "
                 "pinned through itself; Initialize(a, b, worldAnchor)."),
      jointModel("t6_piston_no_limits", "piston", "prismatic", pistonLimits,
                 "Your piston behaves exactly like one whose limits are set but never enabled: "
                 "set enableLimit = true, or the motor drives it on forever."),
      jointModel("t6_piston_axis_in_world_frame", "turned", "prismatic", axisInWorldFrame,
                 "Your piston behaves exactly like one whose axis is the world axis stored as "
                 "the first body's local axis: right only while that body is not turned; "
                 "Initialize(ground, piston, worldAnchor, axis), or localAxisA = "
                 "ground->GetLocalVector(axis)."),
      jointModel("t6_hinge_anchor_offsets_not_turned", "turned", "revolute", offsetsNotTurned,
                 "Your hinge behaves exactly like one whose local anchors are the world offsets "
                 "from each body's centre, not turned into the body's frame: right only for "
                 "unturned bodies; Initialize(a, b, worldAnchor), or localAnchorA = "
                 "a->GetLocalPoint(worldAnchor)."),
      jointModel("t6_rope_rigid", "rope", "distance", ropeRigid,
                 "Your rope behaves exactly like a rigid rod: Initialize sets minLength = "
                 "maxLength = the current distance; a rope needs minLength = 0 and maxLength = "
                 "its full length."),
      jointModel("t6_wheel_motor_wrong_sign", "car", "wheel", motorSign,
                 "Your wheel motor behaves exactly like one whose speed is negated: the car "
                 "drives backwards; pass motorSpeed on as given (negative is clockwise)."),
      jointModel("t6_wheel_no_spring", "car", "wheel", wheelSpring,
                 "Your wheel joint behaves exactly like one with no suspension spring (stiffness "
                 "and damping 0): call b2LinearStiffness(def.stiffness, def.damping, hertz, "
                 "dampingRatio, chassis, wheel)."),
      jointModel("t6_mouse_maxforce_without_mass", "mouse_drag", "mouse", mouseMaxForce,
                 "Your mouse joint behaves exactly like one whose maxForce is 1000 N whatever the "
                 "body: the testbed uses 1000 times the body's mass."),
      jointModel("t6_mouse_spring_wrong_frequency", "mouse_drag", "mouse", mouseFrequency,
                 "Your mouse joint's spring is not the testbed's 5 Hz: b2LinearStiffness(def."
                 "stiffness, def.damping, 5.0f, 0.7f, ground, body)."),
      MistakeModel{"t6_mouse_joint_not_destroyed", 6,
                   "Your endDrag behaves exactly like one that forgets the joint instead of "
                   "destroying it: the world keeps holding the body; call "
                   "world.DestroyJoint(joint).",
                   jointsDestroyed},
      MistakeModel{"t6_end_drag_keeps_pointer", 6,
                   "Your endDrag behaves exactly like one that destroys the joint but leaves the "
                   "caller's pointer on it: set joint = nullptr after world.DestroyJoint(joint).",
                   pointersCleared},
      MistakeModel{"t6_begin_drag_leaves_body_asleep", 6,
                   "Your beginDrag behaves exactly like one that does not wake the body: a "
                   "sleeping body ignores the drag; call body->SetAwake(true).",
                   bodiesWoken},
  };
}

}  // namespace a6::grader::mistakes
