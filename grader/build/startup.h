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

/// Checks that `build`'s probe starts, relinking it with the starter's objects for the files
/// that keep it from starting. Returns why no probe can serve at all, or "".
std::string ensureProbeStarts(const Kit& kit, Build& build, const std::filesystem::path& work,
                              const std::vector<std::filesystem::path>& secrets);

}  // namespace a6::grader
