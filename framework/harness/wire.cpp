// The harness's plain data as JSON (see wire.h for the encoding).
#include "harness/wire.h"

#include <unistd.h>

#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <system_error>
#include <utility>
#include <vector>

namespace a6::wire {

using nlohmann::json;

namespace {

// Doubles
// ------------------------------------------------------------------------------------------

constexpr std::uint64_t kPositiveNaN = 0x7ff8000000000000ull;
constexpr std::uint64_t kNegativeNaN = 0xfff8000000000000ull;

std::uint64_t bitsOf(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

double fromBits(std::uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// Structure access with context -----------------------------------------------------------------

// Prefixes the message of a Malformed thrown by `body` with `where` ("states[2]: ...").
template <typename Body>
auto within(const std::string& where, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const Malformed& e) {
    // "states" + "[2]..." reads "states[2]...", anything else gets a colon.
    throw Malformed(where + (e.what()[0] == '[' ? "" : ": ") + e.what());
  }
}

const json& field(const json& j, const char* name) {
  if (!j.is_object()) {
    throw Malformed(std::string("expected an object with field '") + name + "', got " +
                    j.type_name());
  }
  const auto it = j.find(name);
  if (it == j.end()) throw Malformed(std::string("missing field '") + name + "'");
  return *it;
}

// Decodes member `name` of `j` with `decode`; errors inside it are prefixed with the name.
template <typename Decode>
auto member(const json& j, const char* name, Decode&& decode) -> decltype(decode(j)) {
  const json& value = field(j, name);
  return within(name, [&] { return decode(value); });
}

double getDouble(const json& j, const char* name) { return member(j, name, decodeDouble); }

int getInt(const json& j, const char* name) {
  const json& v = field(j, name);
  if (!v.is_number_integer()) {
    throw Malformed(std::string(name) + ": expected an integer, got " + v.type_name());
  }
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      throw Malformed(std::string(name) + ": " + std::to_string(u) + " does not fit an int");
    }
    return static_cast<int>(u);
  }
  const auto i = v.get<std::int64_t>();
  if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max()) {
    throw Malformed(std::string(name) + ": " + std::to_string(i) + " does not fit an int");
  }
  return static_cast<int>(i);
}

std::uint64_t getUint64(const json& j, const char* name) {
  const json& v = field(j, name);
  if (v.is_number_unsigned()) return v.get<std::uint64_t>();
  throw Malformed(std::string(name) + ": expected an unsigned integer, got " +
                  (v.is_number_integer() ? std::string("a negative integer") : v.type_name()));
}

bool getBool(const json& j, const char* name) {
  const json& v = field(j, name);
  if (!v.is_boolean()) {
    throw Malformed(std::string(name) + ": expected true or false, got " + v.type_name());
  }
  return v.get<bool>();
}

std::string getString(const json& j, const char* name) {
  const json& v = field(j, name);
  if (!v.is_string())
    throw Malformed(std::string(name) + ": expected a string, got " + v.type_name());
  return v.get<std::string>();
}

// Vec2 -------------------------------------------------------------------------------------------

json vec(const Vec2& v) { return json::array({encodeDouble(v.x()), encodeDouble(v.y())}); }

Vec2 toVec(const json& j) {
  if (!j.is_array() || j.size() != 2) {
    throw Malformed(std::string("expected [x, y], got ") +
                    (j.is_array() ? "an array of " + std::to_string(j.size()) : j.type_name()));
  }
  return Vec2(within("[0]", [&] { return decodeDouble(j[0]); }),
              within("[1]", [&] { return decodeDouble(j[1]); }));
}

Vec2 getVec(const json& j, const char* name) { return member(j, name, toVec); }

// Lists ------------------------------------------------------------------------------------------

template <typename T, typename Encode>
json list(const std::vector<T>& items, Encode&& encode) {
  json out = json::array();
  out.get_ref<json::array_t&>().reserve(items.size());
  for (const T& item : items) out.push_back(encode(item));
  return out;
}

template <typename Decode>
auto toList(const json& j, Decode&& decode) -> std::vector<decltype(decode(j))> {
  if (!j.is_array()) throw Malformed(std::string("expected an array, got ") + j.type_name());
  std::vector<decltype(decode(j))> out;
  out.reserve(j.size());
  for (std::size_t k = 0; k < j.size(); ++k) {
    out.push_back(within("[" + std::to_string(k) + "]", [&] { return decode(j[k]); }));
  }
  return out;
}

template <typename Decode>
auto getList(const json& j, const char* name, Decode&& decode) -> std::vector<decltype(decode(j))> {
  return member(j, name, [&](const json& v) { return toList(v, decode); });
}

