// The wire format between the grader and the probe (framework/harness/wire.h): every request and
// result survives the trip with every field bit for bit (NaN, infinities and -0.0 included),
// malformed input gives a clear error, and serve() never throws.
#include "harness/wire.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "harness/wire_fields.h"

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

// Through the pipe's bytes, as the pipe does.
json throughBytes(const json& j) { return wire::fromBytes(wire::toBytes(j)); }

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
  std::string text() { return "name-" + std::to_string(++k) + " \xc3\xa9"; }
  Vec2 vec() {
    const double x = number();
    return Vec2(x, number());
  }
};

// ---- every field, walked through the one field list (harness/wire_fields.h) -------------------

// Gives every listed field of a value its own value (special doubles among them), never its
// default; lists get two elements, each filled.
struct Fill {
  Filler& f;
  void operator()(const char*, double& x) { x = f.number(); }
  void operator()(const char*, int& x) { x = f.integer(); }
  void operator()(const char*, std::uint64_t& x) {
    x = 1000000007ull * static_cast<std::uint64_t>(f.integer() + 100);
  }
  void operator()(const char*, bool& x) { x = !x; }  // never its default
  void operator()(const char*, std::string& x) { x = f.text(); }
  void operator()(const char*, Vec2& x) { x = f.vec(); }
  void operator()(const char*, Mat2& x) {
    x.row(0) = f.vec().transpose();
    x.row(1) = f.vec().transpose();
  }
  template <typename E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void operator()(const char*, E& x) {
    const auto& names = wire::namesOf(x);  // the value after its default
    std::size_t k = 0;
    while (k < std::size(names) && names[k].first != x) ++k;
    x = names[(k + 1) % std::size(names)].first;
  }
  template <typename T>
  void operator()(const char* name, std::vector<T>& items) {
    items.resize(2);
    for (T& item : items) (*this)(name, item);
  }
  template <typename T, std::enable_if_t<std::is_class_v<T>, int> = 0>
  void operator()(const char*, T& x) {
    wire::fields(*this, x);
  }
};

// Every leaf of a value, in order, as "path = exact value" (doubles by their bits): two values
// are the same, field for field and bit for bit, when their leaves are.
struct Leaves {
  std::vector<std::string> out;
  std::string at;
  void leaf(const char* name, const std::string& value) {
    out.push_back(at + name + " = " + value);
  }
  void operator()(const char* name, double x) { leaf(name, std::to_string(bits(x))); }
  void operator()(const char* name, int x) { leaf(name, std::to_string(x)); }
  void operator()(const char* name, std::uint64_t x) { leaf(name, std::to_string(x)); }
  void operator()(const char* name, bool x) { leaf(name, x ? "true" : "false"); }
  void operator()(const char* name, const std::string& x) { leaf(name, x); }
  void operator()(const char* name, const Vec2& x) {
    leaf(name, std::to_string(bits(x.x())) + " " + std::to_string(bits(x.y())));
  }
  void operator()(const char* name, const Mat2& x) {
    leaf(name, std::to_string(bits(x(0, 0))) + " " + std::to_string(bits(x(0, 1))) + " " +
                   std::to_string(bits(x(1, 0))) + " " + std::to_string(bits(x(1, 1))));
  }
  template <typename E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void operator()(const char* name, E x) {
    leaf(name, std::to_string(static_cast<int>(x)));
  }
  template <typename T>
  void operator()(const char* name, const std::vector<T>& items) {
    leaf(name, std::to_string(items.size()) + " items");
    for (std::size_t k = 0; k < items.size(); ++k) {
      (*this)((std::string(name) + "[" + std::to_string(k) + "]").c_str(), items[k]);
    }
  }
  template <typename T, std::enable_if_t<std::is_class_v<T>, int> = 0>
  void operator()(const char* name, const T& x) {
    const std::string outer = at;
    at += std::string(name) + ".";
    wire::fields(*this, const_cast<T&>(x));  // only read
    at = outer;
  }
};

template <typename T>
std::vector<std::string> leavesOf(const T& x) {
  Leaves leaves;
  leaves("", x);
  return leaves.out;
}

