// What the intake does with each entry, archive or folder alike (for intake.cpp only): the
// checks (screen), and the Collector that keeps the chosen copy of each task file and the notes,
// then writes the copies under their own names.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "intake/intake.h"

namespace a6::grader::entries {

namespace fs = std::filesystem;

// At most this many notes about skipped entries; the rest are counted in one last note.
constexpr std::size_t kMaxEntryNotes = 40;

std::string humanBytes(std::uintmax_t bytes);

// A path as it appears in a note: quoted, control characters escaped, long ones shortened.
std::string shownPath(const std::string& path);

bool isTaskFile(const std::string& name);

// A path inside a submission, split into its components. Both '/' and '\' separate (zips made on
// Windows sometimes use '\'); empty and '.' components are dropped.
struct EntryPath {
  std::vector<std::string> parts;
  bool absolute = false;
  bool parent = false;  // has a '..' component
  std::string name() const { return parts.empty() ? std::string() : parts.back(); }
};

EntryPath splitPath(const std::string& raw);

std::string joinPath(const std::vector<std::string>& parts);

struct Copy {
  std::string path;   // as found, '/'-separated, relative to the submission
  std::size_t depth;  // number of components
  std::string data;   // its bytes (only for the copy currently chosen)
};

bool better(const Copy& a, const Copy& b);

// What an intake collects: the chosen copy of each task file, every copy's path, the notes.
class Collector {
 public:
  explicit Collector(const IntakeLimits& limits) : limits_(limits) {}

  void note(std::string text) { notes_.push_back(std::move(text)); }
  // A note about one skipped entry; counted but not listed past kMaxEntryNotes.
  void entryNote(std::string text) {
    if (entryNotes_++ < kMaxEntryNotes) notes_.push_back(std::move(text));
  }

  // Whether a copy of `name` at `path` could still win, i.e. is worth reading. The same path
  // twice (a tarball appended to with tar -r) is one copy: the later, as extracting would leave.
  bool wanted(const std::string& name, const std::string& path, std::size_t depth) const {
    auto it = chosen_.find(name);
    return it == chosen_.end() || path == it->second.path ||
           better(Copy{path, depth, {}}, it->second);
  }

  // Offers a copy read in full; a refused one is noted.
  void offer(const std::string& name, const std::string& path, std::size_t depth, std::string data);

  // A copy of `name`, usable or not, exists at `path` (for the duplicates note).
  void seen(const std::string& name, const std::string& path) { seen_[name].push_back(path); }

  Intake finish(const fs::path& dest, const std::string& what, bool anyEntries,
                bool sawNestedArchive);

  const IntakeLimits& limits() const { return limits_; }
  bool anyChosen() const { return !chosen_.empty(); }

 private:
  // Readable by all; notes text that is not UTF-8. False (with out.error) when it cannot.
  bool write(const fs::path& target, const Copy& copy, Intake& out);

  // Which copy of `name` was taken and which were not, when there were several.
  void noteDuplicates(const std::string& name, const std::string& taken);

  // The notes about the whole submission: skipped entries not listed, nothing found.
  void closingNotes(const std::string& what, bool anyEntries, bool sawNestedArchive,
                    const Intake& out);

  const IntakeLimits& limits_;
  std::map<std::string, Copy> chosen_;
  std::map<std::string, std::vector<std::string>> seen_;
  std::vector<std::string> notes_;
  std::size_t entryNotes_ = 0;
};

enum class Kind { Regular, Directory, Symlink, Hardlink, Device, Fifo, Socket, Other };

// The checks every entry goes through (a regular file, a safe path, not too deep, named like a
// task file); refusals noted. Returns the task file name to read, or "".
std::string screen(Collector& c, const std::string& raw, const EntryPath& p, Kind kind,
                   const std::string& linkTarget, bool& sawNestedArchive);

std::string tooLarge(const std::string& path, std::uintmax_t size, const IntakeLimits& limits,
                     bool atLeast);

}  // namespace a6::grader::entries