json ints(const std::vector<int>& v) { return json(v); }
std::vector<int> toInts(const json& j) {
  return toList(j, [](const json& e) {
    if (!e.is_number_integer()) {
      throw Malformed(std::string("expected an integer, got ") + e.type_name());
    }
    const auto i = e.get<std::int64_t>();
    if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max()) {
      throw Malformed(std::to_string(i) + " does not fit an int");
    }
    return static_cast<int>(i);
  });
}

// Enums ------------------------------------------------------------------------------------------

template <typename E, std::size_t N>
std::string enumName(E value, const std::pair<E, const char*> (&names)[N]) {
  for (const auto& [e, name] : names) {
    if (e == value) return name;
  }
  return "unknown";
}

template <typename E, std::size_t N>
E enumValue(const json& j, const char* fieldName, const std::pair<E, const char*> (&names)[N]) {
  const std::string text = getString(j, fieldName);
  for (const auto& [e, name] : names) {
    if (text == name) return e;
  }
  std::string allowed;
  for (const auto& entry : names)
    allowed += std::string(allowed.empty() ? "" : ", ") + entry.second;
  throw Malformed(std::string(fieldName) + ": '" + text + "' is not one of " + allowed);
}

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

// The framework's types
// ----------------------------------------------------------------------------

json enc(const Particle& p) {
  return {{"x", vec(p.x)},
          {"v", vec(p.v)},
          {"f", vec(p.f)},
          {"m", encodeDouble(p.m)},
          {"pinned", p.pinned},
          {"temperature", encodeDouble(p.temperature)},
          {"age", encodeDouble(p.age)},
          {"lifetime", encodeDouble(p.lifetime)}};
}
Particle decParticle(const json& j) {
  Particle p;
  p.x = getVec(j, "x");
  p.v = getVec(j, "v");
  p.f = getVec(j, "f");
  p.m = getDouble(j, "m");
  p.pinned = getBool(j, "pinned");
  p.temperature = getDouble(j, "temperature");
  p.age = getDouble(j, "age");
  p.lifetime = getDouble(j, "lifetime");
  return p;
}

json enc(const SpringData& s) {
  return {{"i", s.i},
          {"j", s.j},
          {"restLength", encodeDouble(s.restLength)},
          {"ks", encodeDouble(s.ks)},
          {"kd", encodeDouble(s.kd)},
          {"type", enumName(s.type, kSpringTypes)}};
}
SpringData decSpring(const json& j) {
  SpringData s;
  s.i = getInt(j, "i");
  s.j = getInt(j, "j");
  s.restLength = getDouble(j, "restLength");
  s.ks = getDouble(j, "ks");
  s.kd = getDouble(j, "kd");
  s.type = enumValue(j, "type", kSpringTypes);
  return s;
}

json enc(const HalfPlane& h) {
  return {{"normal", vec(h.normal)}, {"offset", encodeDouble(h.offset)}};
}
HalfPlane decPlane(const json& j) {
  HalfPlane h;
  h.normal = getVec(j, "normal");
  h.offset = getDouble(j, "offset");
  return h;
}

json enc(const CircleObstacle& c) {
  return {{"center", vec(c.center)}, {"radius", encodeDouble(c.radius)}};
}
CircleObstacle decCircle(const json& j) {
  CircleObstacle c;
  c.center = getVec(j, "center");
  c.radius = getDouble(j, "radius");
  return c;
}

json enc(const Contact& c) { return {{"depth", encodeDouble(c.depth)}, {"normal", vec(c.normal)}}; }
Contact decContact(const json& j) {
  Contact c;
  c.depth = getDouble(j, "depth");
  c.normal = getVec(j, "normal");
  return c;
}

json enc(const Environment& e) {
  return {{"gravity", vec(e.gravity)},
          {"airTemperature", encodeDouble(e.airTemperature)},
          {"buoyancy", encodeDouble(e.buoyancy)},
          {"drag", encodeDouble(e.drag)},
          {"repulsion", encodeDouble(e.repulsion)},
          {"planes", list(e.planes, [](const HalfPlane& h) { return enc(h); })},
          {"circles", list(e.circles, [](const CircleObstacle& c) { return enc(c); })}};
}
Environment decEnvironment(const json& j) {
  Environment e;
  e.gravity = getVec(j, "gravity");
  e.airTemperature = getDouble(j, "airTemperature");
  e.buoyancy = getDouble(j, "buoyancy");
  e.drag = getDouble(j, "drag");
  e.repulsion = getDouble(j, "repulsion");
  e.planes = getList(j, "planes", decPlane);
  e.circles = getList(j, "circles", decCircle);
  return e;
}