// The names a type's field list gives, in order.
struct Names {
  std::vector<std::string> out;
  template <typename M>
  void operator()(const char* name, M&) {
    out.push_back(name);
  }
};
template <typename T>
std::vector<std::string> namesOf(T x) {
  Names names;
  wire::fields(names, x);
  return names.out;
}
std::vector<std::string> keysOf(const json& object, std::vector<std::string> leaveOut = {}) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : object.items()) {
    if (std::find(leaveOut.begin(), leaveOut.end(), key) == leaveOut.end()) keys.push_back(key);
  }
  return keys;
}
std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// How many members an aggregate has (a base class counts as one): the largest N for which
// T{any, ..., any} with N values compiles. So a member added to a wire type and not to its field
// list is caught, though the list alone cannot see it.
struct AnyValue {
  template <typename U>
  operator U() const;  // never called: only in unevaluated braces
};
template <typename T, typename Seq, typename = void>
struct BracesWith : std::false_type {};
template <typename T, std::size_t... I>
struct BracesWith<T, std::index_sequence<I...>,
                  std::void_t<decltype(T{(static_cast<void>(I), AnyValue{})...})>>
    : std::true_type {};
template <typename T, std::size_t N = 0>
constexpr std::size_t memberCount() {
  if constexpr (N > 40 || !BracesWith<T, std::make_index_sequence<N + 1>>::value) {
    return N;
  } else {
    return memberCount<T, N + 1>();
  }
}
template <typename T>
void everyMemberListed(const char* type) {
  const std::size_t outcome = std::is_base_of_v<harness::Outcome, T> ? 1 : 0;
  EXPECT_EQ(memberCount<T>(), namesOf(T{}).size() + outcome)
      << type << ": a member is missing from its field list in harness/wire_fields.h (or the list "
      << "names one twice)";
}

// A value of T with every listed field filled; it must differ from T{} in every leaf that T{}
// has (lists are empty in T{}), so that a field the filler missed cannot pass unseen.
template <typename T>
T filled(Filler& f) {
  T x{};
  Fill fill{f};
  wire::fields(fill, x);
  const std::vector<std::string> before = leavesOf(T{}), after = leavesOf(x);
  for (const std::string& leaf : before) {
    EXPECT_EQ(std::count(after.begin(), after.end(), leaf), 0)
        << leaf << ": the filler left this field at its default";
  }
  return x;
}

// Request kind K: a request filled, encoded under its kind, sent through the pipe's bytes, decoded;
// every field the same, and the body holds exactly the listed fields. Then its result likewise,
// after its outcome ("error" and "fault").
template <std::size_t K>
void kindSurvives(Filler& f) {
  using R = std::variant_alternative_t<K, harness::Request>;
  using Result = typename R::Result;
  everyMemberListed<R>(R::kKind);
  const R a = filled<R>(f);
  const json j = throughBytes(wire::encodeRequest(harness::Request(std::in_place_index<K>, a)));
  EXPECT_EQ(j["kind"], R::kKind);
  EXPECT_EQ(sorted(keysOf(j["body"])), sorted(namesOf(R{}))) << R::kKind;
  const harness::Request b = wire::decodeRequest(j);
  ASSERT_EQ(b.index(), K) << R::kKind;
  EXPECT_EQ(leavesOf(a), leavesOf(std::get<K>(b))) << R::kKind;
  EXPECT_GT(leavesOf(a).size(), namesOf(R{}).size() - 1) << R::kKind;

  everyMemberListed<Result>(R::kKind);
  const Result ra = filled<Result>(f);
  const json rj = throughBytes(wire::encodeResult<R>(ra));
  EXPECT_EQ(sorted(keysOf(rj, {"error", "fault"})), sorted(namesOf(Result{}))) << R::kKind;
  const Result rb = wire::decodeResult<R>(rj);
  EXPECT_EQ(rb.error, ra.error);
  EXPECT_EQ(rb.fault, ra.fault);
  EXPECT_EQ(leavesOf(ra), leavesOf(rb)) << R::kKind;
}
template <std::size_t... K>
void everyKindSurvives(Filler& f, std::index_sequence<K...>) {
  (kindSurvives<K>(f), ...);
}

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
    const json sent = throughBytes(json::array({wire::encodeDouble(x)}));
    const double back = wire::decodeDouble(sent[0]);
    EXPECT_EQ(bits(x), bits(back)) << "value " << x << " encoded as " << sent.dump();
  }
}

