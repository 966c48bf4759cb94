#include "summary.h"

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "comparisons.h"
#include "suite.h"

namespace a6::test {

namespace {

// The margin lines are for the fairness checks (tests/check_run.cmake sets A6_MARGINS=1), not
// for students.
bool marginsWanted() {
  const char* value = std::getenv("A6_MARGINS");
  return value != nullptr && std::string(value) == "1";
}

}  // namespace

TaskSummary::TaskSummary(bool pointToTasks) : pointToTasks_(pointToTasks) {
  margin_.fill(std::numeric_limits<double>::quiet_NaN());
}

void TaskSummary::OnTestEnd(const ::testing::TestInfo& info) {
  const std::string suite = info.test_suite_name();
  if (suite.size() < 5 || suite.compare(0, 4, "Task") != 0) return;
  const int task = suite[4] - '1';
  if (task < 0 || task >= kTaskCount || info.result()->Skipped()) return;
  const ComparisonLog log = comparisonsOf(info);
  if (info.result()->Passed()) {
    ++passed_[task];
    closest_[task] = std::max(closest_[task], log.largestPassingRatio);
    agreement_[task] = std::max(agreement_[task], log.agreement);
    return;
  }
  ++failed_[task];
  const double margin = marginOf(info);
  if (marginsWanted()) {
    std::printf("A6-CHECK-MARGIN %s.%s %s\n", info.test_suite_name(), info.name(),
                num(margin).c_str());
  }
  if (!(margin_[task] <= margin)) margin_[task] = margin;  // NaN: the first failed check
}

namespace {

void printLine(const char* key, const std::array<double, kTaskCount>& values) {
  std::string line = key;
  for (int t = 0; t < kTaskCount; ++t) {
    line += " " + std::to_string(t + 1) + ":" + (std::isnan(values[t]) ? "none" : num(values[t]));
  }
  std::printf("%s\n", line.c_str());
}

}  // namespace

void TaskSummary::OnTestProgramEnd(const ::testing::UnitTest&) {
  int passed = 0, failed = 0;
  std::printf("\nSummary by task\n");
  for (int t = 0; t < kTaskCount; ++t) {
    std::printf("  Task %d  %-20s %3d passed, %3d failed%s\n", t + 1, taskFile(t + 1).c_str(),
                passed_[t], failed_[t], failed_[t] > 0 ? "   <-- look here" : "");
    passed += passed_[t];
    failed += failed_[t];
  }
  // Machine-readable lines for the checks: task:passed:failed ..., then the numbers of
  // comparisons.h per task.
  std::printf("A6-SUMMARY");
  for (int t = 0; t < kTaskCount; ++t) std::printf(" %d:%d:%d", t + 1, passed_[t], failed_[t]);
  std::printf("\n");
  if (marginsWanted()) {
    printLine("A6-MARGIN", margin_);
    printLine("A6-CLOSEST", closest_);
    printLine("A6-AGREEMENT", agreement_);
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  if (pointToTasks_ && failed > 0) {
    std::printf(
        "The failures, task by task: ctest -R Task<N> --output-on-failure, or a6_tests "
        "--gtest_filter='Task<N>*'\n");
  }
  std::fflush(stdout);
}

}  // namespace a6::test
