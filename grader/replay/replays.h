// The replays stage (see replay_view.h): the student's runs beside the reference's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "checks/scene_run.h"
#include "replay/replay_view.h"

namespace a6::grader {

/// One view per run, in order; `referenceDir` holds <scene>.json (render/replay.h).
std::vector<ReplayView> buildReplays(const std::vector<SceneRun>& runs,
                                     const std::filesystem::path& referenceDir);

/// What the plot's shape means (public for the tests): energies (empty when unknown) over the
/// frames, the error per frame, the frame index where the positions part (-1: never), and the
/// time of each frame.
std::string readPlot(const std::vector<double>& student, const std::vector<double>& reference,
                     const std::vector<double>& error, int parted,
                     const std::vector<double>& times);

}  // namespace a6::grader