TEST(WireDoubles, NonFiniteValuesAreReadableStrings) {
  EXPECT_EQ(wire::encodeDouble(kInf), "inf");
  EXPECT_EQ(wire::encodeDouble(-kInf), "-inf");
  EXPECT_EQ(wire::encodeDouble(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(wire::encodeDouble(fromBits(0x7ff0000000000001ull)), "nan:0x7ff0000000000001");
  EXPECT_TRUE(wire::encodeDouble(-0.0).is_number());
  EXPECT_TRUE(std::signbit(wire::decodeDouble(throughBytes(wire::encodeDouble(-0.0)))));
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
  const json back = throughBytes(list);
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
      ADD_FAILURE() << bad.dump() << " was accepted as a double";
    } catch (const wire::Malformed& e) {
      EXPECT_NE(std::string(e.what()).find("expected a number"), std::string::npos) << e.what();
    }
  }
}

// ---- requests
// ------------------------------------------------------------------------------------------

// Generated from the field lists: every listed field of every request kind and its result
// survives.
TEST(WireRequests, EveryRequestAndResultSurvivesWithEveryField) {
  Filler f;
  everyKindSurvives(f, std::make_index_sequence<std::variant_size_v<harness::Request>>());
}

// What the force channel sends of a particle: each field of fields(Particle) is a force input or
// named as none, so that a member added to Particle is sent to the reference forces or said not
// to matter to them.
TEST(WireFields, EveryFieldOfAParticleIsAForceInputOrSaidNotToBe) {
  Names inputs;
  Particle p;
  wire::forceInputs(inputs, p);
  std::vector<std::string> both = inputs.out;
  both.insert(both.end(), std::begin(wire::kNotForceInputs), std::end(wire::kNotForceInputs));
  EXPECT_EQ(sorted(both), sorted(namesOf(Particle{})))
      << "harness/wire_fields.h: a field of Particle is neither in forceInputs nor in "
         "kNotForceInputs (or is in both)";
}

// The types inside requests and results: every member listed too.
TEST(WireFields, EveryMemberOfEveryTypeInsideIsListed) {
  everyMemberListed<Particle>("Particle");
  everyMemberListed<Spring>("Spring");  // the force channel's
  everyMemberListed<SpringData>("SpringData");
  everyMemberListed<HalfPlane>("HalfPlane");
  everyMemberListed<CircleObstacle>("CircleObstacle");
  everyMemberListed<Contact>("Contact");
  everyMemberListed<Environment>("Environment");
  everyMemberListed<EmitterSpec>("EmitterSpec");
  everyMemberListed<SceneParams>("SceneParams");
  everyMemberListed<ShapeData>("ShapeData");
  everyMemberListed<JointData>("JointData");
  everyMemberListed<View>("View");
  everyMemberListed<Snapshot>("Snapshot");
  everyMemberListed<SceneEnergy>("SceneEnergy");
  everyMemberListed<harness::DragEvent>("DragEvent");
  everyMemberListed<harness::BodyPose>("BodyPose");
  everyMemberListed<harness::BodyInfo>("BodyInfo");
  everyMemberListed<harness::JointInfo>("JointInfo");
}

// A failed result's outcome survives: the fault a probe may report, and its words.
TEST(WireResults, AProbesFaultSurvivesAndOthersAreRefused) {
  harness::SceneResult r;
  r.fail(harness::Fault::Refused, "runScene: frame -1 is outside [0, 36000]");
  const harness::SceneResult back = wire::decodeResult<harness::SceneRequest>(
      throughBytes(wire::encodeResult<harness::SceneRequest>(r)));
  EXPECT_EQ(back.fault, harness::Fault::Refused);
  EXPECT_EQ(back.error, r.error);
  // Only the grader finds crashes, time-outs and the like: a probe claiming one is garbage.
  EXPECT_THROW(
      wire::decodeResult<harness::SceneRequest>(json{{"error", "x"}, {"fault", "timedOut"}}),
      wire::Malformed);
  // An error without a fault is an exception's.
  EXPECT_EQ(wire::decodeResult<harness::SceneRequest>(json{{"error", "x"}}).fault,
            harness::Fault::Exception);
}

