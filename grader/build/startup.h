// The end of the build stage: a probe that starts. Code that runs before main (static
// initializers) can keep the whole probe from serving: an exit(), an abort(), a crash or an
// endless loop there would fail every check of every task. So the probe must first start up; if
// it does not, each compiled file is tried alone among the starter's objects, and the files whose
// probe does not start are replaced by the starter's: they cost their own task, as a file that
// does not compile does.
//
// Takes the kit, the build (its probe and each task's object) and what the probe must not see;
// gives the build with the culprits replaced, and why no probe can serve at all, or "".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "build/build.h"

namespace a6::grader {

/// How long a probe may take to reach main and answer a request that runs no student code, s.
constexpr double kStartupSeconds = 5;

/// Whether `probe` reaches main and serves: "" when it answers, twice, a request that runs no
/// student code (a scene request with an invalid frame, refused before any scene is made);
/// otherwise why not (it crashed, exited or hung before main: a static initializer, typically).
std::string startupFailure(const std::filesystem::path& probe, const std::filesystem::path& runDir,
                           const std::vector<std::filesystem::path>& secrets, uid_t uid, gid_t gid);

/// Checks that `build`'s probe starts, replacing the files that keep it from starting by the
/// starter's (`build` is then the relinked build). Returns why no probe can serve at all (every
/// check then fails at once with that reason), or "".
std::string ensureProbeStarts(const Kit& kit, Build& build, const std::filesystem::path& work,
                              const std::vector<std::filesystem::path>& secrets);

}  // namespace a6::grader
