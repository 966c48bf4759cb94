#include "build/startup.h"

#include <map>
#include <set>
#include <sstream>

#include "common/limits.h"
#include "probe/probe_client.h"

namespace fs = std::filesystem;

namespace a6::grader {
namespace {

const char* const kBeforeMain =
    "Code that runs before main, such as the initializer of a global or static variable, must "
    "not exit, abort, crash or loop.";

// "" when `probe` answers, twice, a request that runs no student code (an invalid frame,
// refused before any scene is made); otherwise why not (it crashed, exited or hung).
std::string startupFailure(const fs::path& probe, const fs::path& runDir,
                           const std::vector<fs::path>& secrets, uid_t uid, gid_t gid) {
  ProbeClient client(probe, runDir, Limits{});
  const SandboxView view = probeView(secrets);
  client.setHidden(view.hide, view.reveal);
  client.setUser(uid, gid);
  client.setRequestTimeout(kStartupSeconds);
  client.setMaxStarts(1);
  harness::SceneRequest ping;
  ping.frames = {-1};
  for (int k = 0; k < 2; ++k) {
    const harness::SceneResult r = client.ask(ping);
    if (r.fault == harness::Fault::Refused) continue;  // main runs, and refused the frame
    if (r.fault == harness::Fault::TimedOut) {
      std::ostringstream out;
      out << "it did not reach main within " << kStartupSeconds << " s (is there an endless "
          << "loop in code that runs before main, such as a static initializer?)";
      return out.str();
    }
    return r.error.empty() ? "it answered a request it must refuse" : r.error;
  }
  return "";
}

// The compiled files whose probe, alone among the starter's objects, does not start, with why.
std::map<std::string, std::string> culpritsOf(const Kit& kit, const Build& build,
                                              const fs::path& work,
                                              const std::vector<fs::path>& secrets) {
  std::set<std::string> compiled;
  for (const TaskBuild& task : build.tasks) {
    if (task.status == TaskBuild::Status::Compiled) compiled.insert(task.file);
  }
  std::map<std::string, std::string> culprits;
  for (const std::string& file : compiled) {
    std::set<std::string> others = compiled;
    others.erase(file);
    const fs::path dir = work / "startup" / fs::path(file).stem();
    const Build solo = relinkProbe(kit, build, others, dir / "build");
    if (!solo.ok()) continue;
    const std::string why = startupFailure(solo.probe, dir / "run", secrets, kit.uid, kit.gid);
    if (!why.empty()) culprits[file] = why;
  }
  return culprits;
}

// `build` relinked with the starter's objects for the culprits (link errors, with the reason);
// false when the relink failed (`build` is then unchanged).
bool replaceCulprits(const Kit& kit, Build& build,
                     const std::map<std::string, std::string>& culprits, const fs::path& work) {
  std::set<std::string> starterFor;
  for (const auto& [file, why] : culprits) starterFor.insert(file);
  Build rebuilt = relinkProbe(kit, build, starterFor, work / "build-without-startup-failures");
  if (!rebuilt.ok()) return false;
  for (std::size_t i = 0; i < rebuilt.tasks.size() && i < build.tasks.size(); ++i) {
    TaskBuild& task = rebuilt.tasks[i];
    const auto culprit = culprits.find(task.file);
    if (culprit == culprits.end()) continue;
    task = build.tasks[i];
    task.status = TaskBuild::Status::LinkError;
    task.messages += task.file +
                     " compiled, but the program built with it did not start: " + culprit->second +
                     "\n" + kBeforeMain + " Task " + std::to_string(i + 1) +
                     " is graded with the starter's stub.\n";
  }
  rebuilt.seconds += build.seconds;
  build = rebuilt;
  return true;
}

}  // namespace

std::string ensureProbeStarts(const Kit& kit, Build& build, const fs::path& work,
                              const std::vector<fs::path>& secrets) {
  const std::string failure =
      startupFailure(build.probe, work / "startup", secrets, kit.uid, kit.gid);
  if (failure.empty()) return "";
  const std::string whole =
      "the program built from your files did not start: " + failure + "\n(" + kBeforeMain + ")";
  const std::map<std::string, std::string> culprits = culpritsOf(kit, build, work, secrets);
  // Only the files together fail, or the relink failed: nothing to single out.
  if (culprits.empty() || !replaceCulprits(kit, build, culprits, work)) return whole;
  if (const std::string still =
          startupFailure(build.probe, work / "startup", secrets, kit.uid, kit.gid);
      !still.empty()) {
    return "the program built from your files did not start, even with the starter's code in "
           "place of the files that kept it from starting: " +
           still;
  }
  return "";
}

}  // namespace a6::grader
