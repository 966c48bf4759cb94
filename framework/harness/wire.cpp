// The harness's plain data as JSON documents, sent as MessagePack (see wire.h for the encoding).
#include "harness/wire.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include "harness/wire_fields.h"

namespace a6::wire {

using nlohmann::json;

namespace {

// Doubles ----------------------------------------------------------------------------------------

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

// `e` with `where` before it: "states" + "[2]..." reads "states[2]...", anything else gets a colon.
Malformed prefixed(const std::string& where, const Malformed& e) {
  return Malformed(where + (e.what()[0] == '[' ? "" : ": ") + e.what());
}

// Prefixes the message of a Malformed thrown by `body` with `where`: a member's name
// ("states: ...") or a list item's index ("[2]...", written only when it is needed).
template <typename Where, typename Body>
auto within(Where where, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const Malformed& e) {
    if constexpr (std::is_integral_v<Where>) {
      throw prefixed("[" + std::to_string(where) + "]", e);
    } else {
      throw prefixed(where, e);
    }
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

// An int, or Malformed saying why not.
int toInt(const json& v) {
  if (!v.is_number_integer())
    throw Malformed(std::string("expected an integer, got ") + v.type_name());
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      throw Malformed(std::to_string(u) + " does not fit an int");
    }
    return static_cast<int>(u);
  }
  const auto i = v.get<std::int64_t>();
  if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max()) {
    throw Malformed(std::to_string(i) + " does not fit an int");
  }
  return static_cast<int>(i);
}

// The longest text a string from the wire keeps, bytes: an error message of megabytes would be
// kept for every failed request of a check, in every report of it.
constexpr std::size_t kMaxTextBytes = 4096;

// A string's text, at most kMaxTextBytes of it, as valid UTF-8: MessagePack's strings are
// whatever bytes the probe sent, so bad bytes become U+FFFD (nlohmann's replacing writer does
// it; ASCII, nearly every string, as is).
std::string textOf(const json& v) {
  const std::string& sent = v.get_ref<const std::string&>();
  std::string s = sent.substr(0, kMaxTextBytes);
  if (sent.size() > s.size())
    s += " (" + std::to_string(sent.size() - s.size()) + " more bytes of this text cut)";
  if (std::all_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }))
    return s;
  return json::parse(json(s).dump(-1, ' ', false, json::error_handler_t::replace))
      .get<std::string>();
}

std::string getString(const json& j, const char* name) {
  const json& v = field(j, name);
  if (!v.is_string())
    throw Malformed(std::string(name) + ": expected a string, got " + v.type_name());
  return textOf(v);
}

// Vec2 -------------------------------------------------------------------------------------------

json vec(const Vec2& v) { return json::array({encodeDouble(v.x()), encodeDouble(v.y())}); }

Vec2 toVec(const json& j) {
  if (!j.is_array() || j.size() != 2) {
    throw Malformed(std::string("expected [x, y], got ") +
                    (j.is_array() ? "an array of " + std::to_string(j.size()) : j.type_name()));
  }
  const double x = within(0, [&] { return decodeDouble(j[0]); });  // in order: the first
  const double y = within(1, [&] { return decodeDouble(j[1]); });  // bad item is named
  return Vec2(x, y);
}

// Mat2, row by row: [[a00, a01], [a10, a11]] ----------------------------------------------------

json mat(const Mat2& m) {
  return json::array({vec(m.row(0).transpose()), vec(m.row(1).transpose())});
}

Mat2 toMat(const json& j) {
  if (!j.is_array() || j.size() != 2) {
    throw Malformed(std::string("expected [[a, b], [c, d]], got ") +
                    (j.is_array() ? "an array of " + std::to_string(j.size()) : j.type_name()));
  }
  Mat2 m;
  m.row(0) = within(0, [&] { return toVec(j[0]); }).transpose();
  m.row(1) = within(1, [&] { return toVec(j[1]); }).transpose();
  return m;
}

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
    out.push_back(within(k, [&] { return decode(j[k]); }));
  }
  return out;
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
E enumValue(const json& j, const std::pair<E, const char*> (&names)[N]) {
  if (!j.is_string()) throw Malformed(std::string("expected a string, got ") + j.type_name());
  const std::string text = textOf(j);
  for (const auto& [e, name] : names) {
    if (text == name) return e;
  }
  std::string allowed;
  for (const auto& entry : names)
    allowed += std::string(allowed.empty() ? "" : ", ") + entry.second;
  throw Malformed("'" + text + "' is not one of " + allowed);
}

