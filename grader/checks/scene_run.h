// The student's code's runs for the report's player (checks stage): an imaged scene run again
// at a replay's frames, and a failed particle check's run again at many step counts. Plain data.
#pragma once

#include <string>
#include <vector>

#include "harness/student_code.h"

namespace a6::grader {

struct SceneRun {
  std::string scene;
  int task = 0;  ///< the task its images are filed under
  std::vector<int> frames;
  harness::SceneResult result;  ///< result.snapshots[k] after frames[k]; or the failure
};

/// One run of particles of a failed task-5 check asked again of the student's code, stopped
/// after each of `steps` steps (each a request of its own from the same start), for a replay of
/// its trajectory. Plain data.
struct ParticleTrajectory {
  std::string check;  ///< "Task5Particles.FallsUnderGravity"
  harness::ParticleRunRequest request;
  std::vector<int> steps;                      ///< ascending
  std::vector<harness::ParticlesResult> runs;  ///< runs[k] after steps[k]; all ran
};

}  // namespace a6::grader
