// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): the solution from
// another checkout on the grading machine.
//
// The test puts a readable copy of the solution's spring.cpp at
// /var/tmp/a6_other_checkout/<this repository's path>/solution/spring.cpp (a TA's second
// checkout, outside the grader's own trees; @A6_SOURCE_DIR@ is replaced by the repository's path
// when the test stages the submission). This file includes it when the compiler can find it, and is
// the starter's stub otherwise. Expected: the compiler sees only the system's headers, the kit and
// the submission (an allow-list), so the stub is compiled and task 1 gets what the starter gets.
#if __has_include("/var/tmp/a6_other_checkout@A6_SOURCE_DIR@/solution/spring.cpp")
#include "/var/tmp/a6_other_checkout@A6_SOURCE_DIR@/solution/spring.cpp"
#else
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const { return Vec2::Zero(); }

}  // namespace a6
#endif
