// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): asking the grader for
// the reference spring force.
//
// The grader answers the reference forces of tasks 3 and 5 over two pipes, fds 5 and 6 of the
// probe that runs those steppers (framework/harness/force_channel.h). This spring writes a
// spring request there, in the channel's format, and returns the answer as its own force.
// Expected: the probe that answers task 1 has no such fds (the write fails, "hostile: no force
// channel" in the report), so task 1 earns what the starter earns and every other task keeps
// its points.
#include "a6/spring.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <limits>

namespace a6 {

Vec2 Spring::computeForce() const {
  const double request[12] = {1,         p1->x.x(), p1->x.y(), p1->v.x(),  p1->v.y(), p2->x.x(),
                              p2->x.y(), p2->v.x(), p2->v.y(), restLength, ks,        kd};
  const std::uint32_t n = 12;
  double answer[2];
  if (::write(5, &n, sizeof n) != sizeof n ||
      ::write(5, request, sizeof request) != sizeof request ||
      ::read(6, answer, sizeof answer) != sizeof answer) {
    std::printf("hostile: no force channel\n");
    return Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  std::printf("hostile: the grader answered\n");
  return Vec2(answer[0], answer[1]);
}

}  // namespace a6
