// The first divergence (after Columbia's FOSSSim): for a failed check of a stepping task (3, 5
// or 7), its run restarted from the reference's state at every step, one step at a time, so that
// the first step where the student's own step departs from the reference's is found, with the
// quantity that departs (a position, a velocity, a count, a temperature, an age). Asked in the
// checks stage after every check has been collected, while the probe is up.
//
// Takes the student's code, the public checks' transcript, the failed checks and the reference
// steppers (given by the grading: the mistakes library's, none in a student release); gives at
// most one divergence per failed check, for at most kDivergenceChecks checks.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checks/budgeted_student.h"
#include "checks/outcome.h"
#include "checks/transcript.h"

namespace a6::grader {

/// The reference steppers the divergence restarts from (empty: no divergence is looked for).
struct ReferenceSteppers {
  std::function<std::optional<harness::SimulateResult>(const harness::SimulateRequest&)> simulate;
  std::function<std::optional<harness::ParticlesResult>(const harness::ParticleRunRequest&)>
      particles;
};

/// Failed checks looked at, at most, and steps restarted per check, at most.
constexpr std::size_t kDivergenceChecks = 3;
constexpr int kDivergenceSteps = 240;

std::vector<Divergence> findDivergences(BudgetedStudent& student, const Transcript& transcript,
                                        const std::vector<std::string>& failed,
                                        const ReferenceSteppers& reference);

}  // namespace a6::grader
