// The student's code with a witness: every request is passed on unchanged, and when the
// student's code did not answer (in the grader: it crashed, ran out of time or was not run), the
// running check is marked (suite.h: codeFailedInThisCheck), so that its hints, written for wrong
// answers, stay out of a failure that gave no answer. Takes the student's code to pass requests
// to; gives its answers unchanged.
#pragma once

#include "harness/student_code.h"
#include "suite.h"

namespace a6::test {

class WatchedStudent final : public harness::StudentCode {
 public:
  explicit WatchedStudent(harness::StudentCode& inner) : inner_(inner) {}

 private:
  harness::Answer respond(const harness::Request& request) override {
    harness::Answer answer = inner_.ask(request);
    // An exception the student's code threw is its answer to this input, which a hint may
    // explain (an index outside the grid); a crash, a time-out or no run at all is not.
    const harness::Outcome& outcome = harness::outcomeOf(answer);
    if (!outcome.ok() && outcome.fault != harness::Fault::Exception) noteCodeFailed();
    return answer;
  }

  harness::StudentCode& inner_;
};

}  // namespace a6::test
