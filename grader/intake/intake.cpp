// Taking a submission in. See intake.h for the contract.
//
// Intake notes
// ------------
// A submission is untrusted data. We never extract anything: the archive (or the folder) is
// read entry by entry, only entries whose file name is one of the seven task files are read, into
// memory, with a size cap, and at the end the chosen copies are written under `dest` with names
// we choose (the seven known names). Nothing a submission names can make us write elsewhere, so
// '..', absolute paths, links and devices are only reported, never acted on.
//
// Several copies of a task file: the shallowest wins (Gradescope puts the files at the root of
// the submission, students often zip the folder that holds them); ties go to the path that
// sorts first, so the result never depends on archive or directory order. A copy that is
// refused (too large, binary) does not count: the next one is taken, with a note.
//
// Zip bombs: an entry's data is read only for task files (at most maxFileBytes each) and an
// archive stops being read after maxEntries entries or maxTotalBytes of decompressed data.
#include "intake/intake.h"

#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <system_error>

namespace a6::grader {
namespace {

namespace fs = std::filesystem;

// At most this many notes about skipped entries; the rest are counted in one last note.
constexpr std::size_t kMaxEntryNotes = 40;

std::string humanBytes(std::uintmax_t bytes) {
  char buf[64];
  if (bytes >= (1u << 20)) {
    std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1u << 20));
  } else if (bytes >= (1u << 10)) {
    std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(bytes) / (1u << 10));
  } else {
    std::snprintf(buf, sizeof buf, "%ju bytes", bytes);
  }
  return buf;
}

// A path as it appears in a note: quoted, control characters escaped, long ones shortened.
std::string shownPath(const std::string& path) {
  std::string out = "'";
  for (unsigned char c : path) {
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (out.size() > 200) out = out.substr(0, 100) + "..." + out.substr(out.size() - 90);
  return out + "'";
}

bool isTaskFile(const std::string& name) {
  return std::find(kTaskFiles.begin(), kTaskFiles.end(), name) != kTaskFiles.end();
}

// The task file `name` matches when case is ignored (a near miss worth a note), or "".
std::string nearMissOf(const std::string& name) {
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string l = lower(name);
  for (const std::string& task : kTaskFiles) {
    if (l == task || l == task + ".txt") return task;
  }
  return "";
}

bool isNestedArchive(const std::string& name) {
  static const char* const kExtensions[] = {".zip",    ".tar", ".tgz", ".tar.gz", ".tar.bz2",
                                            ".tar.xz", ".gz",  ".7z",  ".rar"};
  std::string l = name;
  for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* ext : kExtensions) {
    const std::size_t n = std::strlen(ext);
    if (l.size() > n && l.compare(l.size() - n, n, ext) == 0) return true;
  }
  return false;
}

bool validUtf8(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    int extra = 0;
    if (c < 0x80) {
      ++i;
      continue;
    } else if ((c & 0xE0) == 0xC0 && c >= 0xC2) {
      extra = 1;
    } else if ((c & 0xF0) == 0xE0) {
      extra = 2;
    } else if ((c & 0xF8) == 0xF0 && c <= 0xF4) {
      extra = 3;
    } else {
      return false;
    }
    if (i + extra >= s.size()) return false;
    for (int k = 1; k <= extra; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    }
    i += extra + 1;
  }
  return true;
}

// A path inside a submission, split into its components. Both '/' and '\' separate (zips made on
// Windows sometimes use '\'); empty and '.' components are dropped.
struct EntryPath {
  std::vector<std::string> parts;
  bool absolute = false;
  bool parent = false;  // has a '..' component
  std::string name() const { return parts.empty() ? std::string() : parts.back(); }
};

EntryPath splitPath(const std::string& raw) {
  EntryPath p;
  if (!raw.empty() && (raw[0] == '/' || raw[0] == '\\')) p.absolute = true;
  // "C:..." (a Windows drive) counts as absolute too.
  if (raw.size() >= 2 && raw[1] == ':' && std::isalpha(static_cast<unsigned char>(raw[0]))) {
    p.absolute = true;
  }
  std::string part;
  auto flush = [&] {
    if (part == "..") p.parent = true;
    if (!part.empty() && part != ".") p.parts.push_back(part);
    part.clear();
  };
  for (char c : raw) {
    if (c == '/' || c == '\\') {
      flush();
    } else {
      part += c;
    }
  }
  flush();
  return p;
}