// Any listed type (wire_fields.h) and what its fields hold ------------------------------------

// Whether T has a field list.
template <typename T, typename = void>
struct Listed : std::false_type {};
template <typename T>
struct Listed<T, std::void_t<decltype(fields(std::declval<int&>(), std::declval<T&>()))>>
    : std::true_type {};

json encodeValue(double x) { return encodeDouble(x); }
json encodeValue(int x) { return x; }
json encodeValue(std::uint64_t x) { return x; }
json encodeValue(bool x) { return x; }
json encodeValue(const std::string& x) { return x; }
json encodeValue(const Vec2& x) { return vec(x); }
json encodeValue(const Mat2& x) { return mat(x); }
template <typename E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
json encodeValue(E x) {
  return enumName(x, namesOf(x));
}
template <typename T, std::enable_if_t<Listed<T>::value, int> = 0>
json encodeValue(const T& x);
template <typename T>
json encodeValue(const std::vector<T>& items) {
  return list(items, [](const T& item) { return encodeValue(item); });
}

// Writes each field it is shown into `out`.
struct Writer {
  json& out;
  template <typename M>
  void operator()(const char* name, const M& member) {
    out[name] = encodeValue(member);
  }
};

template <typename T, std::enable_if_t<Listed<T>::value, int>>
json encodeValue(const T& x) {
  json out = json::object();
  Writer writer{out};
  fields(writer, const_cast<T&>(x));  // the writer only reads
  return out;
}

void decodeValue(const json& j, double& x) { x = decodeDouble(j); }
void decodeValue(const json& j, int& x) { x = toInt(j); }
void decodeValue(const json& j, std::uint64_t& x) {
  if (!j.is_number_unsigned()) {
    throw Malformed(std::string("expected an unsigned integer, got ") +
                    (j.is_number_integer() ? std::string("a negative integer") : j.type_name()));
  }
  x = j.get<std::uint64_t>();
}
void decodeValue(const json& j, bool& x) {
  if (!j.is_boolean()) throw Malformed(std::string("expected true or false, got ") + j.type_name());
  x = j.get<bool>();
}
void decodeValue(const json& j, std::string& x) {
  if (!j.is_string()) throw Malformed(std::string("expected a string, got ") + j.type_name());
  x = textOf(j);
}
void decodeValue(const json& j, Vec2& x) { x = toVec(j); }
void decodeValue(const json& j, Mat2& x) { x = toMat(j); }
template <typename E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
void decodeValue(const json& j, E& x) {
  x = enumValue(j, namesOf(x));
}
template <typename T, std::enable_if_t<Listed<T>::value, int> = 0>
void decodeValue(const json& j, T& x);
template <typename T>
void decodeValue(const json& j, std::vector<T>& items) {
  items = toList(j, [](const json& e) {
    T item{};
    decodeValue(e, item);
    return item;
  });
}

// Reads each field it is shown from `in`; a missing or malformed one throws Malformed, named.
struct Reader {
  const json& in;
  template <typename M>
  void operator()(const char* name, M& member) {
    const json& value = field(in, name);
    within(name, [&] { decodeValue(value, member); });
  }
};

template <typename T, std::enable_if_t<Listed<T>::value, int>>
void decodeValue(const json& j, T& x) {
  Reader reader{j};
  fields(reader, x);
}

template <typename T>
T decodeAsValue(const json& j) {
  T x{};
  decodeValue(j, x);
  return x;
}

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
    if (s.size() == 22 && s.compare(0, 6, "nan:0x") == 0 &&
        s.find_first_not_of("0123456789abcdef", 6) == std::string::npos) {
      std::uint64_t bits = 0;  // 16 lower-case hex digits: always read whole
      std::from_chars(s.data() + 6, s.data() + s.size(), bits, 16);
      if (const double x = fromBits(bits); std::isnan(x)) return x;
    }
    throw Malformed("expected a number, \"inf\", \"-inf\" or a NaN, got the string \"" +
                    textOf(j).substr(0, 40) + "\"");
  }
  throw Malformed(std::string("expected a number, got ") + j.type_name());
}

// Requests and answers, any kind ---------------------------------------------------------------

