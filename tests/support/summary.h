// The per-task summary every physics-suite main prints at the end: a table for people and one
// machine-readable line for the checks (tests/check_run.cmake):
//   A6-SUMMARY 1:<passed>:<failed> 2:<passed>:<failed> ... 6:<passed>:<failed>
// Tests count for the task named by their suite ("Task3TimeStepping..." is task 3).
#pragma once

#include <gtest/gtest.h>

#include <array>

namespace a6::test {

class TaskSummary : public ::testing::EmptyTestEventListener {
 public:
  void OnTestEnd(const ::testing::TestInfo& info) override;
  void OnTestProgramEnd(const ::testing::UnitTest& unitTest) override;

 private:
  std::array<int, 6> passed_{}, failed_{};
};

}  // namespace a6::test