std::string joinPath(const std::vector<std::string>& parts) {
  std::string s;
  for (const std::string& part : parts) s += (s.empty() ? "" : "/") + part;
  return s;
}

// One copy of a task file found in the submission.
struct Copy {
  std::string path;   // as found, '/'-separated, relative to the submission
  std::size_t depth;  // number of components
  std::string data;   // its bytes (only for the copy currently chosen)
};

bool better(const Copy& a, const Copy& b) {
  return a.depth != b.depth ? a.depth < b.depth : a.path < b.path;
}

// What an intake collects while it reads: the chosen copy of each task file, every copy's path
// (for the duplicate note) and the notes.
class Collector {
 public:
  explicit Collector(const IntakeLimits& limits) : limits_(limits) {}

  void note(std::string text) { notes_.push_back(std::move(text)); }
  // A note about one skipped entry; counted but not listed past kMaxEntryNotes.
  void entryNote(std::string text) {
    if (entryNotes_++ < kMaxEntryNotes) notes_.push_back(std::move(text));
  }

  // Whether a copy of `name` at `path` (depth `depth`) could still win, i.e. is worth reading.
  // The same path twice (a tarball appended to with tar -r) counts as one copy: the later one,
  // as extracting it would leave.
  bool wanted(const std::string& name, const std::string& path, std::size_t depth) const {
    auto it = chosen_.find(name);
    return it == chosen_.end() || path == it->second.path ||
           better(Copy{path, depth, {}}, it->second);
  }

  // Offers a copy that was read in full; checks its content (a refused copy is noted).
  void offer(const std::string& name, const std::string& path, std::size_t depth,
             std::string data) {
    if (data.find('\0') != std::string::npos) {
      entryNote(shownPath(path) +
                ": refused: it contains NUL bytes, so it is binary, not C++ "
                "source; submit the .cpp text file");
      return;
    }
    if (wanted(name, path, depth)) chosen_[name] = Copy{path, depth, std::move(data)};
  }

  // Records that a (usable or not) copy of `name` exists at `path`, for the duplicates note.
  void seen(const std::string& name, const std::string& path) { seen_[name].push_back(path); }

  // Writes the chosen copies into dest and returns the result.
  Intake finish(const fs::path& dest, const std::string& what, bool anyEntries,
                bool sawNestedArchive) {
    Intake out;
    if (!makeDest(dest, out)) return out;
    for (const std::string& name : kTaskFiles) {
      // A stale copy from an earlier run must never be mistaken for this submission's file.
      std::error_code ec;
      fs::remove(dest / name, ec);
      auto it = chosen_.find(name);
      if (it == chosen_.end()) continue;
      if (!write(dest / name, it->second, out)) return out;
      out.files[name] = dest / name;
      noteDuplicates(name, it->second.path);
    }
    closingNotes(what, anyEntries, sawNestedArchive, out);
    out.notes = std::move(notes_);
    return out;
  }

  const IntakeLimits& limits() const { return limits_; }
  bool anyChosen() const { return !chosen_.empty(); }

 private:
  // Creates dest, readable by the sandbox's user. False (with out.error) when it cannot.
  static bool makeDest(const fs::path& dest, Intake& out) {
    std::error_code ec;
    fs::create_directories(dest, ec);
    if (ec) {
      out.error = "cannot create the folder " + dest.string() +
                  " for the submission's files: " + ec.message() +
                  " (check that the output folder is writable)";
      out.graderFault = true;
      return false;
    }
    fs::permissions(dest,
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                        fs::perms::others_read | fs::perms::others_exec,
                    ec);
    return true;
  }

