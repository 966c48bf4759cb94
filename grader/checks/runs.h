// The replays' runs (made in the checks stage, after every check has been collected, so they can
// change no score): each scene the public images check, run once more by the student's code from
// frame 0 to its last image (at least 60 frames), about 60 of its frames recorded for the
// report's player. A scene whose images' run failed (it crashed or ran out of time) is not run
// again: its replay says why the images failed. Takes the student's code (the budgeted probe: the
// time budget still holds) and the scenes; gives each scene's run, or why there is none.
#pragma once

#include <string>
#include <vector>

#include "checks/budgeted_student.h"
#include "checks/scene_run.h"
#include "checks/transcript.h"
#include "common/limits.h"
#include "golden_checks.h"

namespace a6::grader {

/// The designed inputs asked of the student's code within kMeasureSeconds together, in order;
/// those answered to the end are kept, their label as the exchange's check.
Transcript askDesigned(BudgetedStudent& student, const std::vector<Designed>& designed);

std::vector<SceneRun> runReplays(BudgetedStudent& student,
                                 const std::vector<a6::test::ImagedScene>& scenes);

/// Failed particle checks replayed at most, the step counts sampled of each, its particles at most.
constexpr std::size_t kParticleTrajectories = 2;
constexpr int kTrajectorySamples = 60;
constexpr std::size_t kParticlesPerTrajectory = 200;

/// Up to `kParticleTrajectories` failed task-5 checks (`failed`, in run order), each with its
/// longest run of particles already alive (no emission, the reference forces, at most
/// kParticlesPerTrajectory particles) asked again at kTrajectorySamples step counts up to its own,
/// within kReplaySeconds each. A check whose code fails on them gets none.
std::vector<ParticleTrajectory> runParticleTrajectories(BudgetedStudent& student,
                                                        const Transcript& transcript,
                                                        const std::vector<std::string>& failed);

}  // namespace a6::grader
