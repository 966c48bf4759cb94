// Building a submission's probe: each task file compiled on its own, in the sandbox, against the
// framework headers only; a missing or broken file replaced by the starter's prebuilt object;
// then one link against the prebuilt kit.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "common/limits.h"
#include "intake/intake.h"
#include "sandbox/sandbox.h"

namespace a6::grader {

/// What was built once, read from BUILD/grader/kit.json (build.cmake). A compile reads `dir`
/// besides the system headers; the link also reads `probeMain` and `linkInputs`.
struct Kit {
  std::string compiler;                   ///< absolute path of the C++ compiler
  std::vector<std::string> compileFlags;  ///< pinned: -std=c++17 -O2 -ffp-contract=off -I...
  std::vector<std::string> probeMain;     ///< the probe's main object(s), linked first
  std::vector<std::string> modelsMain;    ///< the main asking the grader for reference forces
  std::vector<std::string> linkInputs;    ///< after the task objects: the probe kit, Box2D, ...
  std::filesystem::path starterObjects;   ///< the starter's <task>.o and .syms (its symbols)
  std::filesystem::path knownObjects;     ///< the solution's <task>.cpp and .o, out of the
                                          ///< compiles' view (unlike `dir`); or ""
  std::filesystem::path dir;              ///< the kit folder: staged headers, starter objects
  /// Hidden from the tools but for `dir`, the work folder and the student's files: the
  /// repository and the build tree; a caller may add more (a batch's other submissions).
  std::vector<std::filesystem::path> secrets;
  /// Who compiles and links as root. Not in kit.json: concurrent gradings each need their own,
  /// as a uid's processes share one process limit (a6_grade --sandbox-uid).
  uid_t uid = 65534;
  gid_t gid = 65534;
  std::string error;
  bool ok() const { return error.empty(); }
};
Kit loadKit(const std::filesystem::path& kitJson);

/// BUILD/grader/kit.json of the build tree this grader was built in.
std::filesystem::path defaultKitPath();

/// "" when the tools, as the kit's sandbox user in their sandbox, can read all they need of the
/// kit; else one line naming the folder that shuts the user out and the fix (a grader problem,
/// such as a kit built with umask 077, never the submission's).
std::string kitUnreadableInSandbox(const Kit& kit, const std::filesystem::path& workDir);

struct TaskBuild {
  std::string file;  ///< e.g. "cloth.cpp"
  /// LinkError: it compiled, but the probe linked only with the starter's object in its place.
  enum class Status {
    Compiled,
    Missing,
    CompileError,
    TimedOut,
    LinkError
  } status = Status::Missing;
  std::string messages;          ///< the compiler's (and linker's) output (capped), for the report
  double seconds = 0;            ///< compile time, s
  std::filesystem::path object;  ///< Compiled: the object file (relinkProbe links it again)
  bool known = false;            ///< Compiled: the kit's object of this text (knownObjects)
  bool usesStarter() const { return status != Status::Compiled; }
};

struct Build {
  std::string error;                  ///< the probe could not be linked at all
  std::filesystem::path probe;        ///< workDir/a6_probe, holding no reference model
  std::filesystem::path modelsProbe;  ///< workDir/a6_probe_models: gets the reference forces
  std::vector<TaskBuild> tasks;       ///< in task order
  double seconds = 0;                 ///< compiling and linking, wall clock
  double linkSeconds = 0;             ///< of which linking (all attempts)
  std::vector<std::string> notes;     ///< sandbox protections that could not be applied
  bool ok() const { return error.empty(); }
};

/// `text`, or its first `bytes` bytes and a line saying how many more were cut, then `after`.
inline std::string cap(const std::string& text, std::size_t bytes, const char* after = "\n") {
  if (text.size() <= bytes) return text;
  return text.substr(0, bytes) + "\n[... " + std::to_string(text.size() - bytes) +
         " more bytes cut]" + after;
}

/// Limits for one compile or link (common/limits.h: kCompileSeconds, kCompileMemoryBytes), 64 MiB
/// files, a few processes (the driver runs cc1plus, as, collect2, ld).
Limits defaultCompileLimits();

/// Compiles each file of `intake` (sandboxed, `jobs` at a time, each seeing only the kit, its
/// file and its workDir/obj/<task>/) and links workDir/a6_probe in workDir/link/. An object with
/// code that runs before the probe's seccomp filter (an ifunc resolver, a .preinit_array entry)
/// is replaced by the starter's; a file equal to a known text gets the kit's object; nothing
/// compiled from a submission is kept for another. A compile or link the machine ended is done
/// again once while the budget lasts.
Build buildProbe(const Kit& kit, const Intake& intake, const std::filesystem::path& workDir,
                 const Limits& compileLimits = defaultCompileLimits(), int jobs = 2,
                 double budgetSeconds = kDefaultBuildBudget);

/// Links a probe again in workDir from `compiled`'s objects, with the starter's for the files in
/// `starterFor` and those that did not compile.
Build relinkProbe(const Kit& kit, const Build& compiled, const std::set<std::string>& starterFor,
                  const std::filesystem::path& workDir);

}  // namespace a6::grader
