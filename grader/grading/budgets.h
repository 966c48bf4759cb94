// The time one grading may take: its build's, the student's code's and the grader's own. Read by
// the build (build/), the checks (checks/) and the tests that hold a grading to them; in
// grading/, the stage that runs the others, since the bound is the whole grading's.
#pragma once

namespace a6::grader {

/// The whole build of one submission may take this long (s): every compile gets what is left
/// of it, up to its own limit; a file not compiled when it is used up is graded with the
/// starter's stub.
constexpr double kDefaultBuildBudget = 150;

/// Each link gets at least this much, s, even when the build's budget is spent (a build links its
/// two probes, and again for a link the machine ended or a file that keeps the probe from
/// starting).
constexpr double kLinkAllowance = 10;

/// The time the student's code may take over all checks together (--time-budget), s: well
/// within Gradescope's default of 10 minutes for the whole run, which would otherwise end it
/// with a 0.
constexpr double kDefaultTimeBudget = 420;

/// The grader's own work in one grading, s: intake, the links past the budget, the start-up
/// checks (build/startup.h: a few runs of 5 s, only for a program that does not start), its
/// side of the checks, naming the mistakes, the replays, the report. Seconds on an idle machine
/// (Gradescope's run_autograder allows 30: TIME_LIMIT is the build's budget, TIME_BUDGET and
/// 30 s); this much beside CI's load (other graders, builds and CPU hogs on every core).
constexpr double kOwnWorkSeconds = 120;

/// The wall time of a grading, whatever the code does, s: the build's budget and a link's
/// allowance, the student's `timeBudget`, and the grader's own work as loaded as CI's. The
/// hostile ctests hold every grading to it.
constexpr double maxGradingSeconds(double timeBudget) {
  return kDefaultBuildBudget + kLinkAllowance + timeBudget + kOwnWorkSeconds;
}

}  // namespace a6::grader
