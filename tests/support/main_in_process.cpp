// The physics suite's main for the in-process build: the student's seven files are linked into
// this binary. At the end it prints a summary per task (summary.h), which the starter and
// wrong-version checks read.
#include <gtest/gtest.h>

#include <string>

#include "brief_failures.h"
#include "suite.h"
#include "summary.h"
#include "watched_student.h"

namespace {
#include A6_FORCE_MODELS  // grader/reference/physics.inc, or own_models.inc in a student release

std::unique_ptr<a6::harness::StudentCode> gStudent;
std::unique_ptr<a6::test::WatchedStudent> gWatched;
}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gWatched; }
}  // namespace a6::test

// --summary-only: GoogleTest's own printer is left out, so a run prints the summary per task and
// nothing else (ctest's whole-suite entry, `physics`: the entries Task1..Task6 show the failures).
// --log FILE: the summary, then each failed check with its first message (at most
// BriefFailures::kMaxLines lines), every message in full in FILE (the entries Task1..Task6).
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  bool summaryOnly = false;
  std::string log;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    summaryOnly = summaryOnly || arg == "--summary-only";
    if (arg == "--log" && k + 1 < argc) log = argv[++k];
  }
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  if (summaryOnly || !log.empty()) delete listeners.Release(listeners.default_result_printer());
  gStudent = a6::harness::makeInProcess(referenceForceModel());
  gWatched = std::make_unique<a6::test::WatchedStudent>(*gStudent);
  // GoogleTest tells the end of the run to its listeners last first: the summary comes first.
  if (!log.empty()) listeners.Append(new a6::test::BriefFailures(log));
  listeners.Append(new a6::test::TaskSummary(summaryOnly));
  return RUN_ALL_TESTS();
}