  // Writes one chosen copy to `target`, readable by all; notes text that is not UTF-8.
  // False (with out.error) when it cannot be written.
  bool write(const fs::path& target, const Copy& copy, Intake& out) {
    {
      std::ofstream file(target, std::ios::binary | std::ios::trunc);
      file.write(copy.data.data(), static_cast<std::streamsize>(copy.data.size()));
      if (!file) {
        out.error = "cannot write " + target.string() + ": " + std::strerror(errno) +
                    " (check the output folder: disk full or not writable?)";
        out.graderFault = true;
        return false;
      }
    }
    std::error_code ec;
    fs::permissions(target,
                    fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                        fs::perms::others_read,
                    ec);
    if (!validUtf8(copy.data)) {
      note(shownPath(copy.path) +
           ": not valid UTF-8 text (taken anyway; if the compiler "
           "rejects a character, save the file as UTF-8)");
    }
    return true;
  }

  // When `name` was found more than once: which copy was taken and which were not.
  void noteDuplicates(const std::string& name, const std::string& taken) {
    auto& paths = seen_[name];
    std::sort(paths.begin(), paths.end());
    paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
    if (paths.size() <= 1) return;
    std::string others;
    for (const std::string& p : paths) {
      if (p != taken) others += (others.empty() ? "" : ", ") + shownPath(p);
    }
    note(name + ": " + std::to_string(paths.size()) + " copies found; took " + shownPath(taken) +
         " (the shallowest copy wins), ignored " + others);
  }

  // The notes about the whole submission: skipped entries not listed, nothing found.
  void closingNotes(const std::string& what, bool anyEntries, bool sawNestedArchive,
                    const Intake& out) {
    if (entryNotes_ > kMaxEntryNotes) {
      note(std::to_string(entryNotes_ - kMaxEntryNotes) + " more skipped entries are not listed");
    }
    if (!anyEntries) {
      note("the " + what + " is empty");
    } else if (out.files.empty()) {
      std::string names;
      for (const std::string& n : kTaskFiles) names += (names.empty() ? "" : ", ") + n;
      note("no task file was found in the " + what + " (looked for " + names + " at any depth)" +
           (sawNestedArchive ? ". Archives inside the submission are not opened: submit the "
                               ".cpp files themselves"
                             : ""));
    }
  }

  const IntakeLimits& limits_;
  std::map<std::string, Copy> chosen_;
  std::map<std::string, std::vector<std::string>> seen_;
  std::vector<std::string> notes_;
  std::size_t entryNotes_ = 0;
};

// The checks every entry goes through, archive or folder. Returns true when the entry is a task
// file worth reading (a regular file, safe path, not too deep, named like a task file).
enum class Kind { Regular, Directory, Symlink, Hardlink, Device, Fifo, Socket, Other };

