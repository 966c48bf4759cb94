// What one check gave (checks/), and what the student's code did across the checks that a TA
// may want to look at though it was graded. The checks stage makes them; scoring, mistakes and
// the report read them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace a6::grader {

/// One test as run in the grader's process.
struct TestOutcome {
  std::string name;  ///< "Task1Spring.AtRestGivesZeroForce"
  bool passed = false;
  std::string message;  ///< the failure messages (input, expected, actual, hint)
  double seconds = 0;
  /// The largest relative difference of its exact comparisons (tests/support/comparisons.h)
  /// when it is beyond double rounding (about 1e-7 for float intermediates), else 0.
  double agreement = 0;
  /// For golden-image checks: paths of the images (student, reference, difference), if any.
  std::vector<std::filesystem::path> images;
  /// The machine may have ended it, not the code (a time limit, a probe killed or not started):
  /// a failed check so marked is run again (checks stage). Not in results.json.
  bool machineMayHaveEndedIt = false;
  /// It failed for the grader alone (a probe that could not start, a grader error): a repeat
  /// makes the grading the machine's failure, never the student's 0.
  bool graderFailedIt = false;
  bool ranAgain = false;  ///< this is the outcome of its second run
};

/// What the student's code did that a TA may want to look at, though it was graded: probes that
/// crashed, requests and checks stopped at a time limit (or not run when the time budget was
/// spent), probes that did not start. results.json's extra_data.incidents.
struct Incidents {
  int crashes = 0, timeouts = 0, startFailures = 0;
};

/// A failed stepping check's first divergence (checks/divergence.h).
struct Divergence {
  std::string check;     ///< the failed check whose run it restarted
  int step = 0;          ///< the first step (1-based) whose student step departs; 0: none did
  int steps = 0;         ///< the steps it restarted from
  std::string quantity;  ///< "particle 2's velocity", "the count of particles"
  std::string text;      ///< one sentence for the student
};

}  // namespace a6::grader
