// Objects the grader compiled before, kept by the exact text of their source (a6_grade
// --object-cache; a6_batch keeps one for its whole run). A file graded again (a regrade after a
// rubric change, an untouched starter file, the same file in many submissions) is not compiled
// again: its object and the compiler's messages come from the cache.
//
// Why an entry can be trusted (docs/instructor.md, "The object cache"):
//   - a task file is compiled alone: its compiler sees the kit, its own file and its own object
//     folder, never another task file (grader/build/build.cpp), and __FILE__ names the file
//     alone, so the object depends on the file's text, the kit and the machine's compiler and
//     headers, which the fingerprint covers, and on nothing else unless the file asks for the
//     moment or place of its compile (__TIME__, __has_include of a covered file): then a reused
//     object holds what its first compile saw, which affects that file's own grading only;
//   - an entry is used only when its stored fingerprint and text equal, byte for byte, what
//     would be compiled now, and its object the size and hash it was kept with (the folder name
//     is a 64-bit hash, a hint only: a collision, made on purpose or not, is a miss);
//   - only the grader writes it, outside every sandbox, after the compile succeeded with every
//     protection on and the object passed the checks a fresh one passes; the folder is the
//     grader's alone (mode 0700) and hidden from every compiler and probe.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "build/build.h"

namespace a6::grader {

/// What one compile gave: the object's bytes and the compiler's messages.
struct CachedCompile {
  std::string object;
  std::string messages;
};

/// A folder of compiled objects. Default-constructed it is off: it finds and keeps nothing.
class ObjectCache {
 public:
  /// Objects larger than this are not kept (a compile may write 64 MiB).
  static constexpr std::size_t kMaxObjectBytes = std::size_t{4} << 20;

  ObjectCache() = default;
  /// `dir` is created (mode 0700) when missing; `fingerprint` as kitFingerprint() gives it.
  ObjectCache(std::filesystem::path dir, std::string fingerprint);

  bool on() const { return !dir_.empty(); }
  const std::filesystem::path& dir() const { return dir_; }
  /// Why it is off though a folder was given, or "".
  const std::string& error() const { return error_; }

  /// The whole, intact entry compiled from exactly `source` as `file`, if there is one.
  std::optional<CachedCompile> find(const std::string& file, const std::string& source) const;
  /// Keeps `object` (a regular file's bytes, not over kMaxObjectBytes) and `messages` for `file`
  /// with text `source`, in place of a broken entry or another text's. Returns "" or why not.
  std::string keep(const std::string& file, const std::string& source,
                   const std::filesystem::path& object, const std::string& messages) const;

 private:
  std::filesystem::path entryDir(const std::string& file, const std::string& source) const;
  std::string label(const std::string& file) const;
  void removeLeftovers() const;
  std::filesystem::path moveAside(const std::filesystem::path& entry) const;

  std::filesystem::path dir_;
  std::string fingerprint_;
  std::string error_;
};

/// What decides a compile's output besides the student's file, as one string: this grader's
/// program (size, time: its sandbox and messages), the compiler and assembler, the flags and the
/// kit's secrets, the staged a6/ headers (their text), the precompiled header, and every folder
/// under /usr/include, the compiler's own folders and the flags' -isystem folders (their times:
/// a package upgrade renames files into them). A header edited in place is not seen: empty the
/// cache after that.
std::string kitFingerprint(const Kit& kit);

/// The bytes of a regular file, read without following a link, or nothing.
std::optional<std::string> readRegularFile(const std::filesystem::path& file);

}  // namespace a6::grader
