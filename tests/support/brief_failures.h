// A short account of a run's failures, for ctest's entries Task1..Task6 (a6_tests --log FILE):
// each failed check by name with its first message, at most kMaxLines lines in all, and every
// message in full in FILE, which the account names. (The summary per task, summary.h, comes
// first.)
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace a6::test {

class BriefFailures : public ::testing::EmptyTestEventListener {
 public:
  static constexpr int kMaxLines = 150;  ///< of the failures printed, besides the summary

  explicit BriefFailures(std::string logPath);
  void OnTestEnd(const ::testing::TestInfo& info) override;
  void OnTestProgramEnd(const ::testing::UnitTest& unitTest) override;

 private:
  struct Failed {
    std::string name;   ///< Task1Spring.AtRestGivesZeroForce
    std::string first;  ///< its first failure's message
    int more = 0;       ///< its other failures
  };
  std::string logPath_;
  std::string log_;  ///< every message in full, as GoogleTest prints them
  std::vector<Failed> failed_;
};

}  // namespace a6::test
