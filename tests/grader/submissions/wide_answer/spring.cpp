// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): the answer frame that
// costs the grader the most memory to decode.
//
// computeForce writes, on fd 4, one frame just under the grader's cap (4 MiB) of the wire's own
// encoding, CBOR: an array of empty maps, one byte each, the message whose decoded form is
// largest for its size (about 80 bytes of memory a byte), for a damped spring; for an undamped
// one, arrays nested deeper than any answer. Expected: both are garbage ("garbage from the probe":
// more values, or deeper, than any answer), task 1 gets what the starter gets, and a6_grade's peak
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
  std::string body;
  // (By the spring, not by a count of calls: after garbage the grader starts a new probe.)
  if (kd > 0) {
    // 0x9a: an array whose length follows in 4 bytes, big-endian; 0xa0: an empty map.
    const std::size_t n = kCap - 5;
    body = {'\x9a', static_cast<char>(n >> 24), static_cast<char>(n >> 16),
            static_cast<char>(n >> 8), static_cast<char>(n)};
    body += std::string(n, '\xa0');
  } else {
    // 0x81: an array of one item, nested; 0xf6: null, the innermost item.
    body = std::string(kCap - 1, '\x81') + '\xf6';
  }
  send(body);
  return Vec2::Zero();
}

}  // namespace a6
