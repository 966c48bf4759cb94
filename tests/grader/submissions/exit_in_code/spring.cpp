// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): exit(0) mid-request.
//
// computeForce ends the program with status 0 (as if everything had gone well). Expected: each
// task 1 check fails with "the probe crashed: exited with 0", every other task keeps its points.
#include "a6/spring.h"

#include <cstdlib>

namespace a6 {

Vec2 Spring::computeForce() const { std::exit(0); }

}  // namespace a6