const char* describe(Kind kind) {
  switch (kind) {
    case Kind::Symlink:
      return "a symbolic link";
    case Kind::Hardlink:
      return "a hard link";
    case Kind::Device:
      return "a device file";
    case Kind::Fifo:
      return "a named pipe (FIFO)";
    case Kind::Socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

// Decides what to do with one entry; notes refusals. Returns the task file name to read, or "".
std::string screen(Collector& c, const std::string& raw, const EntryPath& p, Kind kind,
                   const std::string& linkTarget, bool& sawNestedArchive) {
  const std::string& shown = raw;
  if (p.absolute) {
    c.entryNote(shownPath(shown) +
                ": refused: an absolute path (nothing is ever written "
                "outside the grader's folder)");
    return "";
  }
  if (p.parent) {
    c.entryNote(shownPath(shown) +
                ": refused: the path contains '..' (nothing is ever written "
                "outside the grader's folder)");
    return "";
  }
  if (p.parts.empty()) return "";
  if (p.parts.front() == "__MACOSX") return "";  // macOS resource forks ("._spring.cpp")
  const std::string name = p.name();
  if (kind == Kind::Directory) return "";
  if (static_cast<int>(p.parts.size()) > c.limits().maxDepth) {
    c.entryNote(shownPath(shown) + ": skipped: " + std::to_string(p.parts.size()) +
                " levels deep, over the limit of " + std::to_string(c.limits().maxDepth));
    return "";
  }
  if (kind != Kind::Regular) {
    std::string why = std::string(describe(kind));
    if (!linkTarget.empty()) why += " to " + shownPath(linkTarget);
    c.entryNote(shownPath(shown) + ": refused: " + why +
                "; links and special files are never followed" +
                (isTaskFile(name) ? ": submit the file itself" : ""));
    if (isTaskFile(name)) c.seen(name, joinPath(p.parts));
    return "";
  }
  if (isTaskFile(name)) return name;
  if (isNestedArchive(name)) {
    sawNestedArchive = true;
    c.entryNote(shownPath(shown) +
                ": a nested archive, not opened (submit the .cpp files "
                "themselves, not an archive inside the archive)");
    return "";
  }
  const std::string near = nearMissOf(name);
  if (!near.empty()) {
    c.entryNote(shownPath(shown) + ": ignored: the name must be exactly '" + near +
                "' (names are case-sensitive)");
  }
  return "";
}

std::string tooLarge(const std::string& path, std::uintmax_t size, const IntakeLimits& limits,
                     bool atLeast) {
  return shownPath(path) + ": refused: " + (atLeast ? "more than " : "") + humanBytes(size) +
         ", over the " + humanBytes(limits.maxFileBytes) + " limit for a task file";
}

// ---- archives (libarchive) ----

struct ArchiveDeleter {
  void operator()(archive* a) const { archive_read_free(a); }
};

std::string archiveError(archive* a) {
  const char* s = archive_error_string(a);
  return s ? s : "unknown error";
}

Kind kindOf(archive_entry* e) {
  if (archive_entry_hardlink(e) != nullptr) return Kind::Hardlink;
  if (archive_entry_symlink(e) != nullptr) return Kind::Symlink;
  switch (archive_entry_filetype(e)) {
    case AE_IFREG:
      return Kind::Regular;
    case AE_IFDIR:
      return Kind::Directory;
    case AE_IFLNK:
      return Kind::Symlink;
    case AE_IFCHR:
    case AE_IFBLK:
      return Kind::Device;
    case AE_IFIFO:
      return Kind::Fifo;
    case AE_IFSOCK:
      return Kind::Socket;
    default:
      return Kind::Other;
  }
}

// Opens `path` as an archive, or returns libarchive's complaint.
std::unique_ptr<archive, ArchiveDeleter> openArchive(const fs::path& path, std::string& error) {
  std::unique_ptr<archive, ArchiveDeleter> a(archive_read_new());
  archive_read_support_format_zip(a.get());
  archive_read_support_format_tar(a.get());
  archive_read_support_format_empty(a.get());
  archive_read_support_filter_gzip(a.get());
  archive_read_support_filter_bzip2(a.get());
  archive_read_support_filter_xz(a.get());
  if (archive_read_open_filename(a.get(), path.c_str(), 64 << 10) != ARCHIVE_OK) {
    error = archiveError(a.get());
    return nullptr;
  }
  return a;
}

// A single task file submitted on its own (not an archive): taken as it is.
Intake readLoneFile(const fs::path& submission, const fs::path& dest, const IntakeLimits& limits) {
  const std::string name = submission.filename().string();
  Collector c(limits);
  std::ifstream in(submission, std::ios::binary);
  std::string data(limits.maxFileBytes + 1, '\0');
  in.read(data.data(), static_cast<std::streamsize>(data.size()));
  data.resize(static_cast<std::size_t>(in.gcount()));
  c.seen(name, name);
  if (data.size() > limits.maxFileBytes) {
    c.note(tooLarge(name, limits.maxFileBytes, limits, true));
  } else {
    c.offer(name, name, 1, std::move(data));
  }
  return c.finish(dest, "submission", true, false);
}

Intake refused(std::string why) {
  Intake out;
  out.error = std::move(why);
  return out;
}

// One pass over an open archive's entries, within the limits: each entry read by step(), which
// says whether to go on; the task files offered to the Collector, the rest noted.
class ArchiveWalk {
 public:
  ArchiveWalk(archive* a, const fs::path& submission, const IntakeLimits& limits)
      : a_(a), submission_(submission), limits_(limits), c_(limits) {}

  Intake run(const fs::path& dest) {
    while (step()) {
    }
    if (!fatal_.empty()) return refused(fatal_);
    if (!damage_.empty()) {
      // Nothing usable: say so as an error, so that a TA asks for the archive again.
      if (!c_.anyChosen()) {
        return refused("cannot read the archive " + submission_.string() + ": " + damage_ +
                       "; no task file could be read before that point (damaged or truncated? "
                       "re-create the archive and submit it again)");
      }
      c_.note(damage_ +
              "; reading stopped there and only the task files read before that point "
              "are used");
    }
    return c_.finish(dest, "archive", anyEntries_, sawNested_);
  }

 private:
  enum class Data { Read, TooLarge, Failed };

  // Bytes the archive has made us decompress so far (zip skips entries by seeking).
  std::size_t consumed(bool zip) const {
    return zip ? readBytes_ : static_cast<std::size_t>(archive_filter_bytes(a_, 0));
  }

  // The next entry; false when the walk ends (the end, a limit, damage).
  bool step() {
    archive_entry* e = nullptr;
    const int r = archive_read_next_header(a_, &e);
    if (r == ARCHIVE_EOF) return false;
    if (r == ARCHIVE_RETRY) return ++entries_ <= limits_.maxEntries;
    if (r == ARCHIVE_FATAL) return damaged();
    // ARCHIVE_OK or ARCHIVE_WARN (e.g. a name in an unknown character set): go on.
    const bool zip = (archive_format(a_) & ARCHIVE_FORMAT_BASE_MASK) == ARCHIVE_FORMAT_ZIP;
    if (!withinLimits(zip)) return false;
    anyEntries_ = true;
    return take(e, zip);
  }

  // A header that cannot be read: nothing at all, or damage after some entries.
  bool damaged() {
    if (entries_ == 0) {
      fatal_ = "cannot read the archive " + submission_.string() + ": " + archiveError(a_) +
               " (damaged or truncated? re-create the archive and submit it again)";
      return false;
    }
    damage_ =
        "the archive is damaged after " + std::to_string(entries_) + " entries" +
        (lastPath_.empty() ? std::string() : " (the last one read: " + shownPath(lastPath_) + ")") +
        ": " + archiveError(a_);
    return false;
  }

  bool withinLimits(bool zip) {
    if (++entries_ > limits_.maxEntries) {
      c_.note("reading stopped after " + std::to_string(limits_.maxEntries) +
              " entries (the limit): the archive holds too many files; entries after that "
              "point were not looked at");
      return false;
    }
    if (consumed(zip) > limits_.maxTotalBytes) {
      c_.note("reading stopped after " + humanBytes(limits_.maxTotalBytes) +
              " of data (the limit): the archive is too large; entries after that point were "
              "not looked at");
      return false;
    }
    return true;
  }

  // One entry: screened, and read when it is a task file wanted.
  bool take(archive_entry* e, bool zip) {
    const char* rawName = archive_entry_pathname_utf8(e);
    if (rawName == nullptr) rawName = archive_entry_pathname(e);
    if (rawName == nullptr) {
      c_.entryNote("entry " + std::to_string(entries_) + ": skipped: its name cannot be read");
      return true;
    }
    const std::string raw = rawName;
    lastPath_ = raw;
    const EntryPath p = splitPath(raw);
    std::string target;
    if (const char* t = archive_entry_hardlink(e))
      target = t;
    else if (const char* t2 = archive_entry_symlink(e))
      target = t2;
    const std::string name = screen(c_, raw, p, kindOf(e), target, sawNested_);
    const bool sizeKnown = archive_entry_size_is_set(e) != 0;
    const auto size = static_cast<std::uintmax_t>(std::max<la_int64_t>(0, archive_entry_size(e)));
    if (name.empty()) return skip(raw, zip, sizeKnown, size);
    const std::string rel = joinPath(p.parts);
    c_.seen(name, rel);
    if (archive_entry_is_encrypted(e)) {
      c_.entryNote(shownPath(raw) + ": refused: it is encrypted; submit it without a password");
      return true;
    }
    if (sizeKnown && size > limits_.maxFileBytes) {
      c_.entryNote(tooLarge(raw, size, limits_, false));
      return true;
    }
    if (!c_.wanted(name, rel, p.parts.size())) return true;
    return read(raw, name, rel, p.parts.size());
  }

  // Skipping a tar entry decompresses it: stop before a huge one instead (zip seeks).
  bool skip(const std::string& raw, bool zip, bool sizeKnown, std::uintmax_t size) {
    if (zip || !sizeKnown || consumed(zip) + size <= limits_.maxTotalBytes) return true;
    c_.note(shownPath(raw) + " holds " + humanBytes(size) + ": reading stopped there, over the " +
            humanBytes(limits_.maxTotalBytes) +
            " limit for a whole submission; entries "
            "after it were not looked at");
    return false;
  }

  bool read(const std::string& raw, const std::string& name, const std::string& rel,
            std::size_t depth) {
    std::string data;
    switch (readData(data)) {
      case Data::Failed:
        damage_ = "the archive is damaged: the data of " + shownPath(raw) + " cannot be read (" +
                  archiveError(a_) + ")";
        return false;
      case Data::TooLarge:
        c_.entryNote(tooLarge(raw, limits_.maxFileBytes, limits_, true));
        return true;
      case Data::Read:
        break;
    }
    c_.offer(name, rel, depth, std::move(data));
    return true;
  }

  // The current entry's data, never more than the cap (a zip's declared size may lie).
  Data readData(std::string& data) {
    char buf[16 << 10];
    for (;;) {
      const la_ssize_t n = archive_read_data(a_, buf, sizeof buf);
      if (n == 0) return Data::Read;
      if (n < 0) {
        if (n == ARCHIVE_WARN || n == ARCHIVE_RETRY) continue;
        return Data::Failed;
      }
      readBytes_ += static_cast<std::size_t>(n);
      if (data.size() + static_cast<std::size_t>(n) > limits_.maxFileBytes) return Data::TooLarge;
      data.append(buf, static_cast<std::size_t>(n));
    }
  }

  archive* a_;
  const fs::path& submission_;
  const IntakeLimits& limits_;
  Collector c_;
  bool anyEntries_ = false, sawNested_ = false;
  std::string damage_;  // why reading stopped early, when the archive is damaged
  std::string fatal_;   // why nothing could be read at all
  std::size_t entries_ = 0, readBytes_ = 0;
  std::string lastPath_;
};

Intake readArchive(const fs::path& submission, const fs::path& dest, const IntakeLimits& limits) {
  std::string openError;
  auto a = openArchive(submission, openError);
  if (a) return ArchiveWalk(a.get(), submission, limits).run(dest);
  if (isTaskFile(submission.filename().string())) return readLoneFile(submission, dest, limits);
  return refused("cannot read the submission " + submission.string() +
                 ": it is neither a folder nor a zip or tar archive (" + openError +
                 "); submit a folder, a .zip, a .tar or a .tar.gz with the seven .cpp files");
}

// ---- folders (std::filesystem, links never followed) ----

Kind kindOf(fs::file_type t) {
  switch (t) {
    case fs::file_type::regular:
      return Kind::Regular;
    case fs::file_type::directory:
      return Kind::Directory;
    case fs::file_type::symlink:
      return Kind::Symlink;
    case fs::file_type::block:
    case fs::file_type::character:
      return Kind::Device;
    case fs::file_type::fifo:
      return Kind::Fifo;
    case fs::file_type::socket:
      return Kind::Socket;
    default:
      return Kind::Other;
  }
}

// Reads a regular file without following a link at its name, at most `cap` + 1 bytes.
std::optional<std::string> readNoFollow(const fs::path& path, std::size_t cap, std::string& why) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    why = std::strerror(errno);
    return std::nullopt;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    why = "not a regular file";
    return std::nullopt;
  }
  std::string data;
  char buf[16 << 10];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      why = std::strerror(errno);
      ::close(fd);
      return std::nullopt;
    }
    if (n == 0) break;
    data.append(buf, static_cast<std::size_t>(n));
    if (data.size() > cap) break;
  }
  ::close(fd);
  return data;
}

