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

/// The names of every Box2D scene: pendulum, hanging, rope, bridge, piston, car, mouse_drag, and
/// turned (for the checks only: no picture shows it).
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

/// The scene "turned": one joint of each builder between bodies turned away from the world's
/// axes and away from the origin, where a point or an axis taken in the wrong frame shows (in
/// the other scenes the first body is the ground or unturned, so both frames agree there).
namespace turned {
inline const b2Vec2 kFrameAt{0.5f, 2.0f};   ///< m, the piston's and the hinge's first body
inline constexpr float kFrameAngle = 0.6f;  ///< rad
inline const b2Vec2 kSliderAt{1.3f, 2.4f};
inline constexpr float kSliderAngle = -0.4f;
inline const b2Vec2 kPistonAxis{0.6f, 0.8f};  ///< world, unit
inline const b2Vec2 kChassisAt{-1.5f, 1.0f};  ///< the wheel's and the rope's first body
inline constexpr float kChassisAngle = 0.35f;
inline const b2Vec2 kWheelAt{-1.9f, 0.5f};
inline constexpr float kWheelAngle = 0.9f;
inline const b2Vec2 kWheelAxis{-0.28f, 0.96f};  ///< world, unit
inline const b2Vec2 kArmAt{0.5f, 0.8f};
inline constexpr float kArmAngle = 1.1f;
inline const b2Vec2 kHingeAt{0.7f, 1.4f};    ///< world: frame - arm
inline const b2Vec2 kRopeFrom{-1.2f, 1.2f};  ///< world, on the chassis
inline const b2Vec2 kRopeTo{0.3f, 0.6f};     ///< world, on the arm
inline constexpr float kRopeLength = 2.5f;
}  // namespace turned
}  // namespace box2d_params

}  // namespace a6
