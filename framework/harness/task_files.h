// The student's task files, in task order: task t is kTaskFiles[t - 1]. The one list the suite,
// the golden images, the grader (intake, build, report, batch) and their tests read.
#pragma once

#include <string>
#include <vector>

namespace a6 {

/// Tasks 1 to 6, then task 7 (extra credit).
inline const std::vector<std::string> kTaskFiles = {
    "spring.cpp",          "forces.cpp", "time_stepping.cpp", "cloth.cpp",
    "particle_system.cpp", "joints.cpp", "implicit.cpp"};
inline constexpr int kTaskCount = 7;

/// The file of task `task` (1-based); "" for a number that is no task.
inline std::string taskFile(int task) {
  return task >= 1 && task <= kTaskCount ? kTaskFiles[static_cast<std::size_t>(task - 1)] : "";
}

}  // namespace a6
