// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): writing on the
// probe's answer pipe.
//
// computeForce returns the starter's zero, but first writes a made-up answer (a length prefix
// and JSON claiming a force) on fd 4, the pipe the probe answers on. Expected: the grader reads
// garbage or a wrong answer, never a pass: task 1 gets 0, every other task keeps its points.
#include "a6/spring.h"

#include <unistd.h>

#include <cstring>

namespace a6 {

Vec2 Spring::computeForce() const {
  const char body[] = "{\"force\":[-10,0],\"error\":\"\"}";
  const unsigned n = sizeof body - 1;
  const unsigned char header[4] = {
      static_cast<unsigned char>(n >> 24), static_cast<unsigned char>(n >> 16),
      static_cast<unsigned char>(n >> 8), static_cast<unsigned char>(n)};
  ssize_t ignored = ::write(4, header, 4);
  ignored = ::write(4, body, n);
  ignored = ::write(4, "junk junk junk", 14);
  (void)ignored;
  return Vec2::Zero();
}

}  // namespace a6
