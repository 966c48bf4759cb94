// The object cache. See object_cache.h for what an entry is and why it can be trusted.
//
// An entry is a folder DIR/<hash>/ of four files:
//   label     the fingerprint, the task file's name, the object's size and hash
//   source    the exact text compiled
//   messages  what the compiler said, as the student was shown it
//   object.o  the object
// It is written under a temporary name (.new-*), flushed to disk, and renamed into place whole,
// so a reader sees a whole entry or none; an entry it replaces is first renamed away (.old-*).
#include "build/object_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <vector>

#include "common/fnv1a.h"

namespace a6::grader {
namespace {

namespace fs = std::filesystem;

// FNV-1a names an entry's folder and sums its object. Neither is a defence against forgery:
// find() compares the text itself, and only the grader writes an object.
std::string sum(const std::string& bytes) {
  Fnv1a h;
  h.add(bytes);
  return std::to_string(bytes.size()) + " " + h.hex();
}

// Writes and flushes to disk: an entry renamed into place is whole even after a power cut.
bool writeDurably(const fs::path& file, const std::string& bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  const bool ok = done == bytes.size() && ::fsync(fd) == 0;
  return ::close(fd) == 0 && ok;
}

// "size time" of a file or folder (following links: the compiler is reached through them).
std::string stamp(const fs::path& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return "-";
  return std::to_string(st.st_size) + " " + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

// The stamps of `dir` and every folder under it (with `files`, of every file too).
void addTree(Fnv1a& h, const fs::path& dir, bool files) {
  h.add(dir.string() + " " + stamp(dir));
  std::vector<std::string> seen;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code tec;
    if (it->is_directory(tec) || (files && it->is_regular_file(tec))) {
      seen.push_back(it->path().string() + " " + stamp(it->path()));
    }
  }
  std::sort(seen.begin(), seen.end());
  for (const std::string& s : seen) h.add(s);
}

// The kit's staged headers, by their text.
std::string headersOf(const Kit& kit) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(kit.dir / "include", ec), end; !ec && it != end;
       it.increment(ec)) {
    std::error_code tec;
    if (it->is_regular_file(tec)) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  Fnv1a h;
  for (const fs::path& f : files) {
    h.add(f.string());
    h.add(readRegularFile(f).value_or("(unreadable)"));
  }
  return h.hex();
}

// The system's part: compiler, assembler, their folders and the headers' folders.
std::string systemOf(const Kit& kit) {
  Fnv1a h;
  for (const fs::path& program :
       {fs::path("/proc/self/exe"), fs::path(kit.compiler), fs::path("/usr/bin/as")}) {
    std::error_code ec;
    h.add(fs::canonical(program, ec).string() + " " + stamp(program));
  }
  for (const char* dir : {"/usr/include", "/usr/lib/gcc", "/usr/libexec/gcc"}) {
    addTree(h, dir, false);
  }
  for (std::size_t i = 0; i + 1 < kit.compileFlags.size(); ++i) {
    const std::string& flag = kit.compileFlags[i];
    const std::string& value = kit.compileFlags[i + 1];
    if (flag == "-isystem" && value.rfind("/usr/include/", 0) != 0) addTree(h, value, true);
    if (flag == "-include") h.add(stamp(value + ".gch"));
  }
  return h.hex();
}

}  // namespace

std::optional<std::string> readRegularFile(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st;
  std::optional<std::string> bytes;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    std::string data(static_cast<std::size_t>(st.st_size), '\0');
    std::size_t got = 0;
    while (got < data.size()) {
      const ssize_t n = ::read(fd, data.data() + got, data.size() - got);
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    if (got == data.size()) bytes = std::move(data);
  }
  ::close(fd);
  return bytes;
}

std::string kitFingerprint(const Kit& kit) {
  std::string out = "compiler " + kit.compiler + "\nflags";
  for (const std::string& flag : kit.compileFlags) out += " " + flag;
  out += "\nsecrets";
  for (const fs::path& s : kit.secrets) out += " " + s.string();
  return out + "\nheaders " + headersOf(kit) + "\nsystem " + systemOf(kit) + "\n";
}

