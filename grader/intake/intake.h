// Taking a submission in: a folder, a zip or a tarball (libarchive). Only the task files are
// taken, by name, wherever they sit; everything else is ignored. Nothing is ever written outside
// `dest`.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "harness/tasks.h"

namespace a6::grader {

/// The task files, in task order (harness/tasks.h).
using a6::kTaskFiles;

struct Intake {
  std::string error;         ///< non-empty when the submission could not be read at all
  bool graderFault = false;  ///< the error is the grader's (its output folder), not the student's
  std::map<std::string, std::filesystem::path> files;  ///< task file name -> its copy in dest
  std::vector<std::string> notes;  ///< what was skipped or refused, and why (for the report)
  bool ok() const { return error.empty(); }
};

struct IntakeLimits {
  std::size_t maxFileBytes = 1u << 20;    ///< a task file larger than this is refused
  std::size_t maxTotalBytes = 64u << 20;  ///< stop reading an archive after decompressing
                                          ///< this much (zip entries skipped by seeking,
                                          ///< never decompressed, do not count)
  std::size_t maxEntries = 10000;         ///< stop reading after this many entries
  int maxDepth = 32;                      ///< path components; deeper files are skipped
};

/// Copies the task files of `submission` (a folder, a zip or tar archive, plain or compressed,
/// detected by content; or one task file) into `dest` (created, 0755; stale task files removed;
/// files 0644). Nothing is extracted: task files are read into memory, and only the seven known
/// names are ever written.
///
/// A task file is taken by its exact name at any depth; of several copies the shallowest wins
/// (ties: the path that sorts first). Refused with a note, never followed or written: absolute
/// and '..' paths, links, devices, FIFOs, sockets, encrypted entries, task files over
/// maxFileBytes or with NUL bytes (then the next copy is taken). Noted too: nested archives,
/// near-miss names ("Spring.cpp"), text not UTF-8 (taken), limits reached, an empty submission
/// or one without task files.
///
/// `error` is set when the submission cannot be read at all (missing, neither folder nor
/// archive, or damaged before any task file: the task files before the damage are taken, with
/// a note).
Intake takeSubmission(const std::filesystem::path& submission, const std::filesystem::path& dest,
                      const IntakeLimits& limits = {});

/// The bytes of the regular file `path`, read without following a link at its name, at most
/// `cap` + 1 of them; nothing (and `why`) when it cannot be read or is no regular file.
std::optional<std::string> readNoFollow(const std::filesystem::path& path, std::size_t cap,
                                        std::string& why);

}  // namespace a6::grader
