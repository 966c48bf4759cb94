// The physics suite's main for the in-process build: the student's six files are linked into
// this binary. At the end it prints a summary per task (summary.h), which the starter and
// wrong-version checks read.
#include <gtest/gtest.h>

#include "suite.h"
#include "summary.h"

namespace {
#include A6_FORCE_MODELS  // reference_models.inc, or own_models.inc in a student release

std::unique_ptr<a6::harness::StudentCode> gStudent;
}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gStudent; }
}  // namespace a6::test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  gStudent = a6::harness::makeInProcess(referenceForceModel());
  ::testing::UnitTest::GetInstance()->listeners().Append(new a6::test::TaskSummary);
  return RUN_ALL_TESTS();
}