ObjectCache::ObjectCache(fs::path dir, std::string fingerprint)
    : fingerprint_(std::move(fingerprint)) {
  dir = fs::absolute(dir).lexically_normal();
  std::error_code ec;
  fs::create_directories(dir.parent_path(), ec);
  // Other submissions' objects: the grader's alone, from the start.
  if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) {
    error_ = "the object cache " + dir.string() + " cannot be created (" + std::strerror(errno) +
             "): every file was compiled";
    return;
  }
  struct stat st;
  if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::geteuid() ||
      (st.st_mode & 077) != 0) {
    error_ = "the object cache " + dir.string() +
             " is not a folder of the grader's alone (mode 0700, owned by the grader's user): "
             "every file was compiled";
    return;
  }
  dir_ = dir;
  removeLeftovers();
}

// What graders killed while keeping or replacing an entry left, an hour on.
void ObjectCache::removeLeftovers() const {
  const auto hourAgo = fs::file_time_type::clock::now() - std::chrono::hours(1);
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code tec;
    if ((name.rfind(".new-", 0) == 0 || name.rfind(".old-", 0) == 0) &&
        fs::last_write_time(it->path(), tec) < hourAgo && !tec) {
      fs::remove_all(it->path(), tec);
    }
  }
}

std::string ObjectCache::label(const std::string& file) const {
  return fingerprint_ + "file " + file + "\n";
}

fs::path ObjectCache::entryDir(const std::string& file, const std::string& source) const {
  Fnv1a h;
  h.add(label(file));
  h.add(source);
  return dir_ / h.hex();
}

std::optional<CachedCompile> ObjectCache::find(const std::string& file,
                                               const std::string& source) const {
  if (!on()) return std::nullopt;
  const fs::path entry = entryDir(file, source);
  const std::optional<std::string> labelled = readRegularFile(entry / "label");
  if (!labelled || labelled->rfind(label(file), 0) != 0 ||
      readRegularFile(entry / "source") != source) {
    return std::nullopt;
  }
  std::optional<std::string> object = readRegularFile(entry / "object.o");
  std::optional<std::string> messages = readRegularFile(entry / "messages");
  if (!object || !messages || *labelled != label(file) + "object " + sum(*object) + "\n") {
    return std::nullopt;  // cut short, or changed since it was kept
  }
  return CachedCompile{std::move(*object), std::move(*messages)};
}

std::string ObjectCache::keep(const std::string& file, const std::string& source,
                              const fs::path& object, const std::string& messages) const {
  if (!on()) return "the cache is off";
  if (find(file, source)) return "";  // kept already, whole
  const std::optional<std::string> bytes = readRegularFile(object);
  if (!bytes) return "the object " + object.string() + " is not a regular file";
  if (bytes->size() > kMaxObjectBytes) return "";  // not worth the room
  std::string tmpl = (dir_ / ".new-XXXXXX").string();
  if (::mkdtemp(tmpl.data()) == nullptr) return "cannot create an entry in " + dir_.string();
  const fs::path tmp = tmpl;
  std::error_code ec;
  if (!writeDurably(tmp / "source", source) || !writeDurably(tmp / "messages", messages) ||
      !writeDurably(tmp / "object.o", *bytes) ||
      !writeDurably(tmp / "label", label(file) + "object " + sum(*bytes) + "\n")) {
    fs::remove_all(tmp, ec);
    return "cannot write an entry in " + dir_.string() + " (is the disk full?)";
  }
  // rename() of a folder onto a full one fails: if another grader put this entry in place
  // meanwhile, that one stays.
  const fs::path entry = entryDir(file, source);
  const fs::path old = moveAside(entry);
  if (std::rename(tmp.c_str(), entry.c_str()) != 0) fs::remove_all(tmp, ec);
  if (!old.empty()) fs::remove_all(old, ec);
  return "";
}

// A broken entry, or another text's that took the folder name, makes way: renamed into a
// .old-* folder, returned for removal ("" when there was none). A reader has its bytes already.
fs::path ObjectCache::moveAside(const fs::path& entry) const {
  std::error_code ec;
  if (!fs::exists(entry, ec)) return {};
  std::string old = (dir_ / ".old-XXXXXX").string();
  if (::mkdtemp(old.data()) == nullptr) return {};
  std::rename(entry.c_str(), (fs::path(old) / "entry").c_str());
  return old;
}

}  // namespace a6::grader
