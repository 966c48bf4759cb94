// Taking a submission in. See intake.h for the contract.
//
// Intake notes: a submission is untrusted data, so nothing is extracted. Only entries named as a
// task file are read, into memory, capped, and the chosen copies are written under `dest` with
// the known names: nothing a submission names can make us write elsewhere, so '..', absolute
// paths, links and devices are only reported.
//
// The shallowest copy wins (Gradescope puts the files at the root, students often zip their
// folder); ties go to the path that sorts first, so that archive or directory order never
// matters. Zip bombs: only task files' data is read, and reading stops at maxEntries entries or
// maxTotalBytes decompressed.
#include "intake/intake.h"

#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <system_error>

#include "intake/entries.h"

namespace a6::grader {
namespace {

namespace fs = std::filesystem;
using namespace entries;  // NOLINT: this stage's own parts (entries.h)

// ---- archives (libarchive) ----

struct ArchiveDeleter {
  void operator()(archive* a) const { archive_read_free(a); }
};

std::string archiveError(archive* a) {
  const char* s = archive_error_string(a);
  return s ? s : "unknown error";
}

// What an entry is, from its mode: an archive's (AE_IF* are the S_IF* values) or lstat's.
Kind kindOf(mode_t mode) {
  switch (mode & S_IFMT) {
    case S_IFREG:
      return Kind::Regular;
    case S_IFDIR:
      return Kind::Directory;
    case S_IFLNK:
      return Kind::Symlink;
    case S_IFCHR:
    case S_IFBLK:
      return Kind::Device;
    case S_IFIFO:
      return Kind::Fifo;
    case S_IFSOCK:
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

// One pass over an open archive's entries, within the limits: step() takes one entry and says
// whether to go on.
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
              "; reading stopped there and only the task files read before that point are used");
    }
    return c_.finish(dest, "archive", anyEntries_, sawNested_);
  }

 private:
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
    Kind kind = kindOf(archive_entry_filetype(e));
    std::string target;
    if (const char* t = archive_entry_hardlink(e)) {
      kind = Kind::Hardlink;
      target = t;
    } else if (const char* t2 = archive_entry_symlink(e)) {
      kind = Kind::Symlink;
      target = t2;
    }
    const std::string name = screen(c_, raw, p, kind, target, sawNested_);
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
            " limit for a whole submission; entries after it were not looked at");
    return false;
  }

  // Reads the entry's data, never more than the cap (a zip's declared size may lie), and offers
  // it; false when the archive is damaged there.
  bool read(const std::string& raw, const std::string& name, const std::string& rel,
            std::size_t depth) {
    std::string data;
    char buf[16 << 10];
    for (la_ssize_t n; (n = archive_read_data(a_, buf, sizeof buf)) != 0;) {
      if (n == ARCHIVE_WARN || n == ARCHIVE_RETRY) continue;
      if (n < 0) {
        damage_ = "the archive is damaged: the data of " + shownPath(raw) + " cannot be read (" +
                  archiveError(a_) + ")";
        return false;
      }
      readBytes_ += static_cast<std::size_t>(n);
      if (data.size() + static_cast<std::size_t>(n) > limits_.maxFileBytes) {
        c_.entryNote(tooLarge(raw, limits_.maxFileBytes, limits_, true));
        return true;
      }
      data.append(buf, static_cast<std::size_t>(n));
    }
    c_.offer(name, rel, depth, std::move(data));
    return true;
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

// Whether the walk of a folder stops before its next entry (a read error, the limit), noted.
bool folderWalkEnds(Collector& c, const std::error_code& ec, std::size_t entries,
                    const IntakeLimits& limits) {
  if (ec) {
    c.note("the folder could not be read completely (" + ec.message() +
           "); only the task files found before that point are used");
    return true;
  }
  if (entries > limits.maxEntries) {
    c.note("reading stopped after " + std::to_string(limits.maxEntries) +
           " entries (the limit): the folder holds too many files; the rest was not looked at");
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
    return refused("cannot read the submission folder " + root.string() + ": " + ec.message() +
                   " (check that it exists and is readable)");
  }
  for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (folderWalkEnds(c, ec, ++entries, limits)) break;
    anyEntries = true;
    const fs::path path = it->path();
    const std::string rel = path.lexically_relative(root).generic_string();
    const EntryPath p = splitPath(rel);
    struct stat st {};
    const Kind kind = ::lstat(path.c_str(), &st) == 0 ? kindOf(st.st_mode) : Kind::Other;
    if (kind == Kind::Directory && !looksInto(c, it, destAbs, rel, p.parts.size(), limits)) {
      continue;
    }
    std::error_code sec;
    const std::string target =
        kind == Kind::Symlink ? fs::read_symlink(path, sec).string() : std::string();
    const std::string name = screen(c, rel, p, kind, target, sawNested);
    if (!name.empty()) takeFolderCopy(c, path, name, joinPath(p.parts), p.parts.size(), limits);
  }
  return c.finish(dest, "folder", anyEntries, sawNested);
}

}  // namespace

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

Intake takeSubmission(const std::filesystem::path& submission, const std::filesystem::path& dest,
                      const IntakeLimits& limits) {
  try {
    std::error_code ec;
    // The submission path itself comes from the TA: follow it if it is a link.
    const fs::file_status st = fs::status(submission, ec);
    if (ec || st.type() == fs::file_type::not_found) {
      return refused("the submission " + submission.string() + " does not exist" +
                     (ec && ec != std::errc::no_such_file_or_directory ? " (" + ec.message() + ")"
                                                                       : std::string()) +
                     "; check the path");
    }
    if (st.type() == fs::file_type::directory) return readFolder(submission, dest, limits);
    if (st.type() == fs::file_type::regular) return readArchive(submission, dest, limits);
    return refused("the submission " + submission.string() +
                   " is neither a folder nor a regular file (an archive); check the path");
  } catch (const std::exception& e) {
    return refused("reading the submission " + submission.string() + " failed: " + e.what());
  }
}

}  // namespace a6::grader