TEST(WireResults, AnErrorAloneIsAWholeResultAndKeepsItsText) {
  const json j = throughBytes(json{{"error", "exception: boom"}});
  EXPECT_EQ(wire::decodeResult<harness::SpringForceRequest>(j).error, "exception: boom");
  EXPECT_EQ(wire::decodeResult<harness::SimulateRequest>(j).error, "exception: boom");
  EXPECT_EQ(wire::decodeResult<harness::SceneRequest>(j).error, "exception: boom");
  EXPECT_TRUE(wire::decodeResult<harness::Box2DRequest>(j).poses.empty());
}

TEST(WireResults, InvalidUtf8InAnErrorIsReplacedNotRefused) {
  harness::SpringForceResult r;
  r.error = "exception: bad bytes \xff\xfe here";
  const std::string bytes = wire::toBytes(wire::encodeResult<harness::SpringForceRequest>(r));
  const auto back = wire::decodeResult<harness::SpringForceRequest>(wire::fromBytes(bytes));
  EXPECT_NE(back.error.find("bad bytes"), std::string::npos);
  EXPECT_NE(back.error.find("\xef\xbf\xbd"), std::string::npos) << "U+FFFD in place of bad bytes";
}

TEST(WireResults, ALongErrorIsCutToItsFirst4KiB) {
  harness::SpringForceResult r;
  r.error = "exception: " + std::string(1 << 20, 'x');
  const auto back = wire::decodeResult<harness::SpringForceRequest>(
      wire::fromBytes(wire::toBytes(wire::encodeResult<harness::SpringForceRequest>(r))));
  EXPECT_EQ(back.error.substr(0, 4096), r.error.substr(0, 4096));
  EXPECT_EQ(back.error.substr(4096),
            " (" + std::to_string(r.error.size() - 4096) + " more bytes of this text cut)");
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

TEST(WireMalformed, BadBytesSayTheyAreNotMessagePack) {
  // JSON text, as a probe written for another wire would send, and a message cut short.
  const std::string cut = wire::toBytes(json{{"error", ""}, {"force", {1, 2}}});
  for (const std::string& bad :
       {std::string("{\"error\": \"\", \"force\": [1, 2]}"), cut.substr(0, cut.size() - 3)}) {
    const std::string e = errorOf([&] { wire::fromBytes(bad); });
    EXPECT_EQ(e.rfind("not MessagePack", 0), 0u) << e;
  }
}

TEST(WireMalformed, AMissingFieldIsNamedWithWhereItWas) {
  harness::SimulateResult r;
  r.recordedFrames = {1, 2};
  r.states = {{Particle{}}, {Particle{}, Particle{}}};
  json j = wire::encodeResult<harness::SimulateRequest>(r);
  j["states"][1][1].erase("m");
  const std::string e = errorOf([&] { wire::decodeResult<harness::SimulateRequest>(j); });
  EXPECT_NE(e.find("the answer to simulate"), std::string::npos) << e;
  EXPECT_NE(e.find("states[1][1]"), std::string::npos) << e;
  EXPECT_NE(e.find("missing field 'm'"), std::string::npos) << e;
}

TEST(WireMalformed, AWrongTypeIsNamed) {
  json j = wire::encodeResult<harness::SpringForceRequest>({});
  j["force"] = json::array({1.0});
  EXPECT_NE(
      errorOf([&] { wire::decodeResult<harness::SpringForceRequest>(j); }).find("expected [x, y]"),
      std::string::npos);
  j["force"] = "north";
  EXPECT_NE(errorOf([&] { wire::decodeResult<harness::SpringForceRequest>(j); }).find("force"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              wire::decodeResult<harness::SpringForceRequest>(json::array());
            }).find("expected an object"),
            std::string::npos);
  json cloth = wire::encodeResult<harness::ClothRequest>({});
  cloth["springs"] = json::array(
      {json{{"i", 1.5}, {"j", 0}, {"restLength", 1}, {"ks", 1}, {"kd", 1}, {"type", "shear"}}});
  EXPECT_NE(errorOf([&] {
              wire::decodeResult<harness::ClothRequest>(cloth);
            }).find("expected an integer"),
            std::string::npos);
  cloth["springs"][0]["i"] = 1;
  cloth["springs"][0]["type"] = "rubber";
  EXPECT_NE(errorOf([&] {
              wire::decodeResult<harness::ClothRequest>(cloth);
            }).find("'rubber' is not one of"),
            std::string::npos);
  json counts = wire::encodeResult<harness::EmitRequest>({});
  counts["counts"] = json::array({5000000000LL});
  EXPECT_NE(errorOf([&] {
              wire::decodeResult<harness::EmitRequest>(counts);
            }).find("does not fit an int"),
            std::string::npos);
}

