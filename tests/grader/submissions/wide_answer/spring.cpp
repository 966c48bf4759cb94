// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): the answer frame that
// costs the grader the most memory to parse.
//
// computeForce writes, on fd 4, one frame just under the grader's cap (4 MiB): an array of empty
// objects, the JSON whose parsed form is largest for its size, then one of arrays nested deeper
// than any answer. Expected: both are garbage ("garbage from the probe"), task 1 gets what the
// starter gets, and a6_grade's peak memory stays under 300 MB (results.json,
// extra_data.grader_peak_rss_mib).
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

int gCalls = 0;

}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  constexpr std::size_t kCap = std::size_t{4} << 20;
  std::string body;
  if (gCalls++ % 2 == 0) {
    body = "[";
    while (body.size() + 4 < kCap) body += "{},";
    body += "{}]";
  } else {
    body = std::string(kCap / 2 - 1, '[') + std::string(kCap / 2 - 1, ']');
  }
  send(body);
  return Vec2::Zero();
}

}  // namespace a6