json enc(const ClothSpec& s) {
  return {{"n", s.n},
          {"size", encodeDouble(s.size)},
          {"origin", vec(s.origin)},
          {"particleMass", encodeDouble(s.particleMass)},
          {"ksStructural", encodeDouble(s.ksStructural)},
          {"kdStructural", encodeDouble(s.kdStructural)},
          {"shear", s.shear},
          {"ksShear", encodeDouble(s.ksShear)},
          {"kdShear", encodeDouble(s.kdShear)},
          {"bending", s.bending},
          {"ksBending", encodeDouble(s.ksBending)},
          {"kdBending", encodeDouble(s.kdBending)},
          {"pinTopCorners", s.pinTopCorners}};
}
ClothSpec decClothSpec(const json& j) {
  ClothSpec s;
  s.n = getInt(j, "n");
  s.size = getDouble(j, "size");
  s.origin = getVec(j, "origin");
  s.particleMass = getDouble(j, "particleMass");
  s.ksStructural = getDouble(j, "ksStructural");
  s.kdStructural = getDouble(j, "kdStructural");
  s.shear = getBool(j, "shear");
  s.ksShear = getDouble(j, "ksShear");
  s.kdShear = getDouble(j, "kdShear");
  s.bending = getBool(j, "bending");
  s.ksBending = getDouble(j, "ksBending");
  s.kdBending = getDouble(j, "kdBending");
  s.pinTopCorners = getBool(j, "pinTopCorners");
  return s;
}

json enc(const EmitterSpec& s) {
  return {{"position", vec(s.position)},
          {"radius", encodeDouble(s.radius)},
          {"velocity", vec(s.velocity)},
          {"velocitySpread", encodeDouble(s.velocitySpread)},
          {"mass", encodeDouble(s.mass)},
          {"temperatureMin", encodeDouble(s.temperatureMin)},
          {"temperatureMax", encodeDouble(s.temperatureMax)},
          {"lifetimeMin", encodeDouble(s.lifetimeMin)},
          {"lifetimeMax", encodeDouble(s.lifetimeMax)},
          {"rate", encodeDouble(s.rate)}};
}
EmitterSpec decEmitter(const json& j) {
  EmitterSpec s;
  s.position = getVec(j, "position");
  s.radius = getDouble(j, "radius");
  s.velocity = getVec(j, "velocity");
  s.velocitySpread = getDouble(j, "velocitySpread");
  s.mass = getDouble(j, "mass");
  s.temperatureMin = getDouble(j, "temperatureMin");
  s.temperatureMax = getDouble(j, "temperatureMax");
  s.lifetimeMin = getDouble(j, "lifetimeMin");
  s.lifetimeMax = getDouble(j, "lifetimeMax");
  s.rate = getDouble(j, "rate");
  return s;
}

json enc(const SceneParams& p) {
  return {{"ks", encodeDouble(p.ks)},     {"kd", encodeDouble(p.kd)},
          {"substeps", p.substeps},       {"n", p.n},
          {"dt", encodeDouble(p.dt)},     {"gravity", encodeDouble(p.gravity)},
          {"drag", encodeDouble(p.drag)}, {"buoyancy", encodeDouble(p.buoyancy)},
          {"structural", p.structural},   {"shear", p.shear},
          {"bending", p.bending},         {"seed", p.seed}};
}
SceneParams decSceneParams(const json& j) {
  SceneParams p;
  p.ks = getDouble(j, "ks");
  p.kd = getDouble(j, "kd");
  p.substeps = getInt(j, "substeps");
  p.n = getInt(j, "n");
  p.dt = getDouble(j, "dt");
  p.gravity = getDouble(j, "gravity");
  p.drag = getDouble(j, "drag");
  p.buoyancy = getDouble(j, "buoyancy");
  p.structural = getBool(j, "structural");
  p.shear = getBool(j, "shear");
  p.bending = getBool(j, "bending");
  p.seed = getUint64(j, "seed");
  return p;
}

json enc(const ShapeData& s) {
  return {{"kind", enumName(s.kind, kShapeKinds)},
          {"body", s.body},
          {"points", list(s.points, [](const Vec2& v) { return vec(v); })},
          {"center", vec(s.center)},
          {"radius", encodeDouble(s.radius)},
          {"angle", encodeDouble(s.angle)}};
}
ShapeData decShape(const json& j) {
  ShapeData s;
  s.kind = enumValue(j, "kind", kShapeKinds);
  s.body = getInt(j, "body");
  s.points = getList(j, "points", toVec);
  s.center = getVec(j, "center");
  s.radius = getDouble(j, "radius");
  s.angle = getDouble(j, "angle");
  return s;
}

