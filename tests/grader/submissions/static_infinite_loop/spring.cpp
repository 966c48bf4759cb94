// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): an endless loop
// before main.
//
// A correct spring, but a static initializer never returns, so the probe never answers.
// Expected: every check fails on its time limit, a6_grade gives up on the probe after a bounded
// number of starts and finishes.
#include "a6/spring.h"

namespace {
int spin() {
  for (volatile unsigned long i = 0;; i = i + 1) {
  }
  return 0;
}
const int kNever = spin();
}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
