// What the numeric comparisons of the running check saw (suite.h's EXPECT_VEC_NEAR, EXPECT_CLOSE
// and ManyInputs record here). The physics suite's summary and the grader read it at the end of
// each check:
//   - the margin of a failed check: its largest failing difference over its tolerance (the
//     tolerance would have to grow that much for the check to pass); a check that also failed
//     for a reason that is not a number (an exception, a count, a crash) has an infinite one;
//   - the agreement of a passed check: its largest relative difference where the expected value
//     is exact, about 1e-16 for double arithmetic and 1e-7 for float intermediates.
#pragma once

#include <gtest/gtest.h>

namespace a6::test {

struct ComparisonLog {
  const ::testing::TestInfo* check = nullptr;  ///< the check these numbers belong to
  double largestPassingRatio = 0;  ///< max |difference| / tolerance over passing exact ones
  double largestFailingRatio = 0;  ///< max |difference| / tolerance over failing ones
  double agreement = 0;            ///< max |difference| / scale over exact comparisons
  int reportedFailures = 0;        ///< GoogleTest failures that came from comparisons
  bool codeFailed = false;         ///< the student's code gave no answer to a request
};

/// The log of `check`: empty if no comparison of that check ran.
ComparisonLog comparisonsOf(const ::testing::TestInfo& check);

/// The margin of a finished, failed check (see above); +infinity when a failure was not numeric.
double marginOf(const ::testing::TestInfo& check);

/// Relative differences above this are not double rounding (double gives ~1e-16 per operation;
/// a long trajectory ~1e-11).
constexpr double kBeyondDoubleRounding = 1e-9;

}  // namespace a6::test
