// Task 6: Box2D 2.4 joints (slide "Box2D joints").
//
// Box2D facts that its own 2.4 docs get wrong: there is no rope joint (a distance joint with a
// minimum and maximum length plays that part), and joint springs take a stiffness (N/m) and a
// damping (N·s/m), converted from a frequency (Hz) and a damping ratio with b2LinearStiffness
// or b2AngularStiffness.
//
// Every builder creates its joint in `world` and returns it; the world owns the joint (destroy
// it with world.DestroyJoint). Points and axes are in the world frame, in m; angles in rad.
#pragma once

#include <box2d/box2d.h>

namespace a6 {

/// Revolute joint at worldAnchor between a and b (pendulum pivot, bridge hinge). No limit, no
/// motor. Create it with b2RevoluteJointDef::Initialize.
b2RevoluteJoint* createHinge(b2World& world, b2Body* a, b2Body* b, const b2Vec2& worldAnchor);

/// A rope: a distance joint between anchorA (on a) and anchorB (on b) that goes slack when
/// shorter than maxLength and never stretches beyond it: minLength 0, maxLength = maxLength,
/// length = the current distance, no spring (stiffness 0, damping 0).
b2DistanceJoint* createRope(b2World& world, b2Body* a, b2Body* b, const b2Vec2& anchorA,
                            const b2Vec2& anchorB, float maxLength);

/// A piston: a prismatic joint at worldAnchor along the unit `axis` (world frame), with its
/// translation limited to [lower, upper] (m) and a motor driving it at motorSpeed (m/s) with at
/// most maxMotorForce (N).
b2PrismaticJoint* createPiston(b2World& world, b2Body* ground, b2Body* piston,
                               const b2Vec2& worldAnchor, const b2Vec2& axis, float lower,
                               float upper, float motorSpeed, float maxMotorForce);

/// Car suspension: a wheel joint anchored at the wheel's centre, sliding along the unit `axis`
/// (world frame, usually (0,1)), with a spring of frequency hertz (Hz) and dampingRatio
/// (converted with b2LinearStiffness), and a motor turning the wheel at motorSpeed (rad/s,
/// counter-clockwise positive) with at most maxMotorTorque (N·m).
b2WheelJoint* createWheel(b2World& world, b2Body* chassis, b2Body* wheel, const b2Vec2& axis,
                          float hertz, float dampingRatio, float motorSpeed, float maxMotorTorque);

/// Starts dragging `body` towards `target` with a mouse joint. b2MouseJointDef has no
/// Initialize(): set bodyA (the ground), bodyB, target, maxForce = 1000 × body mass, and the
/// stiffness and damping of a 5 Hz spring with damping ratio 0.7 (b2LinearStiffness), and wake
/// the body.
b2MouseJoint* beginDrag(b2World& world, b2Body* ground, b2Body* body, const b2Vec2& target);
/// Moves the drag target (world frame, m).
void moveDrag(b2MouseJoint* joint, const b2Vec2& target);
/// Ends the drag: destroys the joint and sets `joint` to nullptr.
void endDrag(b2World& world, b2MouseJoint*& joint);

}  // namespace a6
