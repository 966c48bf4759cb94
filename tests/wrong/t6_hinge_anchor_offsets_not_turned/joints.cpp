// WRONG VERSION (task 6): createHinge sets the joint up by hand with each local anchor the world
// offset from the body's centre, not turned into its frame: right only for unturned bodies.
// Task 6 — Box2D 2.4 joints (slide "Box2D joints").
#include "a6/joints.h"

namespace a6 {

// Revolute joint: a hinge at a world point.
b2RevoluteJoint* createHinge(b2World& world, b2Body* a, b2Body* b, const b2Vec2& worldAnchor) {
  b2RevoluteJointDef def;
  // Wrong: set by hand, the offsets from each body's centre not turned into its frame.
  def.bodyA = a;
  def.bodyB = b;
  def.localAnchorA = worldAnchor - a->GetPosition();
  def.localAnchorB = worldAnchor - b->GetPosition();
  def.referenceAngle = b->GetAngle() - a->GetAngle();
  return static_cast<b2RevoluteJoint*>(world.CreateJoint(&def));
}

// Rope: a distance joint that may shorten (minLength 0) but never stretch past maxLength.
b2DistanceJoint* createRope(b2World& world, b2Body* a, b2Body* b, const b2Vec2& anchorA,
                            const b2Vec2& anchorB, float maxLength) {
  b2DistanceJointDef def;
  def.Initialize(a, b, anchorA, anchorB);
  def.minLength = 0.0f;
  def.maxLength = maxLength;
  def.stiffness = 0.0f;
  def.damping = 0.0f;
  return static_cast<b2DistanceJoint*>(world.CreateJoint(&def));
}

// Prismatic joint: slides along an axis, with limits and a motor.
b2PrismaticJoint* createPiston(b2World& world, b2Body* ground, b2Body* piston,
                               const b2Vec2& worldAnchor, const b2Vec2& axis, float lower,
                               float upper, float motorSpeed, float maxMotorForce) {
  b2PrismaticJointDef def;
  def.Initialize(ground, piston, worldAnchor, axis);
  def.enableLimit = true;
  def.lowerTranslation = lower;
  def.upperTranslation = upper;
  def.enableMotor = true;
  def.motorSpeed = motorSpeed;
  def.maxMotorForce = maxMotorForce;
  return static_cast<b2PrismaticJoint*>(world.CreateJoint(&def));
}

// Wheel joint: a suspension spring along the axis and a motor on the wheel.
b2WheelJoint* createWheel(b2World& world, b2Body* chassis, b2Body* wheel, const b2Vec2& axis,
                          float hertz, float dampingRatio, float motorSpeed, float maxMotorTorque) {
  b2WheelJointDef def;
  def.Initialize(chassis, wheel, wheel->GetPosition(), axis);
  b2LinearStiffness(def.stiffness, def.damping, hertz, dampingRatio, chassis, wheel);
  def.enableMotor = true;
  def.motorSpeed = motorSpeed;
  def.maxMotorTorque = maxMotorTorque;
  return static_cast<b2WheelJoint*>(world.CreateJoint(&def));
}

// Mouse joint: no Initialize(); set every field by hand.
b2MouseJoint* beginDrag(b2World& world, b2Body* ground, b2Body* body, const b2Vec2& target) {
  b2MouseJointDef def;
  def.bodyA = ground;
  def.bodyB = body;
  def.target = target;
  def.maxForce = 1000.0f * body->GetMass();
  b2LinearStiffness(def.stiffness, def.damping, 5.0f, 0.7f, ground, body);
  body->SetAwake(true);
  return static_cast<b2MouseJoint*>(world.CreateJoint(&def));
}

void moveDrag(b2MouseJoint* joint, const b2Vec2& target) { joint->SetTarget(target); }

void endDrag(b2World& world, b2MouseJoint*& joint) {
  world.DestroyJoint(joint);
  joint = nullptr;
}

}  // namespace a6
