// Task 6 — Box2D 2.4 joints
#include "a6/joints.h"

namespace a6 {

b2RevoluteJoint* createHinge(b2World& world, b2Body* a, b2Body* b, const b2Vec2& worldAnchor) {
  b2RevoluteJointDef def;
  def.Initialize(a, b, worldAnchor);
  return static_cast<b2RevoluteJoint*>(world.CreateJoint(&def));
}

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

void moveDrag(b2MouseJoint* joint, const b2Vec2& target) {
  if (joint) joint->SetTarget(target);
}

void endDrag(b2World& world, b2MouseJoint*& joint) {
  if (joint) world.DestroyJoint(joint);
  joint = nullptr;
}

}  // namespace a6
