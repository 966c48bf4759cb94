// Building a submission's probe: each task file compiled on its own, in the sandbox, against the
// framework headers only; a missing or broken file replaced by the starter's prebuilt object;
// then one link against the prebuilt kit.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "grading/budgets.h"
#include "intake/intake.h"
#include "sandbox/sandbox.h"

namespace a6::grader {

/// What was built once, read from BUILD/grader/kit.json (written by CMake,
/// grader/build/build.cmake). What a compile reads besides the system headers sits in
/// `dir`; the link also reads `probeMain` and `linkInputs`.
struct Kit {
  std::string compiler;                   ///< absolute path of the C++ compiler
  std::vector<std::string> compileFlags;  ///< pinned: -std=c++17 -O2 -ffp-contract=off -I...
  std::vector<std::string> probeMain;     ///< the probe's main object(s), linked first
  std::vector<std::string> modelsMain;    ///< the same main, asking the grader for the
                                          ///< reference forces: the second probe's
                                          ///< (Build::modelsProbe)
  std::vector<std::string> linkInputs;    ///< after the seven task objects: the probe kit
                                          ///< library, Box2D, libseccomp
  std::filesystem::path starterObjects;   ///< folder with <task>.o (and <task>.syms: its
                                          ///< defined symbols, demangled) of the starter
  std::filesystem::path knownObjects;     ///< folder with <task>.cpp and <task>.o: texts the
                                          ///< grader's own build compiled (the solution's),
                                          ///< used for a file equal to one byte for byte; ""
                                          ///< for none. Outside `dir`: hidden from every tool
  std::filesystem::path dir;              ///< the kit folder: staged headers, starter objects
  /// Hidden from the compiler and the linker, except `dir`, the work folder and the student's
  /// files: the repository (solution, hidden tests, goldens) and the build tree. A caller may
  /// add more (a batch's other submissions) before buildProbe.
  std::vector<std::filesystem::path> secrets;
  /// Who compiles and links when the grader is root (SandboxSpec::uid, gid). Not in kit.json:
  /// a caller that grades several submissions at once gives each its own uid, since processes
  /// of one uid share their process limit (a6_grade --sandbox-uid).
  uid_t uid = 65534;
  gid_t gid = 65534;
  std::string error;
  bool ok() const { return error.empty(); }
};
Kit loadKit(const std::filesystem::path& kitJson);

/// BUILD/grader/kit.json of the build tree this grader was built in.
std::filesystem::path defaultKitPath();

/// "" when the compiler and the linker, run as the kit's sandbox user in their sandbox, can read
/// everything they need of the kit (its folder, the probe's main and link inputs); otherwise one
/// line naming the folder that shuts the user out, the user, and the fix. A grader problem, never
/// the submission's: a kit built with umask 077, say.
std::string kitUnreadableInSandbox(const Kit& kit, const std::filesystem::path& workDir);

struct TaskBuild {
  std::string file;  ///< e.g. "cloth.cpp"
  /// LinkError: it compiled, but the probe linked only with the starter's object in its place
  /// (it defines main() or a symbol of the framework, or lacks a function the framework calls).
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
  bool known = false;            ///< Compiled: the kit's prebuilt object of this very text
                                 ///< (Kit::knownObjects), not compiled here
  bool usesStarter() const { return status != Status::Compiled; }
};

struct Build {
  std::string error;                  ///< the probe could not be linked at all
  std::filesystem::path probe;        ///< the linked probe executable (workDir/a6_probe): it
                                      ///< serves every request and holds no reference model
  std::filesystem::path modelsProbe;  ///< the same objects with a main that asks the grader
                                      ///< for the reference forces (workDir/a6_probe_models),
                                      ///< for the requests that use them
  std::vector<TaskBuild> tasks;       ///< in task order
  double seconds = 0;                 ///< compiling and linking, wall clock
  double linkSeconds = 0;             ///< of which linking (all attempts)
  std::vector<std::string> notes;     ///< sandbox protections that could not be applied (for
                                      ///< the TA: e.g. not root, so nothing could be hidden)
  bool ok() const { return error.empty(); }
};

/// Limits for one compile or link: 60 s wall and CPU, 512 MiB address space, 64 MiB files,
/// a few processes (the driver runs cc1plus, as, collect2, ld).
Limits defaultCompileLimits();

/// Compiles each file of `intake` in `workDir` (sandboxed, the grader's secrets hidden, only
/// /dev/null, /dev/zero and /dev/urandom among the devices; `jobs` files at a time) and links
/// the probe, workDir/a6_probe. workDir is created; objects go to workDir/obj/<task>/, the link
/// happens in workDir/link/. Each compile sees the kit, its own file and its own object folder
/// only. An object holding code that runs before the probe's seccomp filter (an ifunc resolver,
/// a .preinit_array entry) is replaced by the starter's. A file equal byte for byte to one of
/// the kit's known texts gets the kit's object (TaskBuild::known); nothing compiled from a
/// submission is kept for another. A compile or link that the machine ended (killed by SIGKILL,
/// its time limit, no process to start) is done again once while the budget lasts.
Build buildProbe(const Kit& kit, const Intake& intake, const std::filesystem::path& workDir,
                 const Limits& compileLimits = defaultCompileLimits(), int jobs = 2,
                 double budgetSeconds = kDefaultBuildBudget);

/// Links a probe again, in workDir, from the objects `compiled` holds, with the starter's object
/// for the files in `starterFor` (and for every file that did not compile): no compiling.
Build relinkProbe(const Kit& kit, const Build& compiled, const std::set<std::string>& starterFor,
                  const std::filesystem::path& workDir);

}  // namespace a6::grader