// Whether the walk of a folder stops before its next entry (a read error, or the entry limit),
// with the note saying why.
bool folderWalkEnds(Collector& c, const std::error_code& ec, std::size_t entries,
                    const IntakeLimits& limits) {
  if (ec) {
    c.note("the folder could not be read completely (" + ec.message() +
           "); only the task files found before that point are used");
    return true;
  }
  if (entries > limits.maxEntries) {
    c.note("reading stopped after " + std::to_string(limits.maxEntries) +
           " entries (the limit): the folder holds too many files; the rest was not looked "
           "at");
    return true;
  }
  return false;
}

// Whether the walk looks into the folder at `it`: never the grader's own output folder
// (`destAbs`), nor one deeper than the limit (noted).
bool looksInto(Collector& c, fs::recursive_directory_iterator& it, const fs::path& destAbs,
               const std::string& rel, std::size_t depth, const IntakeLimits& limits) {
  std::error_code ec;
  if (fs::equivalent(it->path(), destAbs, ec)) {
    it.disable_recursion_pending();
    return false;
  }
  if (static_cast<int>(depth) >= limits.maxDepth) {
    it.disable_recursion_pending();
    c.entryNote(shownPath(rel) + ": not looked into: " + std::to_string(depth) +
                " levels deep, the limit is " + std::to_string(limits.maxDepth));
    return false;
  }
  return true;
}

