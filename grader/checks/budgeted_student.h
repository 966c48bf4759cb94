// The student's code as the suite sees it in the grader (checks stage): the probe, within the
// running check's time limit and the time budget of all checks together. Without a probe (the
// build failed) every request fails with the reason, so each check fails with a message
// instead of the grader stopping. Takes the probes; gives each request's result
// and, at the end, how many checks ran out of time.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "common/limits.h"
#include "harness/student_code.h"
#include "probe/probe_pair.h"

namespace a6::grader {

/// A check whose requests crash the probe (or run out of time) gets this many probe starts; its
/// other requests then fail at once. So code that crashes on every call costs its own checks,
/// not the probe's restarts for every task after it.
constexpr int kStartsPerCheck = 3;

class BudgetedStudent final : public harness::StudentCode {
 public:
  using Clock = std::chrono::steady_clock;

  /// `code` may be null: every request then fails with `unavailable`. `probes` (null when `code`
  /// is not the probes) are given each check's time window and starts, and say how many forces
  /// they were answered and how many requests they stopped.
  BudgetedStudent(harness::StudentCode* code, ProbePair* probes, std::string unavailable)
      : probe_(code), probes_(probes), unavailable_(std::move(unavailable)) {}

  /// Why the probe could not be started at all (a grader problem), or "".
  const std::string& startError() const { return startError_; }

  /// All checks together may use `seconds` of the student's code's time, from now on.
  void setTotalBudget(double seconds);
  /// A new check starts: its requests share `seconds` of wall-clock time (plus the allowance
  /// for the forces the grader answers meanwhile).
  void startTest(double seconds);
  /// How many checks ran out of their time (a request stopped at its limit, or the check's
  /// limit reached between requests), each counted once, plus one when the time budget of all
  /// checks was spent.
  int checksOutOfTime();
  /// Whether the machine may have ended the running check, not the code: a request stopped at a
  /// time limit or killed by a SIGKILL the grader did not send, a probe that could not start, a
  /// grader error. Such a check is run again (runChecks).
  bool machineMayHaveEndedIt() const { return machineFault_; }
  /// Whether the running check failed for the grader alone (the probe could not start, the
  /// grader erred): run again, a repeat of it is the machine's, not the code's.
  bool graderFailedIt() const { return graderFault_; }
  /// The time left of the budget of all checks, s.
  double budgetLeft() const;

 private:
  /// The probe's answer, within the check's time and the budget; or why it was not asked.
  harness::Answer respond(const harness::Request& request) override;
  // Why a request is not sent at all (the budget or the check's time spent), or "".
  std::string refusal();
  // The probe's answer, with a used-up check's starts said in the check's terms.
  void interpret(harness::Outcome& result);
  // Counts the check that just ended if it ran out of time, once however many of its
  // requests did.
  void closeCheck();

  harness::StudentCode* probe_;
  ProbePair* probes_;
  std::string unavailable_;
  std::string lastFailure_;  // the last failed request of the running check
  std::string startError_;
  // The running check ran out of its time between requests; the probes' time-outs when it began.
  bool outOfTime_ = false;
  bool machineFault_ = false;  // see machineMayHaveEndedIt()
  bool graderFault_ = false;   // see graderFailedIt()
  int timeoutsAtStart_ = 0;
  int checksOutOfTime_ = 0;
  bool budgetSpent_ = false;
  double limit_ = kDefaultTimeLimit;
  Clock::time_point deadline_ = Clock::now();
  std::size_t answersAtStart_ = 0;
  double budget_ = 0;
  Clock::time_point budgetEnd_ = Clock::time_point::max();
};

}  // namespace a6::grader