json enc(const JointData& d) {
  return {{"type", d.type},
          {"anchorA", vec(d.anchorA)},
          {"anchorB", vec(d.anchorB)},
          {"centerA", vec(d.centerA)},
          {"centerB", vec(d.centerB)},
          {"groundA", d.groundA},
          {"groundB", d.groundB}};
}
JointData decJointData(const json& j) {
  JointData d;
  d.type = getString(j, "type");
  d.anchorA = getVec(j, "anchorA");
  d.anchorB = getVec(j, "anchorB");
  d.centerA = getVec(j, "centerA");
  d.centerB = getVec(j, "centerB");
  d.groundA = getBool(j, "groundA");
  d.groundB = getBool(j, "groundB");
  return d;
}

json enc(const View& v) { return {{"center", vec(v.center)}, {"height", encodeDouble(v.height)}}; }
View decView(const json& j) {
  View v;
  v.center = getVec(j, "center");
  v.height = getDouble(j, "height");
  return v;
}

json enc(const Snapshot& s) {
  return {{"scene", s.scene},
          {"time", encodeDouble(s.time)},
          {"particles", list(s.particles, [](const Particle& p) { return enc(p); })},
          {"particleRadius", encodeDouble(s.particleRadius)},
          {"springs", list(s.springs, [](const SpringData& d) { return enc(d); })},
          {"planes", list(s.planes, [](const HalfPlane& h) { return enc(h); })},
          {"circles", list(s.circles, [](const CircleObstacle& c) { return enc(c); })},
          {"shapes", list(s.shapes, [](const ShapeData& d) { return enc(d); })},
          {"joints", list(s.joints, [](const JointData& d) { return enc(d); })},
          {"view", enc(s.view)}};
}
Snapshot decSnapshot(const json& j) {
  Snapshot s;
  s.scene = getString(j, "scene");
  s.time = getDouble(j, "time");
  s.particles = getList(j, "particles", decParticle);
  s.particleRadius = getDouble(j, "particleRadius");
  s.springs = getList(j, "springs", decSpring);
  s.planes = getList(j, "planes", decPlane);
  s.circles = getList(j, "circles", decCircle);
  s.shapes = getList(j, "shapes", decShape);
  s.joints = getList(j, "joints", decJointData);
  s.view = member(j, "view", decView);
  return s;
}

// The harness's types
// --------------------------------------------------------------------------------

json enc(const harness::DragEvent& e) {
  return {{"kind", enumName(e.kind, kDragKinds)}, {"step", e.step}, {"target", vec(e.target)}};
}
harness::DragEvent decDrag(const json& j) {
  harness::DragEvent e;
  e.kind = enumValue(j, "kind", kDragKinds);
  e.step = getInt(j, "step");
  e.target = getVec(j, "target");
  return e;
}

json enc(const harness::BodyPose& p) {
  return {{"position", vec(p.position)},
          {"angle", encodeDouble(p.angle)},
          {"velocity", vec(p.velocity)},
          {"angularVelocity", encodeDouble(p.angularVelocity)},
          {"awake", p.awake}};
}
harness::BodyPose decPose(const json& j) {
  harness::BodyPose p;
  p.position = getVec(j, "position");
  p.angle = getDouble(j, "angle");
  p.velocity = getVec(j, "velocity");
  p.angularVelocity = getDouble(j, "angularVelocity");
  p.awake = getBool(j, "awake");
  return p;
}

json enc(const harness::BodyInfo& b) {
  return {{"name", b.name},
          {"mass", encodeDouble(b.mass)},
          {"inertia", encodeDouble(b.inertia)},
          {"localCenter", vec(b.localCenter)}};
}
harness::BodyInfo decBody(const json& j) {
  harness::BodyInfo b;
  b.name = getString(j, "name");
  b.mass = getDouble(j, "mass");
  b.inertia = getDouble(j, "inertia");
  b.localCenter = getVec(j, "localCenter");
  return b;
}

