// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): an answer frame that
// announces 2 GiB.
//
// computeForce writes, on fd 4 (the probe's answer pipe), a frame header announcing 0x7fffffff
// bytes and a few of them. Expected: the grader refuses an answer longer than its cap before
// reading it ("over the limit"), restarts the probe, and task 1 gets what the starter gets;
// a6_grade's memory stays small.
#include "a6/spring.h"

#include <unistd.h>

namespace a6 {

Vec2 Spring::computeForce() const {
  const unsigned n = 0x7fffffffu;
  const unsigned char header[4] = {
      static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
      static_cast<unsigned char>(n >> 16), static_cast<unsigned char>(n >> 24)};
  ssize_t ignored = ::write(4, header, 4);
  ignored = ::write(4, "{\"force\":[", 10);
  (void)ignored;
  return Vec2::Zero();
}

}  // namespace a6
