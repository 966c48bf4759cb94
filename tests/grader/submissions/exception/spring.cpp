// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): an exception.
//
// computeForce throws. Expected: task 1's checks fail with the exception's message, every other
// task keeps its points.
#include "a6/spring.h"

#include <stdexcept>

namespace a6 {

Vec2 Spring::computeForce() const { throw std::runtime_error("hostile: thrown from computeForce"); }

}  // namespace a6
