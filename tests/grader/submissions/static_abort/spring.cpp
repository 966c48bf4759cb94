// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): abort() before main.
//
// A correct spring, but a static initializer aborts before main runs, so the probe never
// answers. Expected: a6_grade finishes, every check fails with "killed by SIGABRT".
#include "a6/spring.h"

#include <cstdio>
#include <cstdlib>

namespace {
const int kGone = (std::puts("hostile: aborting before main"), std::abort(), 0);
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
