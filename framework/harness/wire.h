// The harness's requests and results as JSON documents (nlohmann::json), sent between the grader
// and the probe as MessagePack: a double travels as its bytes, never printed or parsed as text
// (with JSON text, the largest part of a grading's CPU). Not CBOR: its strings may come in
// chunks, which nlohmann reads by recursion outside any depth check, so 4 MiB of them could
// overflow the grader's stack; in MessagePack only arrays and maps nest.
//
// Design note: the encoding. decode(encode(x)) is bit-identical for every double (a NaN from
// student code must reach the grader as NaN). A finite double is a number (-0.0 keeps its sign);
// "inf", "-inf", "nan" (the positive quiet NaN), "-nan" (0.0/0.0 on x86) and
// "nan:0x7ff0000000000001" (any other NaN, its bits) are strings. Vectors are [x, y], structures
// objects keyed by their C++ field names, enums lower-case strings. Text that is not UTF-8 (an
// exception's message, any bytes a probe sends) is decoded with U+FFFD for the bad bytes, never
// refused; NaN and infinities sent as numbers, which a probe could write, decode as the same
// values. Framing: a 4-byte little-endian length, then that many bytes; a length above
// kMaxFrameBytes is garbage, never a reason to allocate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "harness/student_code.h"

namespace a6::wire {

/// Thrown by every decoder on malformed input; the message says what and where
/// ("SimulateResult: states[2][5]: missing field 'x'").
struct Malformed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Doubles, one at a time (exposed for the tests) --------------------------------------------------
nlohmann::json encodeDouble(double x);
double decodeDouble(const nlohmann::json& j);  ///< throws Malformed

// Requests: {"kind": the request kind's kKind ("springForce", "simulate", ...), "body": {its
// fields}}. Answers: an object with "error" (empty when the code ran to the end), "fault" and the
// fields of the request's Result.
nlohmann::json encodeRequest(const harness::Request&);
/// A whole request message back; throws Malformed (an unknown kind, a malformed body).
harness::Request decodeRequest(const nlohmann::json& message);

nlohmann::json encodeAnswer(const harness::Answer&);
/// The answer to a request of index `kind` in harness::Request; throws Malformed with a clear
/// message on malformed input (the ProbeClient turns that into the answer's error: "garbage
/// from the probe: ..."). An answer whose error is non-empty may carry nothing else.
harness::Answer decodeAnswer(std::size_t kind, const nlohmann::json&);

/// The typed forms, for a request kind R.
template <class R>
nlohmann::json encodeResult(const typename R::Result& result) {
  return encodeAnswer(harness::answerTo<R>(result));
}
template <class R>
typename R::Result decodeResult(const nlohmann::json& j) {
  return std::get<harness::kKindOf<R>>(decodeAnswer(harness::kKindOf<R>, j));
}

/// Answers one encoded request with `code` (the probe calls this with the in-process
/// implementation); returns the encoded answer. Never throws: a malformed request, an unknown
/// kind or an exception escaping `code` gives an answer whose error says so ({"error": "..."}
/// alone when there is nothing else to say).
nlohmann::json serve(harness::StudentCode& code, const nlohmann::json& request);

/// The largest message either side accepts, bytes (a longer announced length is garbage).
constexpr std::size_t kMaxFrameBytes = std::size_t{256} << 20;

/// The bytes of `message` (MessagePack).
std::string toBytes(const nlohmann::json& message);
/// The 4-byte little-endian length, then toBytes(message). Throws Malformed when the bytes are
/// more than kMaxFrameBytes.
std::string frame(const nlohmann::json& message);
/// The length announced by a 4-byte header.
std::uint32_t frameLength(const unsigned char header[4]);
/// A message back from its bytes; throws Malformed ("not MessagePack: ...") on bad bytes.
nlohmann::json fromBytes(const std::string& bytes);

/// Blocking helpers for the probe's side of the pipe (the grader uses its own, with deadlines).
/// readFrame: false at a clean end of stream (no byte of a new frame); throws Malformed on a
/// truncated frame or a length over kMaxFrameBytes, std::system_error on a read error.
bool readFrame(int fd, std::string& body);
/// Writes all of `bytes`; false (errno set) when the other end is gone or on an error.
bool writeAll(int fd, const std::string& bytes);

}  // namespace a6::wire
