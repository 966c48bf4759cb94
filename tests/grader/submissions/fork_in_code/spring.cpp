// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): fork() in the code.
//
// A correct spring that tries, on every call, to fork a child that would spin forever. The
// probe's seccomp filter refuses fork (EPERM), so the spring goes on and returns the right force.
// Expected: full marks, and no process of the submission is left running after a6_grade ends.
#include "a6/spring.h"

#include <unistd.h>

namespace a6 {

Vec2 Spring::computeForce() const {
  if (::fork() == 0) {
    for (volatile unsigned long i = 0;; i = i + 1) {
    }
  }
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
