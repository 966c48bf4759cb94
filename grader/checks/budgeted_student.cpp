#include "checks/budgeted_student.h"

#include <algorithm>
#include <sstream>

namespace a6::grader {

namespace {
BudgetedStudent::Clock::duration durationOf(double s) {
  return std::chrono::duration_cast<BudgetedStudent::Clock::duration>(
      std::chrono::duration<double>(s));
}
double secondsUntil(BudgetedStudent::Clock::time_point t) {
  return std::chrono::duration<double>(t - BudgetedStudent::Clock::now()).count();
}
}  // namespace

void BudgetedStudent::setTotalBudget(double s) {
  budget_ = s;
  budgetEnd_ = Clock::now() + durationOf(s);
}

void BudgetedStudent::startTest(double s) {
  limit_ = s;
  answersAtStart_ = probes_ ? probes_->forceAnswers() : 0;
  deadline_ = Clock::now() + durationOf(s);
  lastFailure_.clear();
  machineFault_ = graderFault_ = false;
  closeCheck();
  if (probes_) {
    probes_->allowMoreStarts(kStartsPerCheck);
    probes_->startCheck(s, budgetEnd_);
  }
}

int BudgetedStudent::checksOutOfTime() {
  closeCheck();
  return checksOutOfTime_ + (budgetSpent_ ? 1 : 0);
}

void BudgetedStudent::closeCheck() {
  const int timeouts = probes_ ? probes_->incidents().timeouts : 0;
  if (outOfTime_ || timeouts > timeoutsAtStart_) ++checksOutOfTime_;
  timeoutsAtStart_ = timeouts;
  outOfTime_ = false;
}

std::string BudgetedStudent::refusal() {
  const double overall = secondsUntil(budgetEnd_);
  if (overall < 0.01) {
    budgetSpent_ = true;
    std::ostringstream out;
    out << "not run: the checks before it used up the time all checks together may take ("
        << budget_ << " s; their messages say which ran out of time)";
    return out.str();
  }
  const double allowance =
      probes_ ? forceWaitAllowance(probes_->forceAnswers() - answersAtStart_, limit_) : 0;
  if (secondsUntil(deadline_) + allowance < 0.01) {
    outOfTime_ = true;
    machineFault_ = true;  // the time ran out between requests: a busy machine, maybe
    std::ostringstream out;
    out << "this check's time limit of " << limit_
        << " s ran out (is there an endless loop, or a loop that runs far too often?)";
    return out.str();
  }
  return "";
}

double BudgetedStudent::budgetLeft() const { return secondsUntil(budgetEnd_); }

void BudgetedStudent::interpret(harness::Outcome& result) {
  switch (result.fault) {
    case harness::Fault::TimedOut:
    case harness::Fault::Killed:  // the machine, or the code itself (raise(SIGKILL)): charged
      machineFault_ = true;       // when it repeats
      break;
    case harness::Fault::StartFailed:
    case harness::Fault::GraderError:
      machineFault_ = graderFault_ = true;
      break;
    default:
      break;
  }
  switch (result.fault) {
    case harness::Fault::None:
      return;
    case harness::Fault::StartFailed:  // the sandbox could not start it: a grader problem
      if (startError_.empty()) startError_ = result.error;
      lastFailure_ = result.error;
      return;
    case harness::Fault::StartsUsedUp:  // say why, in the check's terms
      result.error =
          reworded("your code crashed or ran out of time " + std::to_string(kStartsPerCheck) +
                   " times in this check, so its other requests were not run" +
                   (lastFailure_.empty() ? "" : "; the last time: " + lastFailure_));
      return;
    default:
      lastFailure_ = result.error;
  }
}

harness::Answer BudgetedStudent::respond(const harness::Request& request) {
  auto failed = [&](harness::Fault fault, std::string words) {
    harness::Outcome why;
    why.fail(fault, std::move(words));
    return harness::failedAnswer(request, std::move(why));
  };
  if (probe_ == nullptr) return failed(harness::Fault::Unavailable, reworded(unavailable_));
  if (std::string why = refusal(); !why.empty()) {
    return failed(harness::Fault::NotRun, reworded(std::move(why)));
  }
  try {
    harness::Answer answer = probe_->ask(request);
    interpret(harness::outcomeOf(answer));
    return answer;
  } catch (const std::exception& e) {
    machineFault_ = graderFault_ = true;
    return failed(harness::Fault::GraderError,
                  std::string("the grader could not run your code: ") + e.what());
  } catch (...) {
    machineFault_ = graderFault_ = true;
    return failed(harness::Fault::GraderError,
                  "the grader could not run your code (unknown error)");
  }
}

}  // namespace a6::grader
