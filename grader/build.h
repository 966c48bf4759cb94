// Building a submission's probe: each task file compiled on its own, in the sandbox, against the
// framework headers only; a missing or broken file replaced by the starter's prebuilt object;
// then one link against the prebuilt kit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "intake.h"
#include "sandbox.h"

namespace a6::grader {

/// What was built once, read from BUILD/grader/kit.json (written by CMake).
struct Kit {
  std::string compiler;                    ///< absolute path of the C++ compiler
  std::vector<std::string> compileFlags;   ///< pinned: -std=c++17 -O2 -ffp-contract=off -I...
  std::vector<std::string> linkInputs;     ///< probe main object, probe kit library, -lbox2d, ...
  std::filesystem::path starterObjects;    ///< folder with <task>.o of the starter
  std::string error;
  bool ok() const { return error.empty(); }
};
Kit loadKit(const std::filesystem::path& kitJson);

struct TaskBuild {
  std::string file;  ///< e.g. "cloth.cpp"
  enum class Status { Compiled, Missing, CompileError, TimedOut } status = Status::Missing;
  std::string messages;  ///< the compiler's output (capped), for the report
  bool usesStarter() const { return status != Status::Compiled; }
};

struct Build {
  std::string error;                  ///< the probe could not be linked at all
  std::filesystem::path probe;        ///< the linked probe executable
  std::vector<TaskBuild> tasks;       ///< in task order
  double seconds = 0;
  bool ok() const { return error.empty(); }
};

/// Compiles each file of `intake` in `workDir` (sandboxed, the grader's secrets hidden) and links
/// the probe.
Build buildProbe(const Kit& kit, const Intake& intake, const std::filesystem::path& workDir,
                 const Limits& compileLimits = {});

}  // namespace a6::grader
