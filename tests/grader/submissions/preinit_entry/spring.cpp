// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a .preinit_array entry
// of its own, to run before the probe's filter if it came first.
//
// The spring is correct. Expected: the build finds the .preinit_array section in the object and
// grades task 1 with the starter's stub (the report says why); every other task keeps its points.
#include "a6/spring.h"

#include <cstdio>

namespace {
void early(int, char**, char**) { std::puts("hostile: ran in .preinit_array"); }
__attribute__((used, section(".preinit_array"))) void (*const kEarly)(int, char**, char**) = &early;
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
