#include "box2d_scenes.h"

#include <cmath>
#include <functional>
#include <map>

#include "a6/joints.h"

namespace a6 {

using namespace box2d_params;

int Box2DScene::indexOf(const b2Body* body) const {
  if (body == ground) return -1;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i] == body) return static_cast<int>(i);
  }
  return -2;
}

namespace {

std::unique_ptr<Box2DScene> newScene(const std::string& name) {
  auto scene = std::make_unique<Box2DScene>();
  scene->name = name;
  scene->world = std::make_unique<b2World>(b2Vec2(0.0f, kGravity));
  b2BodyDef groundDef;
  scene->ground = scene->world->CreateBody(&groundDef);
  return scene;
}

b2Body* addBody(Box2DScene& scene, const std::string& name, const b2Vec2& position,
                const b2Shape& shape, float density, float friction = 0.6f) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = position;
  b2Body* body = scene.world->CreateBody(&def);
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.density = density;
  fixture.friction = friction;
  body->CreateFixture(&fixture);
  scene.bodies.push_back(body);
  scene.bodyNames.push_back(name);
  return body;
}

b2CircleShape circle(float radius) {
  b2CircleShape shape;
  shape.m_radius = radius;
  return shape;
}

b2PolygonShape box(float halfWidth, float halfHeight) {
  b2PolygonShape shape;
  shape.SetAsBox(halfWidth, halfHeight);
  return shape;
}

// A floor on a static body of its own, not the ground the mouse joint hangs from: a joint to
// the ground turns off the ground's contacts with its body (collideConnected is false), which
// would let a dragged box fall through the floor and would wake it whatever beginDrag did.
void addFloorBody(Box2DScene& scene, float y, float halfWidth) {
  b2BodyDef def;
  def.type = b2_staticBody;
  b2Body* floor = scene.world->CreateBody(&def);
  b2EdgeShape edge;
  edge.SetTwoSided(b2Vec2(-halfWidth, y), b2Vec2(halfWidth, y));
  floor->CreateFixture(&edge, 0.0f);
}

// A small bob on a hinge, released from rest at `angle` from the vertical.
std::unique_ptr<Box2DScene> pendulum(const std::string& name, float angle) {
  auto scene = newScene(name);
  const b2Vec2 bobAt = kPivot + kPendulumLength * b2Vec2(std::sin(angle), -std::cos(angle));
  b2Body* bob = addBody(*scene, "bob", bobAt, circle(kBobRadius), 100.0f);
  createHinge(*scene->world, scene->ground, bob, kPivot);
  scene->dragBody = 0;
  return scene;
}

// A bob on a rope, released 0.5 m from the anchor: it falls freely until the rope goes taut.
std::unique_ptr<Box2DScene> rope() {
  auto scene = newScene("rope");
  b2Body* bob = addBody(*scene, "bob", kPivot + b2Vec2(0.5f, 0.0f), circle(0.1f), 20.0f);
  createRope(*scene->world, scene->ground, bob, kPivot, bob->GetPosition(), kRopeMaxLength);
  scene->dragBody = 0;
  return scene;
}

// Planks hinged to each other and, at both ends, to the ground; a box dropped on the middle.
std::unique_ptr<Box2DScene> bridge() {
  auto scene = newScene("bridge");
  const float halfLength = 0.25f;
  const float x0 = -kBridgePlanks * halfLength;
  const float y = 1.0f;
  b2Body* previous = scene->ground;
  for (int k = 0; k < kBridgePlanks; ++k) {
    const float left = x0 + 2 * halfLength * k;
    b2Body* plank = addBody(*scene, "plank" + std::to_string(k), b2Vec2(left + halfLength, y),
                            box(halfLength, 0.05f), 20.0f, 0.2f);
    createHinge(*scene->world, previous, plank, b2Vec2(left, y));
    previous = plank;
  }
  createHinge(*scene->world, previous, scene->ground, b2Vec2(-x0, y));
  addBody(*scene, "load", b2Vec2(0.0f, y + 1.0f), box(0.2f, 0.2f), 10.0f);
  scene->dragBody = kBridgePlanks;
  return scene;
}

// Two vertical pistons: one driven up into its upper limit, one driven down into its lower.
std::unique_ptr<Box2DScene> piston() {
  auto scene = newScene("piston");
  const b2Vec2 axis(0.0f, 1.0f);
  b2Body* up = addBody(*scene, "up", b2Vec2(-1.0f, 1.0f), box(0.3f, 0.2f), 10.0f);
  createPiston(*scene->world, scene->ground, up, up->GetPosition(), axis, kPistonLower,
               kPistonUpper, kPistonSpeed, kPistonMaxForce);
  b2Body* down = addBody(*scene, "down", b2Vec2(1.0f, 1.25f), box(0.3f, 0.2f), 10.0f);
  createPiston(*scene->world, scene->ground, down, down->GetPosition(), axis, -kPistonUpper,
               kPistonLower, -kPistonSpeed, kPistonMaxForce);
  scene->dragBody = 0;
  return scene;
}

