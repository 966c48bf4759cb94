// The student's code as the suite sees it, with a memory: every request is passed on to the
// budgeted probe (checks/budgeted_student.h), and those of the public physics checks are kept
// with their answers in a Transcript, for the mistakes stage. Takes the student's code to pass
// requests to; gives its answers unchanged, and the transcript.
#pragma once

#include <string>
#include <utility>

#include "checks/transcript.h"
#include "harness/student_code.h"

namespace a6::grader {

class RecordingStudent final : public harness::StudentCode {
 public:
  explicit RecordingStudent(harness::StudentCode& inner) : inner_(inner) {}

  /// What the public checks asked and got so far.
  const Transcript& transcript() const { return transcript_; }
  Transcript takeTranscript() { return std::move(transcript_); }

 private:
  /// The inner code's answer; kept when a public check asked and the code ran to the end.
  harness::Answer respond(const harness::Request& request) override;

  harness::StudentCode& inner_;
  Transcript transcript_;
};

/// The running check's name when it is a public physics check (Task<N><Suite>.<Name>, not a
/// Task<N>Hidden one), else "".
std::string publicCheckRunning();

}  // namespace a6::grader
