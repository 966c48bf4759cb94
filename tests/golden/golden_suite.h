// The golden-image tests' in-process driver (golden_main_in_process.cpp): the checks of
// golden_checks.h plus the determinism tests and the command line.
#pragma once

#include "golden_checks.h"

namespace a6::test {

/// Runs the golden-image tests (one per manifest image, GoldenTask<task>.<name>) and the
/// determinism tests against student(): parses GoogleTest's flags and ours (--manifest=FILE,
/// --failures=DIR, --tasks=N,N, --verbose), runs, and prints the summary line
/// "A6-GOLDEN passed=P failed=F skipped=S". Returns the exit status for main().
int runGoldenTests(int argc, char** argv);

}  // namespace a6::test