// A chassis on two sprung, motorised wheels, on gently rolling terrain.
std::unique_ptr<Box2DScene> car() {
  auto scene = newScene("car");
  // Terrain: a polyline of edges from x = -20 to 60 m with small bumps.
  b2Vec2 previous(-20.0f, 0.0f);
  for (float x = -19.0f; x <= 60.0f; x += 1.0f) {
    const b2Vec2 next(x, 0.15f * std::sin(0.7f * x) * (x > 2.0f ? 1.0f : 0.0f));
    b2EdgeShape edge;
    edge.SetTwoSided(previous, next);
    scene->ground->CreateFixture(&edge, 0.0f);
    previous = next;
  }
  b2PolygonShape chassisShape;
  const b2Vec2 hull[6] = {{-1.5f, -0.5f}, {1.5f, -0.5f},  {1.5f, 0.0f},
                          {0.0f, 0.9f},   {-1.15f, 0.9f}, {-1.5f, 0.2f}};
  chassisShape.Set(hull, 6);
  b2Body* chassis = addBody(*scene, "chassis", b2Vec2(0.0f, 1.0f), chassisShape, 1.0f);
  b2Body* rear = addBody(*scene, "rear_wheel", b2Vec2(-1.0f, 0.35f), circle(0.4f), 1.0f, 0.9f);
  b2Body* front = addBody(*scene, "front_wheel", b2Vec2(1.0f, 0.4f), circle(0.4f), 1.0f, 0.9f);
  const b2Vec2 axis(0.0f, 1.0f);
  createWheel(*scene->world, chassis, rear, axis, kWheelHertz, kWheelDampingRatio, kCarMotorSpeed,
              kCarMaxTorque);
  createWheel(*scene->world, chassis, front, axis, kWheelHertz, kWheelDampingRatio, kCarMotorSpeed,
              kCarMaxTorque);
  scene->dragBody = 0;
  return scene;
}

// A box on the floor, for the mouse joint.
std::unique_ptr<Box2DScene> mouseDrag() {
  auto scene = newScene("mouse_drag");
  addFloorBody(*scene, 0.0f, 10.0f);
  addBody(*scene, "box", b2Vec2(0.0f, 0.25f), box(0.25f, 0.25f), 5.0f);
  scene->dragBody = 0;
  return scene;
}

// Every builder once, on bodies turned away from the world's axes (box2d_params::turned): the
// checks read the joints as built, so gravity and contacts do not matter.
std::unique_ptr<Box2DScene> turnedScene() {
  namespace t = turned;
  auto scene = newScene("turned");
  auto add = [&](const char* name, const b2Vec2& at, float angle, const b2Shape& shape) {
    b2Body* body = addBody(*scene, name, at, shape, 5.0f);
    body->SetTransform(at, angle);
    return body;
  };
  b2Body* frame = add("frame", t::kFrameAt, t::kFrameAngle, box(0.4f, 0.1f));
  b2Body* slider = add("slider", t::kSliderAt, t::kSliderAngle, box(0.2f, 0.1f));
  b2Body* chassis = add("chassis", t::kChassisAt, t::kChassisAngle, box(0.6f, 0.2f));
  b2Body* wheel = add("wheel", t::kWheelAt, t::kWheelAngle, circle(0.3f));
  b2Body* arm = add("arm", t::kArmAt, t::kArmAngle, box(0.5f, 0.05f));
  createPiston(*scene->world, frame, slider, t::kSliderAt, t::kPistonAxis, kPistonLower,
               kPistonUpper, kPistonSpeed, kPistonMaxForce);
  createWheel(*scene->world, chassis, wheel, t::kWheelAxis, kWheelHertz, kWheelDampingRatio,
              kCarMotorSpeed, kCarMaxTorque);
  createHinge(*scene->world, frame, arm, t::kHingeAt);
  createRope(*scene->world, chassis, arm, t::kRopeFrom, t::kRopeTo, t::kRopeLength);
  return scene;
}

using Builder = std::function<std::unique_ptr<Box2DScene>()>;

const std::map<std::string, Builder>& registry() {
  static const std::map<std::string, Builder> scenes = {
      {"pendulum", [] { return pendulum("pendulum", kPendulumAngle); }},
      {"hanging", [] { return pendulum("hanging", 0.0f); }},
      {"rope", rope},
      {"bridge", bridge},
      {"piston", piston},
      {"car", car},
      {"mouse_drag", mouseDrag},
      {"turned", turnedScene},
  };
  return scenes;
}

}  // namespace

const std::vector<std::string>& box2dSceneNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& [name, builder] : registry()) out.push_back(name);
    return out;
  }();
  return names;
}

std::unique_ptr<Box2DScene> makeBox2DScene(const std::string& name) {
  const auto it = registry().find(name);
  return it == registry().end() ? nullptr : it->second();
}

}  // namespace a6
