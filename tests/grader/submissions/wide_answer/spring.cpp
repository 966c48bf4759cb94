// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): the answer frames
// that cost the grader the most memory to decode.
//
// computeForce writes, on fd 4, one frame of the wire's own encoding, MessagePack, chosen by the
// spring: for a damped one, 4 MiB (the grader's cap) of an array of empty maps, one byte each,
// the message whose decoded form is largest for its size, larger than any answer; for a soft
// undamped one, 4 MiB of arrays nested deeper than any answer; for a stiff undamped one, the
// message of those the grader decodes that takes it the most memory: an array of 2 million
// nils. Expected: all three are garbage ("garbage from the probe": the first two refused before
// decoding, the third once decoded), task 1 gets what the starter gets, and a6_grade's peak
// memory stays under 300 MB (results.json, extra_data.grader_peak_rss_mib).
#include "a6/spring.h"

#include <unistd.h>

#include <string>

namespace {

void send(const std::string& body) {
  const auto n = static_cast<unsigned>(body.size());
  const unsigned char header[4] = {
      static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
      static_cast<unsigned char>(n >> 16), static_cast<unsigned char>(n >> 24)};
  ssize_t ignored = ::write(4, header, 4);
  for (std::size_t at = 0; at < body.size();) {
    const ssize_t k = ::write(4, body.data() + at, body.size() - at);
    if (k <= 0) break;
    at += static_cast<std::size_t>(k);
  }
  (void)ignored;
}

}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  constexpr std::size_t kCap = std::size_t{4} << 20;
  auto bigEndian = [](std::size_t n) {
    return std::string{static_cast<char>(n >> 24), static_cast<char>(n >> 16),
                       static_cast<char>(n >> 8), static_cast<char>(n)};
  };
  std::string body;
  // (By the spring, not by a count of calls: after garbage the grader starts a new probe.)
  if (kd > 0) {
    // 0xdd: an array whose length follows in 4 bytes; 0x80: an empty map.
    body = "\xdd" + bigEndian(kCap - 5) + std::string(kCap - 5, '\x80');
  } else if (ks < 50) {
    // 0x91: an array of one item, nested; 0xc0: nil, the innermost item.
    body = std::string(kCap - 1, '\x91') + '\xc0';
  } else {
    // As many nils as the grader decodes (one node each: the most memory of the messages it
    // accepts, measured against maps of nils or of empty maps and arrays of empty strings).
    const std::size_t n = (std::size_t{1} << 21) - 2;
    body = "\xdd" + bigEndian(n) + std::string(n, '\xc0');
  }
  send(body);
  return Vec2::Zero();
}

}  // namespace a6
