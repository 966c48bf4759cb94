// A mistake named for a task: a known one its answers matched (mistakes.h), or what the diagnosis
// measured (measure.h). What the report and results.json say.
#pragma once

#include <string>

namespace a6::grader {

struct NamedMistake {
  std::string id;    ///< the wrong version it was written from: "t1_damping_full_relative_velocity"
  int task = 0;      ///< its task (harness/tasks.h)
  std::string text;  ///< one sentence for the student: what the code does, and the fix
  int evidence = 0;  ///< how many of the public checks' requests it matched where it differs
  /// No part was singled out: `text` says what the diagnosis measured (mistakes/measure.h).
  bool measuredOnly = false;
};

}  // namespace a6::grader
