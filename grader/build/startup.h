// The end of the build stage: a probe that starts. Code that runs before main (a static
// initializer that exits, aborts, crashes or loops) would fail every check of every task, so a
// probe that does not start has each compiled file tried alone among the starter's objects, and
// the culprits replaced by the starter's: they cost their own task only.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "build/build.h"

namespace a6::grader {

/// How long a probe may take to reach main and answer a request that runs no student code, s.
constexpr double kStartupSeconds = 5;

/// "" when `probe` answers, twice, a request that runs no student code (an invalid frame,
/// refused before any scene is made); otherwise why not (it crashed, exited or hung).
std::string startupFailure(const std::filesystem::path& probe, const std::filesystem::path& runDir,
                           const std::vector<std::filesystem::path>& secrets, uid_t uid, gid_t gid);

/// Checks that `build`'s probe starts, relinking it with the starter's objects for the files
/// that keep it from starting. Returns why no probe can serve at all, or "".
std::string ensureProbeStarts(const Kit& kit, Build& build, const std::filesystem::path& work,
                              const std::vector<std::filesystem::path>& secrets);

}  // namespace a6::grader
