// The one list of what crosses the wire between the grader and the probe: for each type, its
// fields, by name, in order. Takes nothing; gives fields(v, x), which calls v("name", x.member)
// for every member of x that is sent, and the names of the enums' values.
//
// Encoding and decoding (wire.cpp) and the round-trip test (tests/grader/wire_test.cpp) all walk
// these lists, so a field cannot be sent by one side and not read by the other: a member added to
// a request or a result and not listed here is not sent at all, and the test, which fills every
// listed field with its own value, shows a listed one that does not come back.
//
// A result's own fields only: its outcome (error and fault) is written first by wire.cpp.
#pragma once

#include <utility>

#include "harness/student_code.h"

namespace a6::wire {

// Enums: their values and the names that stand for them.
constexpr std::pair<SpringType, const char*> kSpringTypes[] = {
    {SpringType::Structural, "structural"},
    {SpringType::Shear, "shear"},
    {SpringType::Bending, "bending"},
    {SpringType::Other, "other"}};
constexpr std::pair<ShapeData::Kind, const char*> kShapeKinds[] = {
    {ShapeData::Kind::Circle, "circle"},
    {ShapeData::Kind::Polygon, "polygon"},
    {ShapeData::Kind::Edge, "edge"}};
constexpr std::pair<harness::DragEvent::Kind, const char*> kDragKinds[] = {
    {harness::DragEvent::Kind::Begin, "begin"},
    {harness::DragEvent::Kind::Move, "move"},
    {harness::DragEvent::Kind::End, "end"}};

inline const auto& namesOf(SpringType) { return kSpringTypes; }
inline const auto& namesOf(ShapeData::Kind) { return kShapeKinds; }
inline const auto& namesOf(harness::DragEvent::Kind) { return kDragKinds; }

// The framework's types ---------------------------------------------------------------------------

template <class V>
void fields(V& v, Particle& p) {
  v("x", p.x), v("v", p.v), v("f", p.f), v("m", p.m), v("pinned", p.pinned);
  v("temperature", p.temperature), v("age", p.age), v("lifetime", p.lifetime);
}
template <class V>
void fields(V& v, Spring& s) {  // the force channel's (harness/force_channel.cpp) only
  v("p1", s.p1), v("p2", s.p2), v("restLength", s.restLength), v("ks", s.ks), v("kd", s.kd);
  v("type", s.type);
}
/// What a reference force may read of a particle, which the force channel sends; the rest of
/// fields(Particle) is kNotForceInputs: its force accumulator (the output, summed while the forces
/// are asked), whether a stepper moves it, and the particle system's clock. A member added to
/// Particle belongs to one of the two (tests/grader/wire_test.cpp).
template <class V>
void forceInputs(V& v, Particle& p) {
  v("x", p.x), v("v", p.v), v("m", p.m), v("temperature", p.temperature);
}
constexpr const char* kNotForceInputs[] = {"f", "pinned", "age", "lifetime"};
template <class V>
void fields(V& v, SpringData& s) {
  v("i", s.i), v("j", s.j), v("restLength", s.restLength), v("ks", s.ks), v("kd", s.kd);
  v("type", s.type);
}
template <class V>
void fields(V& v, HalfPlane& h) {
  v("normal", h.normal), v("offset", h.offset);
}
template <class V>
void fields(V& v, CircleObstacle& c) {
  v("center", c.center), v("radius", c.radius);
}
template <class V>
void fields(V& v, Contact& c) {
  v("depth", c.depth), v("normal", c.normal);
}
template <class V>
void fields(V& v, Environment& e) {
  v("gravity", e.gravity), v("airTemperature", e.airTemperature), v("buoyancy", e.buoyancy);
  v("drag", e.drag), v("repulsion", e.repulsion), v("planes", e.planes), v("circles", e.circles);
}
template <class V>
void fields(V& v, ClothSpec& s) {
  v("n", s.n), v("size", s.size), v("origin", s.origin), v("particleMass", s.particleMass);
  v("ksStructural", s.ksStructural), v("kdStructural", s.kdStructural);
  v("shear", s.shear), v("ksShear", s.ksShear), v("kdShear", s.kdShear);
  v("bending", s.bending), v("ksBending", s.ksBending), v("kdBending", s.kdBending);
  v("pinTopCorners", s.pinTopCorners);
}
template <class V>
void fields(V& v, EmitterSpec& s) {
  v("position", s.position), v("radius", s.radius), v("velocity", s.velocity);
  v("velocitySpread", s.velocitySpread), v("mass", s.mass);
  v("temperatureMin", s.temperatureMin), v("temperatureMax", s.temperatureMax);
  v("lifetimeMin", s.lifetimeMin), v("lifetimeMax", s.lifetimeMax), v("rate", s.rate);
}
template <class V>
void fields(V& v, SceneParams& p) {
  v("ks", p.ks), v("kd", p.kd), v("substeps", p.substeps), v("n", p.n), v("dt", p.dt);
  v("gravity", p.gravity), v("drag", p.drag), v("buoyancy", p.buoyancy);
  v("structural", p.structural), v("shear", p.shear), v("bending", p.bending), v("seed", p.seed);
  v("implicit", p.implicit);
}
template <class V>
void fields(V& v, ShapeData& s) {
  v("kind", s.kind), v("body", s.body), v("points", s.points), v("center", s.center);
  v("radius", s.radius), v("angle", s.angle);
}
template <class V>
void fields(V& v, JointData& d) {
  v("type", d.type), v("anchorA", d.anchorA), v("anchorB", d.anchorB);
  v("centerA", d.centerA), v("centerB", d.centerB), v("groundA", d.groundA);
  v("groundB", d.groundB);
}
template <class V>
void fields(V& v, View& w) {
  v("center", w.center), v("height", w.height);
}
template <class V>
void fields(V& v, Snapshot& s) {
  v("scene", s.scene), v("time", s.time), v("particles", s.particles);
  v("particleRadius", s.particleRadius), v("springs", s.springs), v("planes", s.planes);
  v("circles", s.circles), v("shapes", s.shapes), v("joints", s.joints), v("view", s.view);
}

// The harness's types -----------------------------------------------------------------------------

template <class V>
void fields(V& v, harness::DragEvent& e) {
  v("kind", e.kind), v("step", e.step), v("target", e.target);
}
template <class V>
void fields(V& v, harness::BodyPose& p) {
  v("position", p.position), v("angle", p.angle), v("velocity", p.velocity);
  v("angularVelocity", p.angularVelocity), v("awake", p.awake);
}
template <class V>
void fields(V& v, harness::BodyInfo& b) {
  v("name", b.name), v("mass", b.mass), v("inertia", b.inertia), v("localCenter", b.localCenter);
}
template <class V>
void fields(V& v, harness::JointInfo& i) {
  v("type", i.type), v("bodyA", i.bodyA), v("bodyB", i.bodyB);
  v("anchorA", i.anchorA), v("anchorB", i.anchorB);
  v("localAnchorA", i.localAnchorA), v("localAnchorB", i.localAnchorB);
  v("localAxisA", i.localAxisA), v("collideConnected", i.collideConnected);
  v("enableLimit", i.enableLimit), v("lower", i.lower), v("upper", i.upper);
  v("enableMotor", i.enableMotor), v("motorSpeed", i.motorSpeed), v("maxMotor", i.maxMotor);
  v("length", i.length), v("minLength", i.minLength), v("maxLength", i.maxLength);
  v("stiffness", i.stiffness), v("damping", i.damping), v("maxForce", i.maxForce);
  v("target", i.target), v("reactionForce", i.reactionForce);
}

// Requests ----------------------------------------------------------------------------------------

template <class V>
void fields(V& v, harness::SpringForceRequest& r) {
  v("p1", r.p1), v("p2", r.p2), v("restLength", r.restLength), v("ks", r.ks), v("kd", r.kd);
}
template <class V>
void fields(V& v, harness::ForcesRequest& r) {
  v("particle", r.particle), v("env", r.env), v("contact", r.contact);
}
template <class V>
void fields(V& v, harness::SimulateRequest& r) {
  v("particles", r.particles), v("springs", r.springs), v("env", r.env);
  v("frameDt", r.frameDt), v("substeps", r.substeps), v("stepOnly", r.stepOnly);
  v("implicit", r.implicit), v("frames", r.frames), v("recordEvery", r.recordEvery);
  v("referenceForces", r.referenceForces);
}
template <class V>
void fields(V& v, harness::ClothRequest& r) {
  v("spec", r.spec);
}
template <class V>
void fields(V& v, harness::EmitRequest& r) {
  v("spec", r.spec), v("seed", r.seed), v("count", r.count);
}
template <class V>
void fields(V& v, harness::ParticleRunRequest& r) {
  v("emitter", r.emitter), v("env", r.env), v("coolingRate", r.coolingRate), v("seed", r.seed);
  v("initial", r.initial), v("dt", r.dt), v("steps", r.steps);
  v("referenceForces", r.referenceForces);
}
template <class V>
void fields(V& v, harness::Box2DRequest& r) {
  v("scene", r.scene), v("steps", r.steps), v("drag", r.drag);
}
template <class V>
void fields(V& v, harness::SceneRequest& r) {
  v("scene", r.scene), v("frames", r.frames), v("useDefaults", r.useDefaults);
  v("params", r.params), v("lean", r.lean);
}

template <class V>
void fields(V& v, harness::JacobiansRequest& r) {
  v("spring", r.spring);
}

// Results (after their outcome) -------------------------------------------------------------------

template <class V>
void fields(V& v, harness::SpringForceResult& r) {
  v("force", r.force);
}
template <class V>
void fields(V& v, harness::ForcesResult& r) {
  v("gravity", r.gravity), v("buoyancy", r.buoyancy), v("drag", r.drag);
  v("repulsion", r.repulsion), v("total", r.total);
}
template <class V>
void fields(V& v, harness::SimulateResult& r) {
  v("recordedFrames", r.recordedFrames), v("states", r.states);
}
template <class V>
void fields(V& v, harness::ClothResult& r) {
  v("particles", r.particles), v("springs", r.springs);
}
template <class V>
void fields(V& v, harness::ParticlesResult& r) {
  v("particles", r.particles), v("counts", r.counts);
}
template <class V>
void fields(V& v, harness::Box2DResult& r) {
  v("bodies", r.bodies), v("poses", r.poses), v("joints", r.joints);
  v("builtJoints", r.builtJoints), v("jointCounts", r.jointCounts);
  v("dragJoints", r.dragJoints), v("endDragCleared", r.endDragCleared);
}
template <class V>
void fields(V& v, harness::JacobiansResult& r) {
  v("dfdx", r.dfdx), v("dfdv", r.dfdv);
}
template <class V>
void fields(V& v, SceneEnergy& e) {
  v("kinetic", e.kinetic), v("potential", e.potential);
}
template <class V>
void fields(V& v, harness::SceneResult& r) {
  v("snapshots", r.snapshots), v("energies", r.energies);
}

}  // namespace a6::wire