namespace {

// A result: its outcome, then its fields (an error alone is a whole result).
template <typename Result>
json encodeOutcomeAnd(const Result& r) {
  json out = encodeValue(r);
  out["error"] = r.error;
  out["fault"] = faultName(r.fault);
  return out;
}
template <typename Result>
Result decodeOutcomeAnd(const std::string& what, const json& j) {
  return within(what.c_str(), [&] {
    Result r;
    if (startResult(j, r)) return r;
    Reader reader{j};
    fields(reader, r);
    return r;
  });
}

template <std::size_t K>
using KindAt = std::variant_alternative_t<K, harness::Request>;

// The request body of kind K, or nothing when `kind` names another.
template <std::size_t K>
bool decodeIfKind(const std::string& kind, const json& body, harness::Request& out) {
  if (kind != KindAt<K>::kKind) return false;
  out.emplace<K>(within(kind.c_str(), [&] { return decodeAsValue<KindAt<K>>(body); }));
  return true;
}
template <std::size_t... K>
harness::Request decodeKind(const std::string& kind, const json& body, std::index_sequence<K...>) {
  harness::Request out;
  if (!(decodeIfKind<K>(kind, body, out) || ...)) {
    throw Malformed("the probe does not know the request kind '" + kind.substr(0, 40) + "'");
  }
  return out;
}

// The answer to a request of kind K.
template <std::size_t K>
harness::Answer decodeAnswerOf(const json& j) {
  using Result = typename KindAt<K>::Result;
  const std::string what = std::string("the answer to ") + KindAt<K>::kKind;
  return harness::Answer(std::in_place_index<K>, decodeOutcomeAnd<Result>(what, j));
}
template <std::size_t... K>
harness::Answer decodeAnswerAt(std::size_t kind, const json& j, std::index_sequence<K...>) {
  using Decode = harness::Answer (*)(const json&);
  static constexpr Decode kDecoders[] = {&decodeAnswerOf<K>...};
  if (kind >= sizeof...(K)) throw Malformed("no request kind has index " + std::to_string(kind));
  return kDecoders[kind](j);
}

constexpr auto kKinds = std::make_index_sequence<std::variant_size_v<harness::Request>>();

}  // namespace

json encodeRequest(const harness::Request& request) {
  return std::visit(
      [](const auto& r) -> json {
        return {{"kind", r.kKind}, {"body", encodeValue(r)}};
      },
      request);
}

harness::Request decodeRequest(const json& message) {
  return decodeKind(getString(message, "kind"), field(message, "body"), kKinds);
}

json encodeAnswer(const harness::Answer& answer) {
  return std::visit([](const auto& a) { return encodeOutcomeAnd(a); }, answer);
}

harness::Answer decodeAnswer(std::size_t kind, const json& j) {
  return decodeAnswerAt(kind, j, kKinds);
}

// Serving ----------------------------------------------------------------------------------------

json serve(harness::StudentCode& code, const json& message) {
  try {
    return encodeAnswer(code.ask(decodeRequest(message)));
  } catch (const Malformed& e) {
    return {{"error", std::string("malformed request: ") + e.what()}, {"fault", "refused"}};
  } catch (const std::exception& e) {
    return {{"error", std::string("exception: ") + e.what()}, {"fault", "exception"}};
  } catch (...) {
    return {{"error", "exception of unknown type"}, {"fault", "exception"}};
  }
}

// Framing ----------------------------------------------------------------------------------------

std::string toBytes(const json& message) {
  std::string bytes;
  json::to_msgpack(message, bytes);
  return bytes;
}

std::string frame(const json& message) {
  const std::string bytes = toBytes(message);
  if (bytes.size() > kMaxFrameBytes) {
    throw Malformed("message of " + std::to_string(bytes.size()) + " bytes is over the limit of " +
                    std::to_string(kMaxFrameBytes) + " bytes");
  }
  const auto n = static_cast<std::uint32_t>(bytes.size());
  std::string out;
  out.reserve(4 + bytes.size());
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((n >> (8 * k)) & 0xff));
  out += bytes;
  return out;
}

std::uint32_t frameLength(const unsigned char header[4]) {
  return static_cast<std::uint32_t>(header[0]) | static_cast<std::uint32_t>(header[1]) << 8 |
         static_cast<std::uint32_t>(header[2]) << 16 | static_cast<std::uint32_t>(header[3]) << 24;
}

json fromBytes(const std::string& bytes) {
  try {
    return json::from_msgpack(bytes);
  } catch (const json::exception& e) {
    throw Malformed(std::string("not MessagePack: ") + e.what());
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
