// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): an endless loop.
//
// computeForce never returns. Expected: each task 1 check fails when its time limit runs out
// (the probe is killed and restarted), every other task keeps its points, and a6_grade finishes
// in about (task 1 checks) x (time limit).
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  for (volatile unsigned long i = 0;; i = i + 1) {
  }
}

}  // namespace a6
