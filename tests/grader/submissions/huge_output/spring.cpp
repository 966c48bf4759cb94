// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): huge output.
//
// A correct spring that prints 512 MiB on stdout and 128 MiB on stderr before main, and 256 KiB
// on each of its first 64 calls (a scene calls it millions of times: flooding on every call would
// only make it slow, not hostile). Expected: the output is capped (the report keeps 64 KiB), the
// grader neither hangs nor fills the disk, and the score is the correct spring's: full marks.
#include "a6/spring.h"

#include <unistd.h>

#include <cstring>

namespace {

void flood(int fd, std::size_t bytes) {
  static char chunk[1 << 20];
  std::memset(chunk, 'A', sizeof chunk);
  chunk[sizeof chunk - 1] = '\n';
  while (bytes > 0) {
    const std::size_t n = bytes < sizeof chunk ? bytes : sizeof chunk;
    const ssize_t written = ::write(fd, chunk, n);
    if (written <= 0) return;
    bytes -= static_cast<std::size_t>(written);
  }
}

const int kFlooded = (flood(1, std::size_t{512} << 20), flood(2, std::size_t{128} << 20), 0);

}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  static int calls = 0;
  if (++calls <= 64) flood(1, std::size_t{256} << 10);
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
