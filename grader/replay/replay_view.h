// The replays stage: the student's runs of the imaged scenes (checks/runs.h) beside the
// reference runs (tests/golden/replays/, packed from the solution by a6_render_solution
// --replays), measured for the report: the energy over time, the position error, the frame
// where the two part, and one sentence on what the plot's shape means.
//
// Takes the runs and the folder of the reference replays (replay/replays.h: buildReplays);
// gives one ReplayView per scene, plain data the report draws. Nothing here is scored.
#pragma once

#include <string>
#include <vector>

namespace a6::grader {

struct ReplayView {
  std::string scene;  ///< the scene, or for a trajectory the check it comes from
  int task = 0;
  bool trajectory = false;         ///< a failed check's own simulation, not an imaged scene
  std::string student, reference;  ///< the packed runs (render/replay.h), JSON, for the player
  std::vector<int> frames;
  std::vector<double> times;                           ///< s, per frame
  std::vector<double> studentEnergy, referenceEnergy;  ///< kinetic + potential, J (empty:
                                                       ///< unknown, Box2D's bodies)
  std::vector<double> error;  ///< m, per frame; NaN where the student's run is not finite
  std::string errorMeasure;   ///< what `error` measures, for the plot's legend
  double threshold = 0;       ///< m: an error beyond it is "parted"
  int parted = -1;            ///< the first frame index whose error passes the threshold
  std::string reading;        ///< one sentence: what the plot's shape means
  std::string missing;        ///< why there is no replay ("" when there is one)
  std::string divergence;     ///< a failed check's first divergence (checks/divergence.h), or ""
};

}  // namespace a6::grader
