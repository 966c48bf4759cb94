// Records every check's outcome from GoogleTest's events, and starts each check with its time
// limit from the rubric (checks stage). Takes the rubric and where to start a check's clock;
// gives a TestOutcome per check, and how many were skipped.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "checks/outcome.h"
#include "rubric/rubric.h"

namespace a6::grader {

class Collector : public ::testing::EmptyTestEventListener {
 public:
  /// `startCheck(seconds)` runs as each check starts, with its time limit; `endCheck(outcome)` as
  /// it ends, to mark what the machine may have done to it; `progress` prints a line per check
  /// on stderr.
  Collector(const Rubric& rubric, std::vector<TestOutcome>& out,
            std::function<void(double)> startCheck, std::function<void(TestOutcome&)> endCheck,
            bool progress)
      : rubric_(rubric),
        out_(out),
        startCheck_(std::move(startCheck)),
        endCheck_(std::move(endCheck)),
        progress_(progress) {}

  int skipped() const { return skipped_; }

  void OnTestStart(const ::testing::TestInfo& info) override;
  void OnTestPartResult(const ::testing::TestPartResult& part) override;
  void OnTestEnd(const ::testing::TestInfo& info) override;

 private:
  // The paths of a golden-image check's images (student, reference, difference), if it named
  // them as test properties.
  static std::vector<std::filesystem::path> imagesOf(const ::testing::TestResult& result);

  const Rubric& rubric_;
  std::vector<TestOutcome>& out_;
  std::function<void(double)> startCheck_;
  std::function<void(TestOutcome&)> endCheck_;
  bool progress_;
  TestOutcome current_;
  std::string skipMessage_;
  int skipped_ = 0;
};

}  // namespace a6::grader