json enc(const harness::JointInfo& i) {
  return {{"type", i.type},
          {"bodyA", i.bodyA},
          {"bodyB", i.bodyB},
          {"anchorA", vec(i.anchorA)},
          {"anchorB", vec(i.anchorB)},
          {"localAnchorA", vec(i.localAnchorA)},
          {"localAnchorB", vec(i.localAnchorB)},
          {"localAxisA", vec(i.localAxisA)},
          {"collideConnected", i.collideConnected},
          {"enableLimit", i.enableLimit},
          {"lower", encodeDouble(i.lower)},
          {"upper", encodeDouble(i.upper)},
          {"enableMotor", i.enableMotor},
          {"motorSpeed", encodeDouble(i.motorSpeed)},
          {"maxMotor", encodeDouble(i.maxMotor)},
          {"length", encodeDouble(i.length)},
          {"minLength", encodeDouble(i.minLength)},
          {"maxLength", encodeDouble(i.maxLength)},
          {"stiffness", encodeDouble(i.stiffness)},
          {"damping", encodeDouble(i.damping)},
          {"maxForce", encodeDouble(i.maxForce)},
          {"target", vec(i.target)},
          {"reactionForce", vec(i.reactionForce)}};
}
harness::JointInfo decJoint(const json& j) {
  harness::JointInfo i;
  i.type = getString(j, "type");
  i.bodyA = getInt(j, "bodyA");
  i.bodyB = getInt(j, "bodyB");
  i.anchorA = getVec(j, "anchorA");
  i.anchorB = getVec(j, "anchorB");
  i.localAnchorA = getVec(j, "localAnchorA");
  i.localAnchorB = getVec(j, "localAnchorB");
  i.localAxisA = getVec(j, "localAxisA");
  i.collideConnected = getBool(j, "collideConnected");
  i.enableLimit = getBool(j, "enableLimit");
  i.lower = getDouble(j, "lower");
  i.upper = getDouble(j, "upper");
  i.enableMotor = getBool(j, "enableMotor");
  i.motorSpeed = getDouble(j, "motorSpeed");
  i.maxMotor = getDouble(j, "maxMotor");
  i.length = getDouble(j, "length");
  i.minLength = getDouble(j, "minLength");
  i.maxLength = getDouble(j, "maxLength");
  i.stiffness = getDouble(j, "stiffness");
  i.damping = getDouble(j, "damping");
  i.maxForce = getDouble(j, "maxForce");
  i.target = getVec(j, "target");
  i.reactionForce = getVec(j, "reactionForce");
  return i;
}

json encParticles(const std::vector<Particle>& ps) {
  return list(ps, [](const Particle& p) { return enc(p); });
}
json encSprings(const std::vector<SpringData>& ss) {
  return list(ss, [](const SpringData& s) { return enc(s); });
}
json encJoints(const std::vector<harness::JointInfo>& js) {
  return list(js, [](const harness::JointInfo& i) { return enc(i); });
}

json request(const char* kind, json body) { return {{"kind", kind}, {"body", std::move(body)}}; }

// The faults a probe may report: what its own code saw. The others are the grader's findings
// about the probe (a crash, a time-out, garbage), which a probe must not claim.
const char* faultName(harness::Fault fault) {
  switch (fault) {
    case harness::Fault::None:
      return "none";
    case harness::Fault::Exception:
      return "exception";
    case harness::Fault::Refused:
      return "refused";
    default:
      return "exception";  // never sent: only the grader finds the others
  }
}
harness::Fault probeFault(const std::string& name) {
  if (name == "none") return harness::Fault::None;
  if (name == "exception") return harness::Fault::Exception;
  if (name == "refused") return harness::Fault::Refused;
  throw Malformed("\"" + name.substr(0, 40) + "\" is not a fault a probe may report");
}

// A result's "error" and "fault", and whether the rest may be absent (an error alone is a
// whole result). An error without a fault is an exception's; a fault without words gets some.
template <typename Result>
bool startResult(const json& j, Result& r) {
  r.error = getString(j, "error");
  const bool hasFault = j.is_object() && j.contains("fault");
  r.fault = hasFault ? probeFault(getString(j, "fault")) : harness::Fault::None;
  if (r.fault == harness::Fault::None && !r.error.empty()) r.fault = harness::Fault::Exception;
  if (r.fault != harness::Fault::None && r.error.empty()) r.error = "failed (no message)";
  return r.fault != harness::Fault::None && j.size() == (hasFault ? 2u : 1u);
}

// Runs a decoder, naming the result type in its error.
template <typename Decode>
auto decodeAs(const char* what, Decode&& decode) -> decltype(decode()) {
  return within(what, decode);
}

}  // namespace

// Doubles ----------------------------------------------------------------------------------------

json encodeDouble(double x) {
  if (std::isfinite(x)) return x;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  const std::uint64_t bits = bitsOf(x);
  if (bits == kPositiveNaN) return "nan";
  if (bits == kNegativeNaN) return "-nan";
  char text[32];
  std::snprintf(text, sizeof text, "nan:0x%016" PRIx64, bits);
  return text;
}

double decodeDouble(const json& j) {
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    if (s == "nan") return fromBits(kPositiveNaN);
    if (s == "-nan") return fromBits(kNegativeNaN);
    if (s.size() == 22 && s.compare(0, 6, "nan:0x") == 0) {
      std::uint64_t bits = 0;
      bool hex = true;
      for (std::size_t k = 6; k < s.size(); ++k) {
        const char c = s[k];
        const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
        if (digit < 0) hex = false;
        bits = bits << 4 | static_cast<std::uint64_t>(digit < 0 ? 0 : digit);
      }
      const double x = fromBits(bits);
      if (hex && std::isnan(x)) return x;
    }
    throw Malformed("expected a number, \"inf\", \"-inf\" or a NaN, got the string \"" +
                    s.substr(0, 40) + "\"");
  }
  throw Malformed(std::string("expected a number, got ") + j.type_name());
}

