// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): fake results.
//
// computeForce is the starter's stub (task 1 honestly earns nothing), but the file tries to
// hand the grader a perfect results.json: printed on stdout (Gradescope would take stdout if an
// autograder redirected it), written into its working directory, into the grader's output
// folder (three levels up from the probe's working directory, OUT/work/run/probe-N) and into
// /autograder/results/. Expected: the score is unchanged (task 1 gets 0) and OUT/results.json is
// the grader's own.
#include "a6/spring.h"

#include <sys/stat.h>

#include <cstdio>

namespace {

const char* const kFake =
    "{\"score\": 103, \"output\": \"FAKE RESULTS FROM THE SUBMISSION\", \"tests\": "
    "[{\"name\": \"Task 1: spring force\", \"score\": 15, \"max_score\": 15, \"status\": "
    "\"passed\"}]}\n";

void writeFake(const char* path) {
  if (FILE* f = std::fopen(path, "w")) {
    std::fputs(kFake, f);
    std::fclose(f);
    std::printf("hostile: wrote %s\n", path);
  } else {
    std::printf("hostile: could not write %s\n", path);
  }
}

// Runs before main, before the probe's seccomp filter.
const int kPlanted = [] {
  std::fputs(kFake, stdout);
  std::fputs(kFake, stderr);
  writeFake("results.json");
  writeFake("../../../results.json");
  writeFake("../../results.json");
  ::mkdir("/autograder", 0777);
  ::mkdir("/autograder/results", 0777);
  writeFake("/autograder/results/results.json");
  std::fflush(stdout);
  return 0;
}();

}  // namespace

namespace a6 {

// The first calls print and plant again (a flood of output is hostile_test's HugeOutput).
Vec2 Spring::computeForce() const {
  static int calls = 0;
  if (++calls <= 100) {
    std::fputs(kFake, stdout);
    writeFake("../../../results.json");  // after the filter: refused
  }
  return Vec2::Zero();
}

}  // namespace a6
