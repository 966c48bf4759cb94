// The object cache. See object_cache.h for what an entry is and why it can be trusted.
//
// An entry is a folder DIR/<hash>/ of four files:
//   label     the kit's fingerprint and the task file's name
//   source    the exact text compiled
//   messages  what the compiler said, as the student was shown it
//   object.o  the object
// It is written under a temporary name and renamed into place whole, so a reader sees a whole
// entry or none.
#include "build/object_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>
#include <vector>

namespace a6::grader {
namespace {

namespace fs = std::filesystem;

// FNV-1a, 64 bits: names an entry's folder. Only a hint: find() compares the text itself.
struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(const std::string& bytes) {
    for (const unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // a separator: "ab"+"c" differs from "a"+"bc"
  }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
  }
};

// The bytes of a regular file (never through a link), or nothing.
std::optional<std::string> readRegular(const fs::path& file) {
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

bool writeFile(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
  return static_cast<bool>(out.flush());
}

// "size time" of a file (following links: the compiler is reached through them), or "-".
std::string stamp(const fs::path& file) {
  struct stat st;
  if (::stat(file.c_str(), &st) != 0) return "-";
  return std::to_string(st.st_size) + " " + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

// Each file under `dir`, sorted, with its stamp (or its text when `text`).
void addTree(Fnv& h, std::string& out, const fs::path& dir, bool text) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file(ec)) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    if (text) {
      out += "header " + f.string() + "\n";
      h.add(readRegular(f).value_or("(unreadable)"));
    } else {
      h.add(f.string() + " " + stamp(f));
    }
  }
}

}  // namespace

std::string kitFingerprint(const Kit& kit) {
  std::error_code ec;
  const fs::path compiler = fs::canonical(kit.compiler, ec);
  std::string out =
      "compiler " + (ec ? kit.compiler : compiler.string()) + " " + stamp(kit.compiler) + "\nflags";
  Fnv system, headers;
  for (std::size_t i = 0; i < kit.compileFlags.size(); ++i) {
    const std::string& flag = kit.compileFlags[i];
    out += " " + flag;
    if (flag == "-isystem" && i + 1 < kit.compileFlags.size()) {
      addTree(system, out, kit.compileFlags[i + 1], false);
    } else if (flag == "-include" && i + 1 < kit.compileFlags.size()) {
      system.add(stamp(kit.compileFlags[i + 1] + ".gch"));
    }
  }
  out += "\n";
  addTree(headers, out, kit.dir / "include", true);
  return out + "headers " + headers.hex() + "\nsystem " + system.hex() + "\n";
}

ObjectCache::ObjectCache(fs::path dir, std::string kitFingerprint)
    : fingerprint_(std::move(kitFingerprint)) {
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
}

std::string ObjectCache::label(const std::string& file) const {
  return fingerprint_ + "file " + file + "\n";
}

fs::path ObjectCache::entryDir(const std::string& file, const std::string& source) const {
  Fnv h;
  h.add(label(file));
  h.add(source);
  return dir_ / h.hex();
}

std::optional<CachedCompile> ObjectCache::find(const std::string& file,
                                               const std::string& source) const {
  if (!on()) return std::nullopt;
  const fs::path entry = entryDir(file, source);
  if (readRegular(entry / "label") != label(file) || readRegular(entry / "source") != source) {
    return std::nullopt;
  }
  const std::optional<std::string> messages = readRegular(entry / "messages");
  struct stat st;
  if (!messages || ::lstat((entry / "object.o").c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    return std::nullopt;
  }
  return CachedCompile{entry / "object.o", *messages};
}

std::string ObjectCache::keep(const std::string& file, const std::string& source,
                              const fs::path& object, const std::string& messages) const {
  if (!on()) return "the cache is off";
  const fs::path entry = entryDir(file, source);
  std::error_code ec;
  if (fs::exists(entry, ec)) return "";  // kept already (find() judges it)
  const std::optional<std::string> bytes = readRegular(object);
  if (!bytes) return "the object " + object.string() + " is not a regular file";
  std::string tmpl = (dir_ / ".new-XXXXXX").string();
  if (::mkdtemp(tmpl.data()) == nullptr) return "cannot create an entry in " + dir_.string();
  const fs::path tmp = tmpl;
  const bool written = writeFile(tmp / "label", label(file)) && writeFile(tmp / "source", source) &&
                       writeFile(tmp / "messages", messages) && writeFile(tmp / "object.o", *bytes);
  // rename() of a folder onto an existing one fails: an entry kept meanwhile stays as it is.
  if (!written || std::rename(tmp.c_str(), entry.c_str()) != 0) {
    fs::remove_all(tmp, ec);
    return written ? "" : "cannot write an entry in " + dir_.string();
  }
  return "";
}

}  // namespace a6::grader