// Requests ---------------------------------------------------------------------------------------

json encodeSpringForce(const harness::SpringForceRequest& r) {
  return request("springForce", {{"p1", enc(r.p1)},
                                 {"p2", enc(r.p2)},
                                 {"restLength", encodeDouble(r.restLength)},
                                 {"ks", encodeDouble(r.ks)},
                                 {"kd", encodeDouble(r.kd)}});
}
harness::SpringForceRequest decodeSpringForceRequest(const json& j) {
  return decodeAs("SpringForceRequest", [&] {
    harness::SpringForceRequest r;
    r.p1 = member(j, "p1", decParticle);
    r.p2 = member(j, "p2", decParticle);
    r.restLength = getDouble(j, "restLength");
    r.ks = getDouble(j, "ks");
    r.kd = getDouble(j, "kd");
    return r;
  });
}

json encodeForces(const harness::ForcesRequest& r) {
  return request("forces",
                 {{"particle", enc(r.particle)}, {"env", enc(r.env)}, {"contact", enc(r.contact)}});
}
harness::ForcesRequest decodeForcesRequest(const json& j) {
  return decodeAs("ForcesRequest", [&] {
    harness::ForcesRequest r;
    r.particle = member(j, "particle", decParticle);
    r.env = member(j, "env", decEnvironment);
    r.contact = member(j, "contact", decContact);
    return r;
  });
}

json encodeSimulate(const harness::SimulateRequest& r) {
  return request("simulate", {{"particles", encParticles(r.particles)},
                              {"springs", encSprings(r.springs)},
                              {"env", enc(r.env)},
                              {"frameDt", encodeDouble(r.frameDt)},
                              {"substeps", r.substeps},
                              {"stepOnly", r.stepOnly},
                              {"frames", r.frames},
                              {"recordEvery", r.recordEvery},
                              {"referenceForces", r.referenceForces}});
}
harness::SimulateRequest decodeSimulateRequest(const json& j) {
  return decodeAs("SimulateRequest", [&] {
    harness::SimulateRequest r;
    r.particles = getList(j, "particles", decParticle);
    r.springs = getList(j, "springs", decSpring);
    r.env = member(j, "env", decEnvironment);
    r.frameDt = getDouble(j, "frameDt");
    r.substeps = getInt(j, "substeps");
    r.stepOnly = getBool(j, "stepOnly");
    r.frames = getInt(j, "frames");
    r.recordEvery = getInt(j, "recordEvery");
    r.referenceForces = getBool(j, "referenceForces");
    return r;
  });
}

json encodeBuildCloth(const ClothSpec& spec) { return request("buildCloth", enc(spec)); }
ClothSpec decodeBuildClothRequest(const json& j) {
  return decodeAs("ClothSpec", [&] { return decClothSpec(j); });
}

json encodeEmit(const harness::EmitRequest& r) {
  return request("emit", {{"spec", enc(r.spec)}, {"seed", r.seed}, {"count", r.count}});
}
harness::EmitRequest decodeEmitRequest(const json& j) {
  return decodeAs("EmitRequest", [&] {
    harness::EmitRequest r;
    r.spec = member(j, "spec", decEmitter);
    r.seed = getUint64(j, "seed");
    r.count = getInt(j, "count");
    return r;
  });
}

json encodeRunParticles(const harness::ParticleRunRequest& r) {
  return request("runParticles", {{"emitter", enc(r.emitter)},
                                  {"env", enc(r.env)},
                                  {"coolingRate", encodeDouble(r.coolingRate)},
                                  {"seed", r.seed},
                                  {"initial", encParticles(r.initial)},
                                  {"dt", encodeDouble(r.dt)},
                                  {"steps", r.steps},
                                  {"referenceForces", r.referenceForces}});
}
harness::ParticleRunRequest decodeRunParticlesRequest(const json& j) {
  return decodeAs("ParticleRunRequest", [&] {
    harness::ParticleRunRequest r;
    r.emitter = member(j, "emitter", decEmitter);
    r.env = member(j, "env", decEnvironment);
    r.coolingRate = getDouble(j, "coolingRate");
    r.seed = getUint64(j, "seed");
    r.initial = getList(j, "initial", decParticle);
    r.dt = getDouble(j, "dt");
    r.steps = getInt(j, "steps");
    r.referenceForces = getBool(j, "referenceForces");
    return r;
  });
}

json encodeRunBox2D(const harness::Box2DRequest& r) {
  return request("runBox2D",
                 {{"scene", r.scene},
                  {"steps", r.steps},
                  {"drag", list(r.drag, [](const harness::DragEvent& e) { return enc(e); })}});
}
harness::Box2DRequest decodeRunBox2DRequest(const json& j) {
  return decodeAs("Box2DRequest", [&] {
    harness::Box2DRequest r;
    r.scene = getString(j, "scene");
    r.steps = getInt(j, "steps");
    r.drag = getList(j, "drag", decDrag);
    return r;
  });
}

