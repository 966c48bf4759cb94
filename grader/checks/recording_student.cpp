#include "checks/recording_student.h"

#include <gtest/gtest.h>

#include "harness/tasks.h"

namespace a6::grader {

std::string publicCheckRunning() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (info == nullptr) return "";
  const std::string suite = info->test_suite_name();
  const SuiteOwner owner = courseTasks().ofSuite(suite);
  if (owner.task == 0 || owner.kind != SuiteKind::Public) return "";
  return suite + "." + info->name();
}

harness::Answer RecordingStudent::respond(const harness::Request& request) {
  harness::Answer answer = inner_.ask(request);
  std::string check = publicCheckRunning();
  if (!check.empty() && harness::outcomeOf(answer).ok()) {
    transcript_.exchanges.push_back({std::move(check), request, answer});
  }
  return answer;
}

}  // namespace a6::grader
