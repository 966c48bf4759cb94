#include "summary.h"

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "comparisons.h"
#include "suite.h"

namespace a6::test {

namespace {

// The tasks counted.
const std::size_t kSummarizedTasks = static_cast<std::size_t>(courseTasks().count());

// The margin lines are for the fairness checks (tests/check_run.cmake sets A6_MARGINS=1), not
// for students.
bool marginsWanted() {
  const char* value = std::getenv("A6_MARGINS");
  return value != nullptr && std::string(value) == "1";
}

}  // namespace

TaskSummary::TaskSummary(bool pointToTasks)
    : pointToTasks_(pointToTasks),
      passed_(kSummarizedTasks),
      failed_(kSummarizedTasks),
      margin_(kSummarizedTasks, std::numeric_limits<double>::quiet_NaN()),
      closest_(kSummarizedTasks),
      agreement_(kSummarizedTasks) {}

void TaskSummary::OnTestEnd(const ::testing::TestInfo& info) {
  // The physics checks (public and hidden) count, not the images.
  const SuiteOwner suiteOwner = courseTasks().ofSuite(info.test_suite_name());
  if (suiteOwner.task == 0 || !isPhysics(suiteOwner.kind) || info.result()->Skipped()) return;
  const std::size_t task = static_cast<std::size_t>(suiteOwner.task - 1);
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

void printLine(const char* key, const std::vector<double>& values) {
  std::string line = key;
  for (std::size_t t = 0; t < values.size(); ++t) {
    line += " " + std::to_string(t + 1) + ":" + (std::isnan(values[t]) ? "none" : num(values[t]));
  }
  std::printf("%s\n", line.c_str());
}

}  // namespace

void TaskSummary::OnTestProgramEnd(const ::testing::UnitTest&) {
  int passed = 0, failed = 0;
  std::printf("\nSummary by task\n");
  for (std::size_t t = 0; t < kSummarizedTasks; ++t) {
    std::printf("  Task %zu  %-20s %3d passed, %3d failed%s\n", t + 1,
                courseTasks().file(static_cast<int>(t + 1)).c_str(), passed_[t], failed_[t],
                failed_[t] > 0 ? "   <-- look here" : "");
    passed += passed_[t];
    failed += failed_[t];
  }
  // Machine-readable lines for the checks: task:passed:failed ..., then the numbers of
  // comparisons.h per task.
  std::printf("A6-SUMMARY");
  for (std::size_t t = 0; t < kSummarizedTasks; ++t)
    std::printf(" %zu:%d:%d", t + 1, passed_[t], failed_[t]);
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
