// The checks of each entry and the Collector (see entries.h).
#include "intake/entries.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "harness/tasks.h"
#include "sandbox/sandbox.h"  // kOpenFolder, kReadableFile

namespace a6::grader::entries {

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

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The task file `name` matches when case is ignored (a near miss worth a note), or "".
std::string nearMissOf(const std::string& name) {
  const std::string l = lower(name);
  for (const std::string& task : kTaskFiles) {
    if (l == task || l == task + ".txt") return task;
  }
  return "";
}

bool isNestedArchive(const std::string& name) {
  static const char* const kExtensions[] = {".zip",    ".tar", ".tgz", ".tar.gz", ".tar.bz2",
                                            ".tar.xz", ".gz",  ".7z",  ".rar"};
  const std::string l = lower(name);
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

}  // namespace

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

bool better(const Copy& a, const Copy& b) {
  return a.depth != b.depth ? a.depth < b.depth : a.path < b.path;
}

namespace {
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

// Creates dest, readable by the sandbox's user. False (with out.error) when it cannot.
bool makeDest(const fs::path& dest, Intake& out) {
  std::error_code ec;
  fs::create_directories(dest, ec);
  if (ec) {
    out.error = "cannot create the folder " + dest.string() +
                " for the submission's files: " + ec.message() +
                " (check that the output folder is writable)";
    out.graderFault = true;
    return false;
  }
  fs::permissions(dest, kOpenFolder, ec);
  return true;
}
}  // namespace

std::string screen(Collector& c, const std::string& raw, const EntryPath& p, Kind kind,
                   const std::string& linkTarget, bool& sawNestedArchive) {
  if (p.absolute || p.parent) {
    c.entryNote(shownPath(raw) +
                ": refused: " + (p.absolute ? "an absolute path" : "the path contains '..'") +
                " (nothing is ever written outside the grader's folder)");
    return "";
  }
  if (p.parts.empty()) return "";
  if (p.parts.front() == "__MACOSX") return "";  // macOS resource forks ("._spring.cpp")
  const std::string name = p.name();
  if (kind == Kind::Directory) return "";
  if (static_cast<int>(p.parts.size()) > c.limits().maxDepth) {
    c.entryNote(shownPath(raw) + ": skipped: " + std::to_string(p.parts.size()) +
                " levels deep, over the limit of " + std::to_string(c.limits().maxDepth));
    return "";
  }
  if (kind != Kind::Regular) {
    std::string why = describe(kind);
    if (!linkTarget.empty()) why += " to " + shownPath(linkTarget);
    c.entryNote(shownPath(raw) + ": refused: " + why +
                "; links and special files are never followed" +
                (isTaskFile(name) ? ": submit the file itself" : ""));
    if (isTaskFile(name)) c.seen(name, joinPath(p.parts));
    return "";
  }
  if (isTaskFile(name)) return name;
  if (isNestedArchive(name)) {
    sawNestedArchive = true;
    c.entryNote(shownPath(raw) +
                ": a nested archive, not opened (submit the .cpp files "
                "themselves, not an archive inside the archive)");
    return "";
  }
  const std::string near = nearMissOf(name);
  if (!near.empty()) {
    c.entryNote(shownPath(raw) + ": ignored: the name must be exactly '" + near +
                "' (names are case-sensitive)");
  }
  return "";
}

std::string tooLarge(const std::string& path, std::uintmax_t size, const IntakeLimits& limits,
                     bool atLeast) {
  return shownPath(path) + ": refused: " + (atLeast ? "more than " : "") + humanBytes(size) +
         ", over the " + humanBytes(limits.maxFileBytes) + " limit for a task file";
}

void Collector::offer(const std::string& name, const std::string& path, std::size_t depth,
                      std::string data) {
  if (data.find('\0') != std::string::npos) {
    entryNote(shownPath(path) +
              ": refused: it contains NUL bytes, so it is binary, not C++ "
              "source; submit the .cpp text file");
    return;
  }
  if (wanted(name, path, depth)) chosen_[name] = Copy{path, depth, std::move(data)};
}

Intake Collector::finish(const fs::path& dest, const std::string& what, bool anyEntries,
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

bool Collector::write(const fs::path& target, const Copy& copy, Intake& out) {
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
  fs::permissions(target, kReadableFile, ec);
  if (!validUtf8(copy.data)) {
    note(shownPath(copy.path) +
         ": not valid UTF-8 text (taken anyway; if the compiler "
         "rejects a character, save the file as UTF-8)");
  }
  return true;
}

void Collector::noteDuplicates(const std::string& name, const std::string& taken) {
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

void Collector::closingNotes(const std::string& what, bool anyEntries, bool sawNestedArchive,
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

}  // namespace a6::grader::entries
