// The golden-image tests as a library: they reach the student's code only through a
// harness::StudentCode, so they link without student code (the grader can run them against its
// sandboxed probe, rendering and comparing in its own process).
#pragma once

#include "harness/student_code.h"

namespace a6::test {

/// Runs the golden-image tests (one per manifest image, GoldenTask<task>.<name>) and the
/// determinism tests against `student`: parses GoogleTest's flags and ours (--manifest=FILE,
/// --failures=DIR, --tasks=N,N, --verbose), runs, and prints the summary line
/// "A6-GOLDEN passed=P failed=F skipped=S". Returns the exit status for main().
int runGoldenTests(int argc, char** argv, harness::StudentCode& student);

}  // namespace a6::test
