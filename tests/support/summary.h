// The per-task summary every physics-suite main prints at the end: a table for people and
// machine-readable lines for the checks (tests/check_run.cmake):
//   A6-SUMMARY 1:<passed>:<failed> 2:<passed>:<failed> ... 7:<passed>:<failed>
// and, when the environment has A6_MARGINS=1 (the fairness checks), the numbers of comparisons.h:
//   A6-CHECK-MARGIN <check> <margin>                                (each failed check)
//   A6-MARGIN 1:<smallest margin of a failed check, or none> ...   (comparisons.h)
//   A6-CLOSEST 1:<largest difference / tolerance of a passed exact comparison> ...
//   A6-AGREEMENT 1:<largest relative difference of a passed exact comparison> ...
// Tests count for the task named by their suite ("Task3TimeStepping..." is task 3).
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "harness/tasks.h"

namespace a6::test {

class TaskSummary : public ::testing::EmptyTestEventListener {
 public:
  /// `pointToTasks`: the run printed no failure itself; the summary says where to see them.
  explicit TaskSummary(bool pointToTasks = false);
  void OnTestEnd(const ::testing::TestInfo& info) override;
  void OnTestProgramEnd(const ::testing::UnitTest& unitTest) override;

 private:
  bool pointToTasks_ = false;
  // Per task, task t at [t - 1].
  std::vector<int> passed_, failed_;
  std::vector<double> margin_, closest_, agreement_;
};

}  // namespace a6::test
