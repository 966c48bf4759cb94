// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): NaN.
//
// computeForce returns NaN in both components. Expected: task 1's checks fail (NaN is never
// within a tolerance) with the actual value shown, every other task keeps its points.
#include "a6/spring.h"

#include <limits>

namespace a6 {

Vec2 Spring::computeForce() const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Vec2(nan, nan);
}

}  // namespace a6
