// The replays stage (see replay_view.h): the student's runs beside the reference's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "checks/scene_run.h"
#include "checks/transcript.h"
#include "replay/replay_view.h"

namespace a6::grader {

/// One view per run, in order; `referenceDir` holds <scene>.json (render/replay.h).
std::vector<ReplayView> buildReplays(const std::vector<SceneRun>& runs,
                                     const std::filesystem::path& referenceDir);

/// Task 3's failed public checks (in run order), replayed: for the first `kTrajectories` whose
/// simulations the reference can run (mistakes.h: referenceSimulation; none without the library
/// of mistakes), the check's first input where the student's stepper parts from the reference's,
/// both with the reference forces.
std::vector<ReplayView> trajectoryReplays(const Transcript& transcript,
                                          const std::vector<std::string>& failedChecks);

/// Task 5's failed checks' runs of particles (checks/runs.h: runParticleTrajectories),
/// replayed beside the reference's update at the same step counts (mistakes.h:
/// referenceParticleRun; none without the library of mistakes), for those whose runs differ.
std::vector<ReplayView> particleTrajectoryReplays(const std::vector<ParticleTrajectory>& runs);

/// What the plot's shape means (public for the tests): energies (empty when unknown) over the
/// frames, the error per frame, the frame index where the positions part (-1: never), and the
/// time of each frame.
std::string readPlot(const std::vector<double>& student, const std::vector<double>& reference,
                     const std::vector<double>& error, int parted,
                     const std::vector<double>& times);

}  // namespace a6::grader
