// Task 6 — Box2D 2.4 joints
// Slide: "Box2D joints".
//
// Each function creates one joint with world.CreateJoint(&def) and returns it (cast to its
// type). Most joint definitions have an Initialize(bodyA, bodyB, anchor, ...) that computes
// the local anchors for you from a WORLD point; use it.
//
//     createHinge   b2RevoluteJointDef   Initialize(a, b, worldAnchor)
//     createRope    b2DistanceJointDef   Initialize(a, b, anchorA, anchorB); then minLength = 0,
//                                        maxLength = maxLength, stiffness = damping = 0
//                                        (Box2D 2.4 has no rope joint: this is it)
//     createPiston  b2PrismaticJointDef  Initialize(ground, piston, worldAnchor, axis);
//                                        enableLimit, lower/upperTranslation, enableMotor,
//                                        motorSpeed, maxMotorForce
//     createWheel   b2WheelJointDef      Initialize(chassis, wheel, wheel->GetPosition(), axis);
//                                        b2LinearStiffness(def.stiffness, def.damping, hertz,
//                                        dampingRatio, chassis, wheel); enableMotor, motorSpeed,
//                                        maxMotorTorque
//     beginDrag     b2MouseJointDef      NO Initialize(): set bodyA = ground, bodyB = body,
//                                        target, maxForce = 1000 * body->GetMass(), and
//                                        stiffness/damping from b2LinearStiffness(.., 5 Hz, 0.7,
//                                        ground, body); wake the body (SetAwake(true))
//     moveDrag      joint->SetTarget(target)
//     endDrag       world.DestroyJoint(joint); joint = nullptr
//
// Done when: `ctest -R Task6` passes (tests named Task6Joints.*): joint types and anchors, the
// pendulum's period, the reaction force at rest, the piston's limits, the car driving forward,
// and dragging with the mouse joint.
#include "a6/joints.h"

namespace a6 {

b2RevoluteJoint* createHinge(b2World& world, b2Body* a, b2Body* b, const b2Vec2& worldAnchor) {
  // TODO(task 6)
  return nullptr;
}

b2DistanceJoint* createRope(b2World& world, b2Body* a, b2Body* b, const b2Vec2& anchorA,
                            const b2Vec2& anchorB, float maxLength) {
  // TODO(task 6)
  return nullptr;
}

b2PrismaticJoint* createPiston(b2World& world, b2Body* ground, b2Body* piston,
                               const b2Vec2& worldAnchor, const b2Vec2& axis, float lower,
                               float upper, float motorSpeed, float maxMotorForce) {
  // TODO(task 6)
  return nullptr;
}

b2WheelJoint* createWheel(b2World& world, b2Body* chassis, b2Body* wheel, const b2Vec2& axis,
                          float hertz, float dampingRatio, float motorSpeed, float maxMotorTorque) {
  // TODO(task 6)
  return nullptr;
}

b2MouseJoint* beginDrag(b2World& world, b2Body* ground, b2Body* body, const b2Vec2& target) {
  // TODO(task 6)
  return nullptr;
}

void moveDrag(b2MouseJoint* joint, const b2Vec2& target) {
  // TODO(task 6)
}

void endDrag(b2World& world, b2MouseJoint*& joint) {
  // TODO(task 6)
}

}  // namespace a6
