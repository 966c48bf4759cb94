// The wire format between the grader and the probe (framework/harness/wire.h): every request and
// result survives the trip with every field bit for bit (NaN, infinities and -0.0 included),
// malformed input gives a clear error, and serve() never throws.
#include "harness/wire.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace a6 {
namespace {

using nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
double fromBits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

// Through text, as the pipe does.
json throughText(const json& j) { return wire::parse(wire::dump(j)); }

// ---- distinct values for every field, special ones among them
// -------------------------------------

struct Filler {
  int k = 0;
  double number() {
    ++k;
    switch (k % 9) {
      case 0:
        return -0.0;
      case 3:
        return fromBits(0x7ff8000000000000ull | static_cast<std::uint64_t>(k));  // a NaN
      case 5:
        return k % 2 == 0 ? kInf : -kInf;
      case 7:
        return std::numeric_limits<double>::denorm_min() * k;
      default:
        return k * 1.0000001 + 1.0 / 3.0;
    }
  }
  int integer() { return ++k * 7 - 50; }
  bool flag() { return ++k % 2 == 0; }
  std::string text() { return "name-" + std::to_string(++k) + " \xc3\xa9"; }
  Vec2 vec() {
    const double x = number();
    return Vec2(x, number());
  }
};

Particle fill(Filler& f, Particle*) {
  Particle p;
  p.x = f.vec();
  p.v = f.vec();
  p.f = f.vec();
  p.m = f.number();
  p.pinned = f.flag();
  p.temperature = f.number();
  p.age = f.number();
  p.lifetime = f.number();
  return p;
}
SpringData fill(Filler& f, SpringData*) {
  SpringData s;
  s.i = f.integer();
  s.j = f.integer();
  s.restLength = f.number();
  s.ks = f.number();
  s.kd = f.number();
  s.type = static_cast<SpringType>(f.integer() & 3);
  return s;
}
HalfPlane fill(Filler& f, HalfPlane*) { return {f.vec(), f.number()}; }
CircleObstacle fill(Filler& f, CircleObstacle*) { return {f.vec(), f.number()}; }
template <typename T>
std::vector<T> fillList(Filler& f, int n) {
  std::vector<T> out;
  for (int k = 0; k < n; ++k) out.push_back(fill(f, static_cast<T*>(nullptr)));
  return out;
}
Environment fillEnv(Filler& f) {
  Environment e;
  e.gravity = f.vec();
  e.airTemperature = f.number();
  e.buoyancy = f.number();
  e.drag = f.number();
  e.repulsion = f.number();
  e.planes = fillList<HalfPlane>(f, 2);
  e.circles = fillList<CircleObstacle>(f, 3);
  return e;
}
EmitterSpec fillEmitter(Filler& f) {
  EmitterSpec s;
  s.position = f.vec();
  s.radius = f.number();
  s.velocity = f.vec();
  s.velocitySpread = f.number();
  s.mass = f.number();
  s.temperatureMin = f.number();
  s.temperatureMax = f.number();
  s.lifetimeMin = f.number();
  s.lifetimeMax = f.number();
  s.rate = f.number();
  return s;
}
harness::JointInfo fill(Filler& f, harness::JointInfo*) {
  harness::JointInfo i;
  i.type = f.text();
  i.bodyA = f.integer();
  i.bodyB = f.integer();
  i.anchorA = f.vec();
  i.anchorB = f.vec();
  i.localAnchorA = f.vec();
  i.localAnchorB = f.vec();
  i.localAxisA = f.vec();
  i.collideConnected = f.flag();
  i.enableLimit = f.flag();
  i.lower = f.number();
  i.upper = f.number();
  i.enableMotor = f.flag();
  i.motorSpeed = f.number();
  i.maxMotor = f.number();
  i.length = f.number();
  i.minLength = f.number();
  i.maxLength = f.number();
  i.stiffness = f.number();
  i.damping = f.number();
  i.maxForce = f.number();
  i.target = f.vec();
  i.reactionForce = f.vec();
  return i;
}
harness::BodyPose fill(Filler& f, harness::BodyPose*) {
  return {f.vec(), f.number(), f.vec(), f.number(), f.flag()};
}
harness::BodyInfo fill(Filler& f, harness::BodyInfo*) {
  harness::BodyInfo b;
  b.name = f.text();
  b.mass = f.number();
  b.inertia = f.number();
  b.localCenter = f.vec();
  return b;
}
ShapeData fill(Filler& f, ShapeData*) {
  ShapeData s;
  s.kind = static_cast<ShapeData::Kind>((f.integer() & 0x7fffffff) % 3);
  s.body = f.integer();
  s.points = {f.vec(), f.vec(), f.vec()};
  s.center = f.vec();
  s.radius = f.number();
  s.angle = f.number();
  return s;
}
JointData fill(Filler& f, JointData*) {
  JointData d;
  d.type = f.text();
  d.anchorA = f.vec();
  d.anchorB = f.vec();
  d.centerA = f.vec();
  d.centerB = f.vec();
  d.groundA = f.flag();
  d.groundB = !d.groundA;
  return d;
}
Snapshot fill(Filler& f, Snapshot*) {
  Snapshot s;
  s.scene = f.text();
  s.time = f.number();
  s.particles = fillList<Particle>(f, 3);
  s.particleRadius = f.number();
  s.springs = fillList<SpringData>(f, 2);
  s.planes = fillList<HalfPlane>(f, 1);
  s.circles = fillList<CircleObstacle>(f, 2);
  s.shapes = fillList<ShapeData>(f, 3);
  s.joints = fillList<JointData>(f, 2);
  s.view.center = f.vec();
  s.view.height = f.number();
  return s;
}

// ---- bit-for-bit comparison, field by field
// ----------------------------------------------------------

void same(double a, double b, const std::string& at) {
  EXPECT_EQ(bits(a), bits(b)) << at << ": " << a << " came back as " << b;
}
void same(int a, int b, const std::string& at) { EXPECT_EQ(a, b) << at; }
void same(bool a, bool b, const std::string& at) { EXPECT_EQ(a, b) << at; }
void same(std::uint64_t a, std::uint64_t b, const std::string& at) { EXPECT_EQ(a, b) << at; }
void same(const std::string& a, const std::string& b, const std::string& at) {
  EXPECT_EQ(a, b) << at;
}
void same(const Vec2& a, const Vec2& b, const std::string& at) {
  same(a.x(), b.x(), at + ".x");
  same(a.y(), b.y(), at + ".y");
}
template <typename E, typename = std::enable_if_t<std::is_enum_v<E>>>
void same(E a, E b, const std::string& at) {
  EXPECT_EQ(static_cast<int>(a), static_cast<int>(b)) << at;
}
// Declared first: the vector overload calls these.
void same(const Particle& a, const Particle& b, const std::string& at);
void same(const SpringData& a, const SpringData& b, const std::string& at);
void same(const HalfPlane& a, const HalfPlane& b, const std::string& at);
void same(const CircleObstacle& a, const CircleObstacle& b, const std::string& at);
void same(const ShapeData& a, const ShapeData& b, const std::string& at);
void same(const JointData& a, const JointData& b, const std::string& at);
void same(const Snapshot& a, const Snapshot& b, const std::string& at);
void same(const harness::DragEvent& a, const harness::DragEvent& b, const std::string& at);
void same(const harness::BodyPose& a, const harness::BodyPose& b, const std::string& at);
void same(const harness::BodyInfo& a, const harness::BodyInfo& b, const std::string& at);
void same(const harness::JointInfo& a, const harness::JointInfo& b, const std::string& at);
template <typename T>
void same(const std::vector<T>& a, const std::vector<T>& b, const std::string& at);

template <typename T>
void same(const std::vector<T>& a, const std::vector<T>& b, const std::string& at) {
  ASSERT_EQ(a.size(), b.size()) << at;
  for (std::size_t k = 0; k < a.size(); ++k) same(a[k], b[k], at + "[" + std::to_string(k) + "]");
}
#define SAME(field) same(a.field, b.field, at + "." #field)

void same(const Particle& a, const Particle& b, const std::string& at) {
  SAME(x);
  SAME(v);
  SAME(f);
  SAME(m);
  SAME(pinned);
  SAME(temperature);
  SAME(age);
  SAME(lifetime);
}
void same(const SpringData& a, const SpringData& b, const std::string& at) {
  SAME(i);
  SAME(j);
  SAME(restLength);
  SAME(ks);
  SAME(kd);
  SAME(type);
}
void same(const HalfPlane& a, const HalfPlane& b, const std::string& at) {
  SAME(normal);
  SAME(offset);
}
void same(const CircleObstacle& a, const CircleObstacle& b, const std::string& at) {
  SAME(center);
  SAME(radius);
}
void same(const Contact& a, const Contact& b, const std::string& at) {
  SAME(depth);
  SAME(normal);
}
void same(const Environment& a, const Environment& b, const std::string& at) {
  SAME(gravity);
  SAME(airTemperature);
  SAME(buoyancy);
  SAME(drag);
  SAME(repulsion);
  SAME(planes);
  SAME(circles);
}
void same(const EmitterSpec& a, const EmitterSpec& b, const std::string& at) {
  SAME(position);
  SAME(radius);
  SAME(velocity);
  SAME(velocitySpread);
  SAME(mass);
  SAME(temperatureMin);
  SAME(temperatureMax);
  SAME(lifetimeMin);
  SAME(lifetimeMax);
  SAME(rate);
}
void same(const ClothSpec& a, const ClothSpec& b, const std::string& at) {
  SAME(n);
  SAME(size);
  SAME(origin);
  SAME(particleMass);
  SAME(ksStructural);
  SAME(kdStructural);
  SAME(shear);
  SAME(ksShear);
  SAME(kdShear);
  SAME(bending);
  SAME(ksBending);
  SAME(kdBending);
  SAME(pinTopCorners);
}
void same(const SceneParams& a, const SceneParams& b, const std::string& at) {
  SAME(ks);
  SAME(kd);
  SAME(substeps);
  SAME(n);
  SAME(dt);
  SAME(gravity);
  SAME(drag);
  SAME(buoyancy);
  SAME(structural);
  SAME(shear);
  SAME(bending);
  SAME(seed);
}
void same(const ShapeData& a, const ShapeData& b, const std::string& at) {
  SAME(kind);
  SAME(body);
  SAME(points);
  SAME(center);
  SAME(radius);
  SAME(angle);
}
void same(const JointData& a, const JointData& b, const std::string& at) {
  SAME(type);
  SAME(anchorA);
  SAME(anchorB);
  SAME(centerA);
  SAME(centerB);
  SAME(groundA);
  SAME(groundB);
}
void same(const Snapshot& a, const Snapshot& b, const std::string& at) {
  SAME(scene);
  SAME(time);
  SAME(particles);
  SAME(particleRadius);
  SAME(springs);
  SAME(planes);
  SAME(circles);
  SAME(shapes);
  SAME(joints);
  SAME(view.center);
  SAME(view.height);
}
void same(const harness::DragEvent& a, const harness::DragEvent& b, const std::string& at) {
  SAME(kind);
  SAME(step);
  SAME(target);
}
void same(const harness::BodyPose& a, const harness::BodyPose& b, const std::string& at) {
  SAME(position);
  SAME(angle);
  SAME(velocity);
  SAME(angularVelocity);
  SAME(awake);
}
void same(const harness::BodyInfo& a, const harness::BodyInfo& b, const std::string& at) {
  SAME(name);
  SAME(mass);
  SAME(inertia);
  SAME(localCenter);
}
void same(const harness::JointInfo& a, const harness::JointInfo& b, const std::string& at) {
  SAME(type);
  SAME(bodyA);
  SAME(bodyB);
  SAME(anchorA);
  SAME(anchorB);
  SAME(localAnchorA);
  SAME(localAnchorB);
  SAME(localAxisA);
  SAME(collideConnected);
  SAME(enableLimit);
  SAME(lower);
  SAME(upper);
  SAME(enableMotor);
  SAME(motorSpeed);
  SAME(maxMotor);
  SAME(length);
  SAME(minLength);
  SAME(maxLength);
  SAME(stiffness);
  SAME(damping);
  SAME(maxForce);
  SAME(target);
  SAME(reactionForce);
}

// ---- doubles
// ---------------------------------------------------------------------------------------

TEST(WireDoubles, SpecialValuesSurviveBitForBit) {
  const std::vector<double> values = {0.0,
                                      -0.0,
                                      1.0,
                                      -1.0,
                                      0.1,
                                      1.0 / 3.0,
                                      2.0 / 3.0,
                                      1e300,
                                      -1e-300,
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::lowest(),
                                      std::numeric_limits<double>::min(),
                                      std::numeric_limits<double>::denorm_min(),
                                      -std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::epsilon(),
                                      9007199254740993.0,
                                      123456789012345678.0,
                                      kInf,
                                      -kInf,
                                      std::numeric_limits<double>::quiet_NaN(),
                                      -std::numeric_limits<double>::quiet_NaN(),
                                      std::numeric_limits<double>::signaling_NaN(),
                                      fromBits(0x7ff0000000000001ull),
                                      fromBits(0xfff123456789abcdull),
                                      fromBits(0x7fffffffffffffffull)};
  for (double x : values) {
    const json text = throughText(json::array({wire::encodeDouble(x)}));
    const double back = wire::decodeDouble(text[0]);
    EXPECT_EQ(bits(x), bits(back)) << "value " << x << " encoded as " << wire::dump(text);
  }
}

TEST(WireDoubles, NonFiniteValuesAreReadableStrings) {
  EXPECT_EQ(wire::encodeDouble(kInf), "inf");
  EXPECT_EQ(wire::encodeDouble(-kInf), "-inf");
  EXPECT_EQ(wire::encodeDouble(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(wire::encodeDouble(fromBits(0x7ff0000000000001ull)), "nan:0x7ff0000000000001");
  EXPECT_TRUE(wire::encodeDouble(-0.0).is_number());
  EXPECT_EQ(wire::dump(wire::encodeDouble(-0.0)), "-0.0");
}

TEST(WireDoubles, RandomBitPatternsSurviveBitForBit) {
  std::mt19937_64 rng(20240611);
  json list = json::array();
  std::vector<double> values;
  for (int k = 0; k < 200000; ++k) {
    const double x = fromBits(rng());
    values.push_back(x);
    list.push_back(wire::encodeDouble(x));
  }
  const json back = throughText(list);
  int mismatches = 0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (bits(wire::decodeDouble(back[k])) != bits(values[k]) && ++mismatches < 5) {
      ADD_FAILURE() << "bits " << std::hex << bits(values[k]) << " came back as "
                    << bits(wire::decodeDouble(back[k]));
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(WireDoubles, AnythingElseIsRefusedWithTheReason) {
  for (const json& bad : {json("nan:0xzz00000000000000"), json("nan:0x0000000000000001"),
                          json("NaN"), json(true), json::array(), json(nullptr)}) {
    try {
      wire::decodeDouble(bad);
      ADD_FAILURE() << wire::dump(bad) << " was accepted as a double";
    } catch (const wire::Malformed& e) {
      EXPECT_NE(std::string(e.what()).find("expected a number"), std::string::npos) << e.what();
    }
  }
}

// ---- requests
// ------------------------------------------------------------------------------------------

TEST(WireRequests, EveryRequestSurvivesWithEveryField) {
  Filler f;
  {
    harness::SpringForceRequest r;
    r.p1 = fill(f, static_cast<Particle*>(nullptr));
    r.p2 = fill(f, static_cast<Particle*>(nullptr));
    r.restLength = f.number();
    r.ks = f.number();
    r.kd = f.number();
    const json j = throughText(wire::encodeSpringForce(r));
    EXPECT_EQ(j["kind"], "springForce");
    const auto b = wire::decodeSpringForceRequest(j["body"]);
    const auto& a = r;
    const std::string at = "SpringForceRequest";
    SAME(p1);
    SAME(p2);
    SAME(restLength);
    SAME(ks);
    SAME(kd);
  }
  {
    harness::ForcesRequest r;
    r.particle = fill(f, static_cast<Particle*>(nullptr));
    r.env = fillEnv(f);
    r.contact = {f.number(), f.vec()};
    const json j = throughText(wire::encodeForces(r));
    EXPECT_EQ(j["kind"], "forces");
    const auto b = wire::decodeForcesRequest(j["body"]);
    const auto& a = r;
    const std::string at = "ForcesRequest";
    SAME(particle);
    SAME(env);
    SAME(contact);
  }
  {
    harness::SimulateRequest r;
    r.particles = fillList<Particle>(f, 4);
    r.springs = fillList<SpringData>(f, 5);
    r.env = fillEnv(f);
    r.frameDt = f.number();
    r.substeps = f.integer();
    r.stepOnly = true;
    r.frames = f.integer();
    r.recordEvery = f.integer();
    r.referenceForces = true;
    const json j = throughText(wire::encodeSimulate(r));
    EXPECT_EQ(j["kind"], "simulate");
    const auto b = wire::decodeSimulateRequest(j["body"]);
    const auto& a = r;
    const std::string at = "SimulateRequest";
    SAME(particles);
    SAME(springs);
    SAME(env);
    SAME(frameDt);
    SAME(substeps);
    SAME(stepOnly);
    SAME(frames);
    SAME(recordEvery);
    SAME(referenceForces);
  }
  {
    ClothSpec a;
    a.n = f.integer();
    a.size = f.number();
    a.origin = f.vec();
    a.particleMass = f.number();
    a.ksStructural = f.number();
    a.kdStructural = f.number();
    a.shear = false;
    a.ksShear = f.number();
    a.kdShear = f.number();
    a.bending = true;
    a.ksBending = f.number();
    a.kdBending = f.number();
    a.pinTopCorners = false;
    const json j = throughText(wire::encodeBuildCloth(a));
    EXPECT_EQ(j["kind"], "buildCloth");
    same(a, wire::decodeBuildClothRequest(j["body"]), "ClothSpec");
  }
  {
    harness::EmitRequest r;
    r.spec = fillEmitter(f);
    r.seed = 0xfedcba9876543210ull;  // above 2^63: must stay exact
    r.count = f.integer();
    const json j = throughText(wire::encodeEmit(r));
    EXPECT_EQ(j["kind"], "emit");
    const auto b = wire::decodeEmitRequest(j["body"]);
    const auto& a = r;
    const std::string at = "EmitRequest";
    SAME(spec);
    SAME(seed);
    SAME(count);
  }
  {
    harness::ParticleRunRequest r;
    r.emitter = fillEmitter(f);
    r.env = fillEnv(f);
    r.coolingRate = f.number();
    r.seed = 18446744073709551615ull;
    r.initial = fillList<Particle>(f, 3);
    r.dt = f.number();
    r.steps = f.integer();
    r.referenceForces = true;
    const json j = throughText(wire::encodeRunParticles(r));
    EXPECT_EQ(j["kind"], "runParticles");
    const auto b = wire::decodeRunParticlesRequest(j["body"]);
    const auto& a = r;
    const std::string at = "ParticleRunRequest";
    SAME(emitter);
    SAME(env);
    SAME(coolingRate);
    SAME(seed);
    SAME(initial);
    SAME(dt);
    SAME(steps);
    SAME(referenceForces);
  }
  {
    harness::Box2DRequest r;
    r.scene = "mouse_drag";
    r.steps = f.integer();
    r.drag = {{harness::DragEvent::Kind::Begin, 3, f.vec()},
              {harness::DragEvent::Kind::Move, 5, f.vec()},
              {harness::DragEvent::Kind::End, 9, f.vec()}};
    const json j = throughText(wire::encodeRunBox2D(r));
    EXPECT_EQ(j["kind"], "runBox2D");
    const auto b = wire::decodeRunBox2DRequest(j["body"]);
    const auto& a = r;
    const std::string at = "Box2DRequest";
    SAME(scene);
    SAME(steps);
    SAME(drag);
  }
  {
    harness::SceneRequest r;
    r.scene = "cloth_shear";
    r.frames = {0, 60, 30, 60};
    r.useDefaults = false;
    r.params.ks = f.number();
    r.params.kd = f.number();
    r.params.substeps = f.integer();
    r.params.n = f.integer();
    r.params.dt = f.number();
    r.params.gravity = f.number();
    r.params.drag = f.number();
    r.params.buoyancy = f.number();
    r.params.structural = false;
    r.params.shear = true;
    r.params.bending = true;
    r.params.seed = 0x8000000000000001ull;
    const json j = throughText(wire::encodeRunScene(r));
    EXPECT_EQ(j["kind"], "runScene");
    const auto b = wire::decodeRunSceneRequest(j["body"]);
    const auto& a = r;
    const std::string at = "SceneRequest";
    SAME(scene);
    SAME(frames);
    SAME(useDefaults);
    SAME(params);
  }
}

// ---- results
// ----------------------------------------------------------------------------------------------

TEST(WireResults, EveryResultSurvivesWithEveryField) {
  Filler f;
  {
    harness::SpringForceResult a;
    a.error = "";
    a.force = f.vec();
    const auto b = wire::decodeSpringForce(throughText(wire::encodeResult(a)));
    const std::string at = "SpringForceResult";
    SAME(error);
    SAME(force);
  }
  {
    harness::ForcesResult a;
    a.gravity = f.vec();
    a.buoyancy = f.vec();
    a.drag = f.vec();
    a.repulsion = f.vec();
    a.total = f.vec();
    const auto b = wire::decodeForces(throughText(wire::encodeResult(a)));
    const std::string at = "ForcesResult";
    SAME(error);
    SAME(gravity);
    SAME(buoyancy);
    SAME(drag);
    SAME(repulsion);
    SAME(total);
  }
  {
    harness::SimulateResult a;
    a.recordedFrames = {1, 5, 10};
    a.states = {fillList<Particle>(f, 2), fillList<Particle>(f, 2), fillList<Particle>(f, 2)};
    const auto b = wire::decodeSimulate(throughText(wire::encodeResult(a)));
    const std::string at = "SimulateResult";
    SAME(error);
    SAME(recordedFrames);
    SAME(states);
  }
  {
    harness::ClothResult a;
    a.particles = fillList<Particle>(f, 4);
    a.springs = fillList<SpringData>(f, 6);
    const auto b = wire::decodeBuildCloth(throughText(wire::encodeResult(a)));
    const std::string at = "ClothResult";
    SAME(error);
    SAME(particles);
    SAME(springs);
  }
  {
    harness::ParticlesResult a;
    a.particles = fillList<Particle>(f, 5);
    a.counts = {0, 3, 7, -1};
    const auto b = wire::decodeParticles(throughText(wire::encodeResult(a)));
    const std::string at = "ParticlesResult";
    SAME(error);
    SAME(particles);
    SAME(counts);
  }
  {
    harness::Box2DResult a;
    a.bodies = fillList<harness::BodyInfo>(f, 2);
    a.poses = {fillList<harness::BodyPose>(f, 2), fillList<harness::BodyPose>(f, 2)};
    a.joints = fillList<harness::JointInfo>(f, 2);
    a.builtJoints = fillList<harness::JointInfo>(f, 1);
    a.jointCounts = {2, 2, 3};
    a.dragJoints = fillList<harness::JointInfo>(f, 1);
    a.endDragCleared = {1, 0};
    const auto b = wire::decodeRunBox2D(throughText(wire::encodeResult(a)));
    const std::string at = "Box2DResult";
    SAME(error);
    SAME(bodies);
    SAME(poses);
    SAME(joints);
    SAME(builtJoints);
    SAME(jointCounts);
    SAME(dragJoints);
    SAME(endDragCleared);
  }
  {
    harness::SceneResult a;
    a.snapshots = fillList<Snapshot>(f, 2);
    const auto b = wire::decodeRunScene(throughText(wire::encodeResult(a)));
    const std::string at = "SceneResult";
    SAME(error);
    SAME(snapshots);
  }
}

TEST(WireResults, AnErrorAloneIsAWholeResultAndKeepsItsText) {
  const json j = throughText(json{{"error", "exception: boom"}});
  EXPECT_EQ(wire::decodeSpringForce(j).error, "exception: boom");
  EXPECT_EQ(wire::decodeSimulate(j).error, "exception: boom");
  EXPECT_EQ(wire::decodeRunScene(j).error, "exception: boom");
  EXPECT_TRUE(wire::decodeRunBox2D(j).poses.empty());
}

TEST(WireResults, InvalidUtf8InAnErrorIsReplacedNotRefused) {
  harness::SpringForceResult r;
  r.error = "exception: bad bytes \xff\xfe here";
  const std::string text = wire::dump(wire::encodeResult(r));
  const auto back = wire::decodeSpringForce(wire::parse(text));
  EXPECT_NE(back.error.find("bad bytes"), std::string::npos);
  EXPECT_NE(back.error.find("\xef\xbf\xbd"), std::string::npos) << "U+FFFD in place of bad bytes";
}

// ---- malformed input
// ---------------------------------------------------------------------------------------

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const wire::Malformed& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("not Malformed: ") + e.what();
  }
  return "";
}

TEST(WireMalformed, BadTextSaysItIsNotJson) {
  const std::string e = errorOf([] { wire::parse("{\"error\": \"\", \"force\": [1, "); });
  EXPECT_EQ(e.rfind("not JSON", 0), 0u) << e;
}

TEST(WireMalformed, AMissingFieldIsNamedWithWhereItWas) {
  harness::SimulateResult r;
  r.recordedFrames = {1, 2};
  r.states = {{Particle{}}, {Particle{}, Particle{}}};
  json j = wire::encodeResult(r);
  j["states"][1][1].erase("m");
  const std::string e = errorOf([&] { wire::decodeSimulate(j); });
  EXPECT_NE(e.find("SimulateResult"), std::string::npos) << e;
  EXPECT_NE(e.find("states[1][1]"), std::string::npos) << e;
  EXPECT_NE(e.find("missing field 'm'"), std::string::npos) << e;
}

TEST(WireMalformed, AWrongTypeIsNamed) {
  json j = wire::encodeResult(harness::SpringForceResult{});
  j["force"] = json::array({1.0});
  EXPECT_NE(errorOf([&] { wire::decodeSpringForce(j); }).find("expected [x, y]"),
            std::string::npos);
  j["force"] = "north";
  EXPECT_NE(errorOf([&] { wire::decodeSpringForce(j); }).find("force"), std::string::npos);
  EXPECT_NE(errorOf([&] { wire::decodeSpringForce(json::array()); }).find("expected an object"),
            std::string::npos);
  json cloth = wire::encodeResult(harness::ClothResult{});
  cloth["springs"] = json::array(
      {json{{"i", 1.5}, {"j", 0}, {"restLength", 1}, {"ks", 1}, {"kd", 1}, {"type", "shear"}}});
  EXPECT_NE(errorOf([&] { wire::decodeBuildCloth(cloth); }).find("expected an integer"),
            std::string::npos);
  cloth["springs"][0]["i"] = 1;
  cloth["springs"][0]["type"] = "rubber";
  EXPECT_NE(errorOf([&] { wire::decodeBuildCloth(cloth); }).find("'rubber' is not one of"),
            std::string::npos);
  json counts = wire::encodeResult(harness::ParticlesResult{});
  counts["counts"] = json::array({5000000000LL});
  EXPECT_NE(errorOf([&] { wire::decodeParticles(counts); }).find("does not fit an int"),
            std::string::npos);
}

// ---- serve
// ------------------------------------------------------------------------------------------------------

// A StudentCode that remembers the request it got and answers with a fixed result.
class Recorder final : public harness::StudentCode {
 public:
  harness::SpringForceRequest springRequest;
  bool throwOnEmit = false;
  harness::SpringForceResult springForce(const harness::SpringForceRequest& r) override {
    springRequest = r;
    harness::SpringForceResult result;
    result.force = Vec2(std::numeric_limits<double>::quiet_NaN(), -0.0);
    return result;
  }
  harness::ForcesResult forces(const harness::ForcesRequest&) override { return {}; }
  harness::SimulateResult simulate(const harness::SimulateRequest&) override { return {}; }
  harness::ClothResult buildCloth(const ClothSpec&) override { return {}; }
  harness::ParticlesResult emit(const harness::EmitRequest&) override {
    if (throwOnEmit) throw std::runtime_error("escaped the harness");
    return {};
  }
  harness::ParticlesResult runParticles(const harness::ParticleRunRequest&) override { return {}; }
  harness::Box2DResult runBox2D(const harness::Box2DRequest&) override { return {}; }
};

TEST(WireServe, ARequestReachesTheCodeAndItsResultComesBack) {
  Recorder code;
  harness::SpringForceRequest r;
  r.p2.x = Vec2(1, -kInf);
  r.ks = 42;
  const json answer = throughText(wire::serve(code, throughText(wire::encodeSpringForce(r))));
  same(code.springRequest.p2.x, r.p2.x, "p2.x");
  EXPECT_EQ(code.springRequest.ks, 42);
  const auto result = wire::decodeSpringForce(answer);
  EXPECT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(std::isnan(result.force.x()));
  EXPECT_TRUE(std::signbit(result.force.y()) && result.force.y() == 0.0);
}

TEST(WireServe, AnUnknownKindIsAnErrorNotAnException) {
  Recorder code;
  const json answer = wire::serve(code, json{{"kind", "teleport"}, {"body", json::object()}});
  const auto result = wire::decodeSpringForce(answer);
  EXPECT_NE(result.error.find("does not know the request kind 'teleport'"), std::string::npos)
      << result.error;
}

TEST(WireServe, MalformedRequestsAreErrorsNotExceptions) {
  Recorder code;
  for (const json& bad :
       {json(nullptr), json(3), json::array({1, 2}), json{{"kind", "springForce"}},
        json{{"kind", 7}, {"body", json::object()}},
        json{{"kind", "springForce"}, {"body", json{{"p1", 1}}}}}) {
    json answer;
    EXPECT_NO_THROW(answer = wire::serve(code, bad)) << wire::dump(bad);
    const std::string error = wire::decodeSpringForce(answer).error;
    EXPECT_NE(error.find("malformed request"), std::string::npos)
        << wire::dump(bad) << " -> " << error;
  }
}

TEST(WireServe, AnExceptionEscapingTheCodeIsAnError) {
  Recorder code;
  code.throwOnEmit = true;
  const json answer = wire::serve(code, wire::encodeEmit(harness::EmitRequest{}));
  EXPECT_EQ(wire::decodeParticles(answer).error, "exception: escaped the harness");
}

TEST(WireServe, RunSceneFallsBackToTheBaseClassAnswer) {
  Recorder code;
  harness::SceneRequest r;
  r.scene = "fire";
  const auto result = wire::decodeRunScene(wire::serve(code, wire::encodeRunScene(r)));
  EXPECT_NE(result.error.find("not supported"), std::string::npos) << result.error;
}

// ---- framing
// -------------------------------------------------------------------------------------------------------

TEST(WireFraming, AFrameIsALittleEndianLengthThenTheText) {
  const json message = {{"kind", "x"}, {"body", std::string(300, 'a')}};
  const std::string f = wire::frame(message);
  const std::string text = wire::dump(message);
  ASSERT_EQ(f.size(), text.size() + 4);
  EXPECT_EQ(wire::frameLength(reinterpret_cast<const unsigned char*>(f.data())), text.size());
  EXPECT_EQ(static_cast<unsigned char>(f[0]), text.size() & 0xff);
  EXPECT_EQ(static_cast<unsigned char>(f[1]), (text.size() >> 8) & 0xff);
  EXPECT_EQ(f.substr(4), text);
}

TEST(WireFraming, FramesRoundTripThroughAPipeAndBadOnesAreRefused) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const json first = {{"a", 1}}, second = {{"b", "two"}};
  ASSERT_TRUE(wire::writeAll(fds[1], wire::frame(first) + wire::frame(second)));
  // A length over the cap, then a truncated frame.
  const unsigned char huge[] = {0xff, 0xff, 0xff, 0x7f};
  ASSERT_EQ(write(fds[1], huge, 4), 4);
  close(fds[1]);
  std::string body;
  ASSERT_TRUE(wire::readFrame(fds[0], body));
  EXPECT_EQ(wire::parse(body), first);
  ASSERT_TRUE(wire::readFrame(fds[0], body));
  EXPECT_EQ(wire::parse(body), second);
  EXPECT_NE(errorOf([&] { wire::readFrame(fds[0], body); }).find("over the limit"),
            std::string::npos);
  close(fds[0]);

  ASSERT_EQ(pipe(fds), 0);
  const std::string cut = wire::frame(first).substr(0, 6);
  ASSERT_TRUE(wire::writeAll(fds[1], cut));
  close(fds[1]);
  EXPECT_NE(errorOf([&] { wire::readFrame(fds[0], body); }).find("ended inside a frame"),
            std::string::npos);
  close(fds[0]);

  ASSERT_EQ(pipe(fds), 0);
  close(fds[1]);
  EXPECT_FALSE(wire::readFrame(fds[0], body)) << "a clean end of stream is not an error";
  close(fds[0]);
}

}  // namespace
}  // namespace a6
