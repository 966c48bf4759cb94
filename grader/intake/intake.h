// Taking a submission in: a folder, a zip or a tarball (libarchive). Only the task files are
// taken, by name, wherever they sit; everything else is ignored. Nothing is ever written outside
// `dest`.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "harness/task_files.h"

namespace a6::grader {

/// The task files, in task order (harness/task_files.h).
using a6::kTaskFiles;

struct Intake {
  std::string error;  ///< non-empty when the submission could not be read at all
  /// The error is the grader's (its output folder could not be made or written), not the
  /// submission's: the grading failed, nothing is wrong with what the student handed in.
  bool graderFault = false;
  std::map<std::string, std::filesystem::path> files;  ///< task file name -> its copy in dest
  std::vector<std::string> notes;  ///< what was skipped or refused, and why (for the report)
  bool ok() const { return error.empty(); }
};

struct IntakeLimits {
  std::size_t maxFileBytes = 1u << 20;    ///< a task file larger than this is refused
  std::size_t maxTotalBytes = 64u << 20;  ///< stop reading an archive after decompressing
                                          ///< this much (zip entries skipped by seeking and
                                          ///< never decompressed do not count)
  std::size_t maxEntries = 10000;         ///< stop reading after this many entries
  int maxDepth = 32;                      ///< path components; deeper files are skipped
};

/// Copies the seven task files of `submission` (folder, .zip, .tar, .tar.gz, .tgz, .tar.bz2,
/// .tar.xz; detected by content, not name; or one task file on its own) into `dest` (created;
/// stale task files there are removed; files 0644, dest 0755). Nothing is extracted: task
/// files are read into memory, and only the seven known names are ever written, into dest.
///
/// A task file is taken by its exact name at any depth. When a name occurs more than once, the
/// shallowest copy wins (ties: the path that sorts first) and the others are noted. Refused,
/// with a note, and never followed or written: absolute paths and paths with '..', symbolic
/// and hard links, devices, FIFOs and sockets, encrypted entries, task files over
/// maxFileBytes or containing NUL bytes (a refused copy does not count: the next one is
/// taken). Noted too: nested archives (not opened), near-miss names ("Spring.cpp"), task files
/// that are not valid UTF-8 (taken), the limits when reached, an empty submission, and a
/// submission without any task file.
///
/// `error` is set when the submission cannot be read at all: it does not exist, is not a
/// folder or an archive, or is damaged before any task file could be read (a damaged archive
/// with task files before the damage gives those files and a note).
Intake takeSubmission(const std::filesystem::path& submission, const std::filesystem::path& dest,
                      const IntakeLimits& limits = {});

}  // namespace a6::grader
