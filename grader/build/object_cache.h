// Objects the grader compiled before, kept by the exact text of their source (a6_grade
// --object-cache; a6_batch keeps one for its whole run). A file graded again (a regrade after a
// rubric change, an untouched starter file, the same file in many submissions) is not compiled
// again: its object and the compiler's messages come from the cache.
//
// Why an entry can be trusted (docs/instructor.md, "The object cache"):
//   - a task file is compiled alone: its compiler sees the kit, its own file and its own object
//     folder, never another task file (grader/build/build.cpp), so the object depends on the
//     file's text and the kit only;
//   - an entry is used only when its stored text and kit fingerprint equal, byte for byte, what
//     would be compiled now (the folder name is a 64-bit hash, a hint only: a collision, made on
//     purpose or not, is a miss);
//   - only the grader writes it, outside every sandbox, after the compile succeeded and the
//     object passed the same checks a fresh one passes; the folder is the grader's alone (mode
//     0700) and hidden from every compiler and probe.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "build/build.h"

namespace a6::grader {

/// What one compile gave: the object (in the cache: copy it before use) and its messages.
struct CachedCompile {
  std::filesystem::path object;
  std::string messages;
};

/// A folder of compiled objects. Default-constructed it is off: it finds and keeps nothing.
class ObjectCache {
 public:
  ObjectCache() = default;
  /// `dir` is created (mode 0700) when missing; `kitFingerprint` as kitFingerprint() gives it.
  ObjectCache(std::filesystem::path dir, std::string kitFingerprint);

  bool on() const { return !dir_.empty(); }
  const std::filesystem::path& dir() const { return dir_; }
  /// Why it is off though a folder was given (it could not be created), or "".
  const std::string& error() const { return error_; }

  /// The entry compiled from exactly `source` as `file` against this kit, if there is one.
  std::optional<CachedCompile> find(const std::string& file, const std::string& source) const;
  /// Keeps a copy of `object` (a regular file) and `messages` for `file` with text `source`.
  /// Returns "" or why it was not kept. Two graders keeping one entry at once: one copy wins.
  std::string keep(const std::string& file, const std::string& source,
                   const std::filesystem::path& object, const std::string& messages) const;

 private:
  std::filesystem::path entryDir(const std::string& file, const std::string& source) const;
  std::string label(const std::string& file) const;

  std::filesystem::path dir_;
  std::string fingerprint_;
  std::string error_;
};

/// What a compile reads besides the student's file, as one string: the compiler (path, size,
/// time), the flags, the staged a6/ headers (their text), the precompiled header and every
/// header under the flags' -isystem folders (Eigen's, Box2D's: size and time). Rebuilding the
/// kit or upgrading those packages changes it; so the cache never hands out an object compiled
/// against other headers.
std::string kitFingerprint(const Kit& kit);

}  // namespace a6::grader
