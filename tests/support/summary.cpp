#include "summary.h"

#include <cstdio>
#include <string>

namespace a6::test {

void TaskSummary::OnTestEnd(const ::testing::TestInfo& info) {
  const std::string suite = info.test_suite_name();
  if (suite.size() < 5 || suite.compare(0, 4, "Task") != 0) return;
  const int task = suite[4] - '1';
  if (task < 0 || task >= 6 || info.result()->Skipped()) return;
  (info.result()->Passed() ? passed_ : failed_)[task]++;
}

void TaskSummary::OnTestProgramEnd(const ::testing::UnitTest&) {
  static const char* const files[] = {"spring.cpp", "forces.cpp",          "time_stepping.cpp",
                                      "cloth.cpp",  "particle_system.cpp", "joints.cpp"};
  int passed = 0, failed = 0;
  std::printf("\nSummary by task\n");
  for (int t = 0; t < 6; ++t) {
    std::printf("  Task %d  %-20s %3d passed, %3d failed%s\n", t + 1, files[t], passed_[t],
                failed_[t], failed_[t] > 0 ? "   <-- look here" : "");
    passed += passed_[t];
    failed += failed_[t];
  }
  // One machine-readable line for the checks: task:passed:failed ...
  std::printf("A6-SUMMARY");
  for (int t = 0; t < 6; ++t) std::printf(" %d:%d:%d", t + 1, passed_[t], failed_[t]);
  std::printf("\n%d passed, %d failed\n", passed, failed);
  std::fflush(stdout);
}

}  // namespace a6::test
