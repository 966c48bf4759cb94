// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a segmentation fault.
//
// computeForce writes through a null pointer. Expected: each task 1 check fails with "the probe
// crashed: killed by SIGSEGV", the probe is restarted, every other task keeps its points.
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  volatile int* nowhere = nullptr;
  *nowhere = 1;
  return Vec2::Zero();
}

}  // namespace a6
