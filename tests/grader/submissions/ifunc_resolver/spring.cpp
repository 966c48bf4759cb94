// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): code that runs before
// every constructor, even before the probe's .preinit_array.
//
// An ifunc resolver runs while the dynamic loader relocates the program, before any filter can
// be installed; this one would open files there. The spring is correct. Expected: the build finds
// the ifunc symbol in the object and grades task 1 with the starter's stub (the report says
// why); every other task keeps its points.
#include "a6/spring.h"

#include <cstdio>

extern "C" {
static int answer() { return 42; }
static void* resolveAnswer() {
  if (FILE* f = std::fopen("/etc/hostname", "rb")) {
    std::puts("hostile: READ before the filter");
    std::fclose(f);
  }
  return reinterpret_cast<void*>(&answer);
}
int hostileAnswer() __attribute__((ifunc("resolveAnswer")));
}

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