json encodeRunScene(const harness::SceneRequest& r) {
  return request("runScene", {{"scene", r.scene},
                              {"frames", ints(r.frames)},
                              {"useDefaults", r.useDefaults},
                              {"params", enc(r.params)}});
}
harness::SceneRequest decodeRunSceneRequest(const json& j) {
  return decodeAs("SceneRequest", [&] {
    harness::SceneRequest r;
    r.scene = getString(j, "scene");
    r.frames = member(j, "frames", toInts);
    r.useDefaults = getBool(j, "useDefaults");
    r.params = member(j, "params", decSceneParams);
    return r;
  });
}

// Results
// ------------------------------------------------------------------------------------------

json encodeResult(const harness::SpringForceResult& r) {
  return {{"error", r.error}, {"fault", faultName(r.fault)}, {"force", vec(r.force)}};
}
harness::SpringForceResult decodeSpringForce(const json& j) {
  return decodeAs("SpringForceResult", [&] {
    harness::SpringForceResult r;
    if (startResult(j, r)) return r;
    r.force = getVec(j, "force");
    return r;
  });
}

json encodeResult(const harness::ForcesResult& r) {
  return {{"error", r.error},          {"fault", faultName(r.fault)},
          {"gravity", vec(r.gravity)}, {"buoyancy", vec(r.buoyancy)},
          {"drag", vec(r.drag)},       {"repulsion", vec(r.repulsion)},
          {"total", vec(r.total)}};
}
harness::ForcesResult decodeForces(const json& j) {
  return decodeAs("ForcesResult", [&] {
    harness::ForcesResult r;
    if (startResult(j, r)) return r;
    r.gravity = getVec(j, "gravity");
    r.buoyancy = getVec(j, "buoyancy");
    r.drag = getVec(j, "drag");
    r.repulsion = getVec(j, "repulsion");
    r.total = getVec(j, "total");
    return r;
  });
}

json encodeResult(const harness::SimulateResult& r) {
  return {
      {"error", r.error},
      {"fault", faultName(r.fault)},
      {"recordedFrames", ints(r.recordedFrames)},
      {"states", list(r.states, [](const std::vector<Particle>& s) { return encParticles(s); })}};
}
harness::SimulateResult decodeSimulate(const json& j) {
  return decodeAs("SimulateResult", [&] {
    harness::SimulateResult r;
    if (startResult(j, r)) return r;
    r.recordedFrames = member(j, "recordedFrames", toInts);
    r.states = getList(j, "states", [](const json& s) { return toList(s, decParticle); });
    return r;
  });
}

json encodeResult(const harness::ClothResult& r) {
  return {{"error", r.error},
          {"fault", faultName(r.fault)},
          {"particles", encParticles(r.particles)},
          {"springs", encSprings(r.springs)}};
}
harness::ClothResult decodeBuildCloth(const json& j) {
  return decodeAs("ClothResult", [&] {
    harness::ClothResult r;
    if (startResult(j, r)) return r;
    r.particles = getList(j, "particles", decParticle);
    r.springs = getList(j, "springs", decSpring);
    return r;
  });
}

json encodeResult(const harness::ParticlesResult& r) {
  return {{"error", r.error},
          {"fault", faultName(r.fault)},
          {"particles", encParticles(r.particles)},
          {"counts", ints(r.counts)}};
}
harness::ParticlesResult decodeParticles(const json& j) {
  return decodeAs("ParticlesResult", [&] {
    harness::ParticlesResult r;
    if (startResult(j, r)) return r;
    r.particles = getList(j, "particles", decParticle);
    r.counts = member(j, "counts", toInts);
    return r;
  });
}

json encodeResult(const harness::Box2DResult& r) {
  return {{"error", r.error},
          {"fault", faultName(r.fault)},
          {"bodies", list(r.bodies, [](const harness::BodyInfo& b) { return enc(b); })},
          {"poses", list(r.poses,
                         [](const std::vector<harness::BodyPose>& step) {
                           return list(step, [](const harness::BodyPose& p) { return enc(p); });
                         })},
          {"joints", encJoints(r.joints)},
          {"builtJoints", encJoints(r.builtJoints)},
          {"jointCounts", ints(r.jointCounts)},
          {"dragJoints", encJoints(r.dragJoints)},
          {"endDragCleared", ints(r.endDragCleared)}};
}
harness::Box2DResult decodeRunBox2D(const json& j) {
  return decodeAs("Box2DResult", [&] {
    harness::Box2DResult r;
    if (startResult(j, r)) return r;
    r.bodies = getList(j, "bodies", decBody);
    r.poses = getList(j, "poses", [](const json& step) { return toList(step, decPose); });
    r.joints = getList(j, "joints", decJoint);
    r.builtJoints = getList(j, "builtJoints", decJoint);
    r.jointCounts = member(j, "jointCounts", toInts);
    r.dragJoints = getList(j, "dragJoints", decJoint);
    r.endDragCleared = member(j, "endDragCleared", toInts);
    return r;
  });
}

