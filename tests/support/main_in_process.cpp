// The physics suite's main for the in-process build: the student's six files are linked into
// this binary. At the end it prints a summary per task (summary.h), which the starter and
// wrong-version checks read.
#include <gtest/gtest.h>

#include <string>

#include "suite.h"
#include "summary.h"

namespace {
#include A6_FORCE_MODELS  // reference_models.inc, or own_models.inc in a student release

std::unique_ptr<a6::harness::StudentCode> gStudent;
}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gStudent; }
}  // namespace a6::test

// --summary-only: GoogleTest's own printer is left out, so a run prints the summary per task and
// nothing else (ctest's whole-suite entry, `physics`: the entries Task1..Task6 show the failures).
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  bool summaryOnly = false;
  for (int k = 1; k < argc; ++k)
    summaryOnly = summaryOnly || std::string(argv[k]) == "--summary-only";
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  if (summaryOnly) delete listeners.Release(listeners.default_result_printer());
  gStudent = a6::harness::makeInProcess(referenceForceModel());
  listeners.Append(new a6::test::TaskSummary(summaryOnly));
  return RUN_ALL_TESTS();
}