// Reads the copy of task file `name` at `path` (`relStr` in the submission) and offers it,
// unless it is too large or a better copy was already taken.
void takeFolderCopy(Collector& c, const fs::path& path, const std::string& name,
                    const std::string& relStr, std::size_t depth, const IntakeLimits& limits) {
  c.seen(name, relStr);
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (!ec && size > limits.maxFileBytes) {
    c.entryNote(tooLarge(relStr, size, limits, false));
    return;
  }
  if (!c.wanted(name, relStr, depth)) return;
  std::string why;
  auto data = readNoFollow(path, limits.maxFileBytes, why);
  if (!data) {
    c.entryNote(shownPath(relStr) + ": refused: cannot be read (" + why + ")");
  } else if (data->size() > limits.maxFileBytes) {
    c.entryNote(tooLarge(relStr, limits.maxFileBytes, limits, true));
  } else {
    c.offer(name, relStr, depth, std::move(*data));
  }
}

Intake readFolder(const fs::path& root, const fs::path& dest, const IntakeLimits& limits) {
  Collector c(limits);
  bool anyEntries = false, sawNested = false;
  std::size_t entries = 0;
  std::error_code ec;
  // The grader's own output folder may sit inside the submission folder: never read it back.
  const fs::path destAbs = fs::weakly_canonical(dest, ec);
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    Intake out;
    out.error = "cannot read the submission folder " + root.string() + ": " + ec.message() +
                " (check that it exists and is readable)";
    return out;
  }
  for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (folderWalkEnds(c, ec, ++entries, limits)) break;
    anyEntries = true;
    const fs::path path = it->path();
    const std::string rel = path.lexically_relative(root).generic_string();
    const EntryPath p = splitPath(rel);
    std::error_code sec;
    const Kind kind = kindOf(fs::symlink_status(path, sec).type());
    if (kind == Kind::Directory && !looksInto(c, it, destAbs, rel, p.parts.size(), limits)) {
      continue;
    }
    const std::string target =
        kind == Kind::Symlink ? fs::read_symlink(path, sec).string() : std::string();
    const std::string name = screen(c, rel, p, kind, target, sawNested);
    if (!name.empty()) takeFolderCopy(c, path, name, joinPath(p.parts), p.parts.size(), limits);
  }
  return c.finish(dest, "folder", anyEntries, sawNested);
}

}  // namespace

Intake takeSubmission(const std::filesystem::path& submission, const std::filesystem::path& dest,
                      const IntakeLimits& limits) {
  try {
    std::error_code ec;
    // The submission path itself comes from the TA: follow it if it is a link.
    const fs::file_status st = fs::status(submission, ec);
    if (ec || st.type() == fs::file_type::not_found) {
      Intake out;
      out.error = "the submission " + submission.string() + " does not exist" +
                  (ec && ec != std::errc::no_such_file_or_directory ? " (" + ec.message() + ")"
                                                                    : std::string()) +
                  "; check the path";
      return out;
    }
    if (st.type() == fs::file_type::directory) return readFolder(submission, dest, limits);
    if (st.type() == fs::file_type::regular) return readArchive(submission, dest, limits);
    Intake out;
    out.error = "the submission " + submission.string() +
                " is neither a folder nor a regular file (an archive); check the path";
    return out;
  } catch (const std::exception& e) {
    Intake out;
    out.error =
        std::string("reading the submission ") + submission.string() + " failed: " + e.what();
    return out;
  }
}

}  // namespace a6::grader