json encodeResult(const harness::SceneResult& r) {
  return {{"error", r.error},
          {"fault", faultName(r.fault)},
          {"snapshots", list(r.snapshots, [](const Snapshot& s) { return enc(s); })}};
}
harness::SceneResult decodeRunScene(const json& j) {
  return decodeAs("SceneResult", [&] {
    harness::SceneResult r;
    if (startResult(j, r)) return r;
    r.snapshots = getList(j, "snapshots", decSnapshot);
    return r;
  });
}

// Serving
// ------------------------------------------------------------------------------------------

json serve(harness::StudentCode& code, const json& message) {
  std::string kind;
  try {
    kind = getString(message, "kind");
    const json& body = field(message, "body");
    if (kind == "springForce")
      return encodeResult(code.springForce(decodeSpringForceRequest(body)));
    if (kind == "forces") return encodeResult(code.forces(decodeForcesRequest(body)));
    if (kind == "simulate") return encodeResult(code.simulate(decodeSimulateRequest(body)));
    if (kind == "buildCloth") return encodeResult(code.buildCloth(decodeBuildClothRequest(body)));
    if (kind == "emit") return encodeResult(code.emit(decodeEmitRequest(body)));
    if (kind == "runParticles") {
      return encodeResult(code.runParticles(decodeRunParticlesRequest(body)));
    }
    if (kind == "runBox2D") return encodeResult(code.runBox2D(decodeRunBox2DRequest(body)));
    if (kind == "runScene") return encodeResult(code.runScene(decodeRunSceneRequest(body)));
    return {{"error", "the probe does not know the request kind '" + kind + "'"},
            {"fault", "refused"}};
  } catch (const Malformed& e) {
    return {
        {"error", "malformed request" + (kind.empty() ? "" : " '" + kind + "'") + ": " + e.what()},
        {"fault", "refused"}};
  } catch (const std::exception& e) {
    return {{"error", std::string("exception: ") + e.what()}, {"fault", "exception"}};
  } catch (...) {
    return {{"error", "exception of unknown type"}, {"fault", "exception"}};
  }
}

// Framing
// ------------------------------------------------------------------------------------------

std::string dump(const json& message) {
  return message.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string frame(const json& message) {
  const std::string text = dump(message);
  if (text.size() > kMaxFrameBytes) {
    throw Malformed("message of " + std::to_string(text.size()) + " bytes is over the limit of " +
                    std::to_string(kMaxFrameBytes) + " bytes");
  }
  const auto n = static_cast<std::uint32_t>(text.size());
  std::string out;
  out.reserve(4 + text.size());
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((n >> (8 * k)) & 0xff));
  out += text;
  return out;
}

std::uint32_t frameLength(const unsigned char header[4]) {
  return static_cast<std::uint32_t>(header[0]) | static_cast<std::uint32_t>(header[1]) << 8 |
         static_cast<std::uint32_t>(header[2]) << 16 | static_cast<std::uint32_t>(header[3]) << 24;
}

json parse(const std::string& text) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    throw Malformed(std::string("not JSON: ") + e.what());
  }
}

namespace {
// Reads exactly `n` bytes; returns how many it got before the end of stream.
std::size_t readFully(int fd, char* data, std::size_t n) {
  std::size_t got = 0;
  while (got < n) {
    const ssize_t k = ::read(fd, data + got, n - got);
    if (k == 0) break;
    if (k < 0) {
      if (errno == EINTR) continue;
      throw std::system_error(errno, std::generic_category(), "reading a request");
    }
    got += static_cast<std::size_t>(k);
  }
  return got;
}
}  // namespace

bool readFrame(int fd, std::string& body) {
  unsigned char header[4];
  const std::size_t got = readFully(fd, reinterpret_cast<char*>(header), 4);
  if (got == 0) return false;
  if (got < 4) throw Malformed("the stream ended inside a frame header");
  const std::uint32_t n = frameLength(header);
  if (n > kMaxFrameBytes) {
    throw Malformed("a frame announces " + std::to_string(n) + " bytes, over the limit of " +
                    std::to_string(kMaxFrameBytes));
  }
  body.assign(n, '\0');
  if (readFully(fd, body.data(), n) < n) throw Malformed("the stream ended inside a frame");
  return true;
}

bool writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t k = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (k < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(k);
  }
  return true;
}

}  // namespace a6::wire
