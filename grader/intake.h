// Taking a submission in: a folder, a zip or a tarball (libarchive). Only the six task files are
// taken, by name, wherever they sit; everything else is ignored. Nothing is ever written outside
// `dest`.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace a6::grader {

/// The six task files, in task order.
inline const std::vector<std::string> kTaskFiles = {"spring.cpp", "forces.cpp",
                                                    "time_stepping.cpp", "cloth.cpp",
                                                    "particle_system.cpp", "joints.cpp"};

struct Intake {
  std::string error;  ///< non-empty when the submission could not be read at all
  std::map<std::string, std::filesystem::path> files;  ///< task file name -> its copy in dest
  std::vector<std::string> notes;  ///< what was skipped or refused, and why (for the report)
  bool ok() const { return error.empty(); }
};

struct IntakeLimits {
  std::size_t maxFileBytes = 1u << 20;       ///< a task file larger than this is refused
  std::size_t maxTotalBytes = 64u << 20;     ///< stop reading an archive after this much
  std::size_t maxEntries = 10000;
  int maxDepth = 32;                         ///< path components
};

/// Copies the six task files of `submission` (folder, .zip, .tar, .tar.gz, .tgz; detected by
/// content, not name) into `dest` (created). When a name occurs more than once, the shallowest
/// wins and the others are noted. Symlinks, devices, absolute or `..` paths are never followed.
Intake takeSubmission(const std::filesystem::path& submission, const std::filesystem::path& dest,
                      const IntakeLimits& limits = {});

}  // namespace a6::grader