// ---- serve
// ------------------------------------------------------------------------------------------------------

// A StudentCode that remembers the spring request it got and answers it with a fixed result,
// throws on emit when told to, and answers the rest empty.
class Recorder final : public harness::StudentCode {
 public:
  harness::SpringForceRequest springRequest;
  bool throwOnEmit = false;

 private:
  harness::Answer respond(const harness::Request& request) override {
    if (const auto* r = std::get_if<harness::SpringForceRequest>(&request)) {
      springRequest = *r;
      harness::SpringForceResult result;
      result.force = Vec2(std::numeric_limits<double>::quiet_NaN(), -0.0);
      return harness::answerTo<harness::SpringForceRequest>(result);
    }
    if (throwOnEmit && std::holds_alternative<harness::EmitRequest>(request)) {
      throw std::runtime_error("escaped the harness");
    }
    return harness::failedAnswer(request, {});
  }
};

TEST(WireServe, ARequestReachesTheCodeAndItsResultComesBack) {
  Recorder code;
  harness::SpringForceRequest r;
  r.p2.x = Vec2(1, -kInf);
  r.ks = 42;
  const json answer = throughBytes(wire::serve(code, throughBytes(wire::encodeRequest(r))));
  EXPECT_EQ(leavesOf(code.springRequest), leavesOf(r));
  EXPECT_EQ(code.springRequest.ks, 42);
  const auto result = wire::decodeResult<harness::SpringForceRequest>(answer);
  EXPECT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(std::isnan(result.force.x()));
  EXPECT_TRUE(std::signbit(result.force.y()) && result.force.y() == 0.0);
}

TEST(WireServe, AnUnknownKindIsAnErrorNotAnException) {
  Recorder code;
  const json answer = wire::serve(code, json{{"kind", "teleport"}, {"body", json::object()}});
  const auto result = wire::decodeResult<harness::SpringForceRequest>(answer);
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
    EXPECT_NO_THROW(answer = wire::serve(code, bad)) << bad.dump();
    const std::string error = wire::decodeResult<harness::SpringForceRequest>(answer).error;
    EXPECT_NE(error.find("malformed request"), std::string::npos) << bad.dump() << " -> " << error;
  }
}

TEST(WireServe, AnExceptionEscapingTheCodeIsAnError) {
  Recorder code;
  code.throwOnEmit = true;
  const json answer = wire::serve(code, wire::encodeRequest(harness::EmitRequest{}));
  EXPECT_EQ(wire::decodeResult<harness::EmitRequest>(answer).error,
            "exception: escaped the harness");
}

// ---- framing
// -------------------------------------------------------------------------------------------------------

TEST(WireFraming, AFrameIsALittleEndianLengthThenTheBytes) {
  const json message = {{"kind", "x"}, {"body", std::string(300, 'a')}};
  const std::string f = wire::frame(message);
  const std::string bytes = wire::toBytes(message);
  ASSERT_EQ(f.size(), bytes.size() + 4);
  EXPECT_EQ(wire::frameLength(reinterpret_cast<const unsigned char*>(f.data())), bytes.size());
  EXPECT_EQ(static_cast<unsigned char>(f[0]), bytes.size() & 0xff);
  EXPECT_EQ(static_cast<unsigned char>(f[1]), (bytes.size() >> 8) & 0xff);
  EXPECT_EQ(f.substr(4), bytes);
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
  EXPECT_EQ(wire::fromBytes(body), first);
  ASSERT_TRUE(wire::readFrame(fds[0], body));
  EXPECT_EQ(wire::fromBytes(body), second);
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
