// Alternative (correct) task 6: the same joints, their definitions filled in field by field
// with explicit local anchors (GetLocalPoint) instead of Initialize().
#include "a6/joints.h"

namespace a6 {

b2RevoluteJoint* createHinge(b2World& world, b2Body* a, b2Body* b, const b2Vec2& worldAnchor) {
  b2RevoluteJointDef def;
  def.bodyA = a;
  def.bodyB = b;
  def.localAnchorA = a->GetLocalPoint(worldAnchor);
  def.localAnchorB = b->GetLocalPoint(worldAnchor);
  def.referenceAngle = b->GetAngle() - a->GetAngle();
  return static_cast<b2RevoluteJoint*>(world.CreateJoint(&def));
}

b2DistanceJoint* createRope(b2World& world, b2Body* a, b2Body* b, const b2Vec2& anchorA,
                            const b2Vec2& anchorB, float maxLength) {
  b2DistanceJointDef def;
  def.bodyA = a;
  def.bodyB = b;
  def.localAnchorA = a->GetLocalPoint(anchorA);
  def.localAnchorB = b->GetLocalPoint(anchorB);
  def.length = b2Max(b2Distance(anchorA, anchorB), b2_linearSlop);
  def.maxLength = maxLength;
  def.minLength = 0.0f;
  def.damping = 0.0f;
  def.stiffness = 0.0f;
  return static_cast<b2DistanceJoint*>(world.CreateJoint(&def));
}

b2PrismaticJoint* createPiston(b2World& world, b2Body* ground, b2Body* piston,
                               const b2Vec2& worldAnchor, const b2Vec2& axis, float lower,
                               float upper, float motorSpeed, float maxMotorForce) {
  b2PrismaticJointDef def;
  def.bodyA = ground;
  def.bodyB = piston;
  def.localAnchorA = ground->GetLocalPoint(worldAnchor);
  def.localAnchorB = piston->GetLocalPoint(worldAnchor);
  def.localAxisA = ground->GetLocalVector(axis);
  def.referenceAngle = piston->GetAngle() - ground->GetAngle();
  def.maxMotorForce = maxMotorForce;
  def.motorSpeed = motorSpeed;
  def.enableMotor = true;
  def.upperTranslation = upper;
  def.lowerTranslation = lower;
  def.enableLimit = true;
  return static_cast<b2PrismaticJoint*>(world.CreateJoint(&def));
}

b2WheelJoint* createWheel(b2World& world, b2Body* chassis, b2Body* wheel, const b2Vec2& axis,
                          float hertz, float dampingRatio, float motorSpeed, float maxMotorTorque) {
  b2WheelJointDef def;
  def.bodyA = chassis;
  def.bodyB = wheel;
  const b2Vec2 centre = wheel->GetPosition();
  def.localAnchorA = chassis->GetLocalPoint(centre);
  def.localAnchorB = wheel->GetLocalPoint(centre);
  def.localAxisA = chassis->GetLocalVector(axis);
  def.maxMotorTorque = maxMotorTorque;
  def.motorSpeed = motorSpeed;
  def.enableMotor = true;
  b2LinearStiffness(def.stiffness, def.damping, hertz, dampingRatio, chassis, wheel);
  return static_cast<b2WheelJoint*>(world.CreateJoint(&def));
}

b2MouseJoint* beginDrag(b2World& world, b2Body* ground, b2Body* body, const b2Vec2& target) {
  body->SetAwake(true);
  b2MouseJointDef def;
  b2LinearStiffness(def.stiffness, def.damping, 5.0f, 0.7f, ground, body);
  def.maxForce = body->GetMass() * 1000.0f;
  def.target = target;
  def.bodyB = body;
  def.bodyA = ground;
  return static_cast<b2MouseJoint*>(world.CreateJoint(&def));
}

void moveDrag(b2MouseJoint* joint, const b2Vec2& target) { joint->SetTarget(target); }

void endDrag(b2World& world, b2MouseJoint*& joint) {
  b2MouseJoint* doomed = joint;
  joint = nullptr;
  world.DestroyJoint(doomed);
}

}  // namespace a6
