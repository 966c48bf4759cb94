// The physics suite's main for the in-process build: the student's six files are linked into
// this binary. At the end it prints a summary per task, which the starter and wrong-version
// checks read.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "suite.h"

namespace {
#include "reference_models.inc"

std::unique_ptr<a6::harness::StudentCode> gStudent;

// Counts passed and failed tests per task, from the suite name "TaskN...".
class TaskSummary : public ::testing::EmptyTestEventListener {
 public:
  void OnTestEnd(const ::testing::TestInfo& info) override {
    const std::string suite = info.test_suite_name();
    if (suite.size() < 5 || suite.compare(0, 4, "Task") != 0) return;
    const int task = suite[4] - '1';
    if (task < 0 || task >= 6 || info.result()->Skipped()) return;
    (info.result()->Passed() ? passed_ : failed_)[task]++;
  }
  void OnTestProgramEnd(const ::testing::UnitTest&) override {
    static const char* const files[] = {"spring.cpp", "forces.cpp", "time_stepping.cpp",
                                        "cloth.cpp", "particle_system.cpp", "joints.cpp"};
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

 private:
  std::array<int, 6> passed_{}, failed_{};
};
}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gStudent; }
}  // namespace a6::test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  gStudent = a6::harness::makeInProcess(referenceForceModel());
  ::testing::UnitTest::GetInstance()->listeners().Append(new TaskSummary);
  return RUN_ALL_TESTS();
}
