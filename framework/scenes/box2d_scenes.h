// The Box2D scenes of task 6, defined once: the framework builds the world and its bodies,
// the student's joint builders (a6/joints.h) connect them.
//
// Every scene fixes its time step and iteration counts: Box2D 2.4.1 damps the mouse joint's
// rotation per step, so results depend on them.
#pragma once

#include <box2d/box2d.h>

#include <memory>
#include <string>
#include <vector>

namespace a6 {

struct Box2DScene {
  std::string name;
  std::unique_ptr<b2World> world;
  b2Body* ground = nullptr;     ///< the static body every scene has
  std::vector<b2Body*> bodies;  ///< the dynamic bodies, in a fixed order (tests index them)
  std::vector<std::string> bodyNames;
  int dragBody = -1;        ///< index into bodies of the body a mouse drag picks, or -1
  float dt = 1.0f / 60.0f;  ///< s
  int velocityIterations = 8;
  int positionIterations = 3;

  /// One fixed step of the world.
  void step() { world->Step(dt, velocityIterations, positionIterations); }
  /// Index of a body in `bodies`, -1 for the ground, -2 for an unknown body.
  int indexOf(const b2Body* body) const;
};

/// The names of every Box2D scene: pendulum, hanging, rope, bridge, piston, car, mouse_drag.
const std::vector<std::string>& box2dSceneNames();
/// Builds a scene by name (the student's joints included); nullptr for an unknown name.
std::unique_ptr<Box2DScene> makeBox2DScene(const std::string& name);

/// Parameters the scenes use, so that the tests can state their expectations from them.
namespace box2d_params {
inline constexpr float kGravity = -9.81f;         ///< m/s²
inline constexpr float kPendulumLength = 1.0f;    ///< m, pivot to bob centre
inline constexpr float kPendulumAngle = 0.1f;     ///< rad, released from rest at this angle
inline const b2Vec2 kPivot{0.0f, 2.0f};           ///< m
inline constexpr float kBobRadius = 0.05f;        ///< m
inline constexpr float kRopeMaxLength = 1.5f;     ///< m
inline constexpr float kPistonLower = 0.0f;       ///< m
inline constexpr float kPistonUpper = 0.5f;       ///< m
inline constexpr float kPistonSpeed = 1.0f;       ///< m/s
inline constexpr float kPistonMaxForce = 500.0f;  ///< N
inline constexpr float kWheelHertz = 4.0f;        ///< Hz
inline constexpr float kWheelDampingRatio = 0.7f;
inline constexpr float kCarMotorSpeed = -15.0f;  ///< rad/s (clockwise: the car drives to +x)
inline constexpr float kCarMaxTorque = 40.0f;    ///< N·m
inline constexpr int kBridgePlanks = 10;
}  // namespace box2d_params

}  // namespace a6
