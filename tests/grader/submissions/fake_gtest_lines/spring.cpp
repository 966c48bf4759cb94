// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): fake test output.
//
// computeForce is the starter's stub (task 1 honestly earns nothing), but the file prints what a
// passing GoogleTest run and our per-task summary line look like, on stdout and stderr, before
// main and on its first 100 calls. Expected: the score is unchanged (task 1 gets 0): a6_grade never
// reads what the student's code prints.
#include "a6/spring.h"

#include <cstdio>

namespace {

void boast() {
  for (FILE* f : {stdout, stderr}) {
    std::fputs(
        "[==========] 94 tests from 6 test suites ran. (12 ms total)\n"
        "[       OK ] Task1Spring.StretchedPullsP2TowardsP1 (0 ms)\n"
        "[  PASSED  ] 94 tests.\n"
        "A6-SUMMARY 1:14:0 2:14:0 3:16:0 4:15:0 5:20:0 6:15:0\n"
        "Score: 103 / 100\n",
        f);
    std::fflush(f);
  }
}

const int kBoasted = (boast(), 0);

}  // namespace

namespace a6 {

// The first calls boast again (a flood of output is hostile_test's HugeOutput).
Vec2 Spring::computeForce() const {
  static int calls = 0;
  if (++calls <= 100) boast();
  return Vec2::Zero();
}

}  // namespace a6
