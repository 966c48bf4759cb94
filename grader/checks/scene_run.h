// One imaged scene run again by the student's code at a replay's frames (checks stage), for the
// report's player. Plain data.
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

}  // namespace a6::grader
