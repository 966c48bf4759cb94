// The replays' runs (checks stage, after every check has run and been collected, so they can
// change no score): each scene the public images check, run once more by the student's code from
// frame 0 to its last image (at least 60 frames), about 60 of its frames recorded for the
// report's player. Takes the student's code (the budgeted probe: the time budget still holds)
// and the scenes; gives each scene's run, or why there is none.
#pragma once

#include <string>
#include <vector>

#include "checks/budgeted_student.h"
#include "checks/scene_run.h"
#include "golden_checks.h"

namespace a6::grader {

/// The time one scene's replay may take, s (the probe's; beyond it the replay is left out).
constexpr double kReplaySeconds = 10;

std::vector<SceneRun> runReplays(BudgetedStudent& student,
                                 const std::vector<a6::test::ImagedScene>& scenes);

}  // namespace a6::grader
