// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a source that includes
// a device, to hold the compiler until its time limit.
//
// Including /dev/ptmx (or a tty) would block the preprocessor forever. Expected: the compiler
// sees no such device (only /dev/null, /dev/zero and /dev/urandom exist for it), so spring.cpp
// does not compile at once, and task 1 is graded with the starter's stub; the grading takes
// seconds, not the compiler's time limit.
#include "a6/spring.h"

#include "/dev/ptmx"
