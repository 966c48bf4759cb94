// The grader tests' submissions, prepared one way for every test that grades them
// (hostile_test.cpp and scores_test.cpp case by case, batch_test.cpp all in one batch):
//   - the wrong versions of tests/wrong/<name>/ over the solution's files, and the tasks their
//     EXPECT files name;
//   - the fixtures of tests/grader/submissions/<case>/ staged over the solution's files, with
//     @A6_SOURCE_DIR@ replaced by the repository's path (so that the attacks aim at the real
//     solution and goldens) and a link kept a link;
//   - the archive cases, written at test time with libarchive (entries whose paths leave the
//     archive, links to the solution);
//   - a copy of a rubric with every time limit cut short, for the cases whose code never returns.
//
// The including test defines A6_SOURCE_DIR (the repository) and links LibArchive.
#pragma once

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/tasks.h"

#ifndef A6_SOURCE_DIR
#error "define A6_SOURCE_DIR (the repository) to include staging.h"
#endif

namespace a6::test::staging {

namespace fs = std::filesystem;

using a6::kTaskFiles;  // harness/tasks.h
inline const fs::path kSource = A6_SOURCE_DIR;
inline const fs::path kFixtures = kSource / "tests" / "grader" / "submissions";

inline std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void writeAll(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

inline std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) {
    s.replace(at, from.size(), to);
  }
  return s;
}

// ---- fixture folders ----------------------------------------------------------------------------

/// The fixture's text as graded: @A6_SOURCE_DIR@ becomes the repository's path.
inline std::string substituted(const fs::path& file) {
  return replaceAll(readAll(file), "@A6_SOURCE_DIR@", kSource.string());
}

/// Every fixture folder's name, sorted.
inline std::vector<std::string> fixtures() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kFixtures)) {
    if (entry.is_directory()) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// The task files a fixture's submission leaves out (its README says so).
inline std::vector<std::string> omittedBy(const std::string& fixture) {
  if (fixture == "missing_file") return {"cloth.cpp"};
  return {};
}

/// A submission folder: the solution's seven files, the starter's for the tasks in `starter`,
/// then the fixture's task files over them (a link stays a link, made absolute), without
/// `omit`. Throws when the fixture does not exist.
inline fs::path stage(const fs::path& dir, const std::string& fixture,
                      const std::set<int>& starter = {},
                      const std::vector<std::string>& omit = {}) {
  fs::create_directories(dir);
  for (std::size_t i = 0; i < kTaskFiles.size(); ++i) {
    const std::string& file = kTaskFiles[i];
    const char* from = starter.count(static_cast<int>(i + 1)) ? "starter" : "solution";
    fs::copy_file(kSource / from / file, dir / file, fs::copy_options::overwrite_existing);
  }
  if (!fixture.empty()) {
    const fs::path source = kFixtures / fixture;
    if (!fs::is_directory(source)) throw std::runtime_error("no fixture " + source.string());
    for (const std::string& file : kTaskFiles) {
      const fs::path f = source / file;
      if (fs::is_symlink(f)) {
        fs::remove(dir / file);
        fs::create_symlink(fs::canonical(f), dir / file);
      } else if (fs::exists(f)) {
        writeAll(dir / file, substituted(f));
      }
    }
  }
  for (const std::string& file : omit) fs::remove(dir / file);
  return dir;
}

// ---- wrong versions -----------------------------------------------------------------------------

// Variants of the solution: tests/wrong/<name>/ and tests/alternative/<name>/ each hold some of
// the seven files, to be graded in place of the solution's.

/// The folders under tests/<kind>/ (sorted) that hold `marker` ("" for any folder).
inline std::vector<std::string> variants(const std::string& kind, const std::string& marker) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(kSource / "tests" / kind, ec)) {
    if (entry.is_directory() && (marker.empty() || fs::exists(entry.path() / marker))) {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// The folder tests/<kind>/<name> is graded as: the solution's seven files, its own in their place
/// (as the build applied its patches: BUILD/variants/<kind>/<name>/, cmake/A6Variants.cmake).
inline fs::path stageVariant(const fs::path& dir, const std::string& kind,
                             const std::string& name) {
#ifndef A6_VARIANTS_DIR
#error "define A6_VARIANTS_DIR (BUILD/variants) to stage a wrong version or an alternative"
#endif
  fs::create_directories(dir);
  for (const std::string& file : kTaskFiles) {
    const fs::path own = fs::path(A6_VARIANTS_DIR) / kind / name / file;
    fs::copy_file(fs::exists(own) ? own : kSource / "solution" / file, dir / file,
                  fs::copy_options::overwrite_existing);
  }
  return dir;
}

/// Every wrong version under tests/wrong/ (a folder with an EXPECT file), sorted.
inline std::vector<std::string> wrongVersions() { return variants("wrong", "EXPECT"); }
inline fs::path stageWrong(const fs::path& dir, const std::string& name) {
  return stageVariant(dir, "wrong", name);
}

/// Every correct alternative under tests/alternative/ (a folder), sorted.
inline std::vector<std::string> alternatives() { return variants("alternative", ""); }
inline fs::path stageAlternative(const fs::path& dir, const std::string& name) {
  return stageVariant(dir, "alternative", name);
}

/// The tasks a wrong version's EXPECT file names ("fail: 3 4").
inline std::set<int> failingTasks(const std::string& name) {
  std::set<int> tasks;
  std::istringstream in(readAll(kSource / "tests" / "wrong" / name / "EXPECT"));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("fail:", 0) != 0) continue;
    std::istringstream numbers(line.substr(5));
    for (int t; numbers >> t;) tasks.insert(t);
  }
  return tasks;
}

/// The first word after "<key>:" in a wrong version's EXPECT file, or "" when it has none.
inline std::string expected(const std::string& name, const std::string& key) {
  std::istringstream in(readAll(kSource / "tests" / "wrong" / name / "EXPECT"));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key + ":", 0) != 0) continue;
    std::istringstream id(line.substr(key.size() + 1));
    std::string word;
    id >> word;
    return word;
  }
  return "";
}

/// The known mistake the grader must name for a wrong version: its EXPECT file's "mistake: <id>"
/// line (grader/mistakes/library/), or "" when it has none.
inline std::string expectedMistake(const std::string& name) { return expected(name, "mistake"); }

/// What the diagnosis by measurement must give for a wrong version (grader/mistakes/measure.h):
/// its EXPECT file's "diagnosis: <id>" line, or "" when it must give nothing.
inline std::string expectedDiagnosis(const std::string& name) {
  return expected(name, "diagnosis");
}

// ---- archives -----------------------------------------------------------------------------------

struct Entry {
  enum class Type { File, Symlink, Hardlink };
  Entry(std::string p, std::string d) : path(std::move(p)), data(std::move(d)) {}
  Entry(std::string p, Type t, std::string target)
      : path(std::move(p)), type(t), link(std::move(target)) {}
  std::string path;
  std::string data;
  Type type = Type::File;
  std::string link;
};

/// Writes a zip, or a tar.gz; returns "" or what failed.
inline std::string writeArchive(const fs::path& out, bool zip, const std::vector<Entry>& entries) {
  archive* a = archive_write_new();
  if (zip) {
    archive_write_set_format_zip(a);
  } else {
    archive_write_set_format_pax_restricted(a);
    archive_write_add_filter_gzip(a);
  }
  auto failed = [a](const std::string& what) {
    const char* why = archive_error_string(a);
    const std::string error = what + ": " + (why != nullptr ? why : "unknown error");
    archive_write_free(a);
    return error;
  };
  if (archive_write_open_filename(a, out.c_str()) != ARCHIVE_OK)
    return failed("open " + out.string());
  for (const Entry& e : entries) {
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, e.path.c_str());
    archive_entry_set_perm(entry, 0644);
    archive_entry_set_mtime(entry, 1700000000, 0);
    if (e.type == Entry::Type::Symlink) {
      archive_entry_set_filetype(entry, AE_IFLNK);
      archive_entry_set_symlink(entry, e.link.c_str());
    } else if (e.type == Entry::Type::Hardlink) {
      archive_entry_set_filetype(entry, AE_IFREG);
      archive_entry_set_hardlink(entry, e.link.c_str());
      archive_entry_set_size(entry, 0);
    } else {
      archive_entry_set_filetype(entry, AE_IFREG);
      archive_entry_set_size(entry, static_cast<la_int64_t>(e.data.size()));
    }
    const int header = archive_write_header(a, entry);
    archive_entry_free(entry);
    if (header < ARCHIVE_WARN) return failed("header of " + e.path);
    if (e.type == Entry::Type::File && !e.data.empty() &&
        archive_write_data(a, e.data.data(), e.data.size()) !=
            static_cast<la_ssize_t>(e.data.size())) {
      return failed("data of " + e.path);
    }
  }
  if (archive_write_close(a) != ARCHIVE_OK) return failed("close " + out.string());
  archive_write_free(a);
  return "";
}

/// The solution's files with `replaced` left out, as archive entries.
inline std::vector<Entry> solutionEntriesExcept(const std::set<std::string>& replaced) {
  std::vector<Entry> entries;
  for (const std::string& file : kTaskFiles) {
    if (!replaced.count(file)) entries.push_back({file, readAll(kSource / "solution" / file)});
  }
  return entries;
}

/// An archive whose spring.cpp (the solution's) only comes with paths that leave it: relative
/// ('..'), through a folder ('sub/../..'), and absolute; the other five files are the
/// solution's. Graded, spring.cpp is not found.
inline std::vector<Entry> traversalEntries() {
  const std::string spring = readAll(kSource / "solution" / "spring.cpp");
  std::vector<Entry> entries = {{"../spring.cpp", spring},
                                {"sub/../../spring.cpp", spring},
                                {"../../../../a6_traversal_spring.cpp", spring},
                                {"/tmp/a6_traversal_abs/spring.cpp", spring}};
  for (Entry& e : solutionEntriesExcept({"spring.cpp"})) entries.push_back(std::move(e));
  return entries;
}

/// A tar.gz whose spring.cpp is a symbolic link and forces.cpp a hard link to the solution's
/// files. Graded, both are refused.
inline std::vector<Entry> linkEntries() {
  std::vector<Entry> entries = {
      {"spring.cpp", Entry::Type::Symlink, (kSource / "solution" / "spring.cpp").string()},
      {"forces.cpp", Entry::Type::Hardlink, (kSource / "solution" / "forces.cpp").string()}};
  for (Entry& e : solutionEntriesExcept({"spring.cpp", "forces.cpp"}))
    entries.push_back(std::move(e));
  return entries;
}

/// The archive cases: the case's name, its archive's file name, and its entries.
struct ArchiveCase {
  std::string name;
  std::string file;
  std::vector<Entry> entries;
  bool zip() const { return file.size() > 4 && file.compare(file.size() - 4, 4, ".zip") == 0; }
};
inline std::vector<ArchiveCase> archiveCases() {
  return {{"zip_traversal", "traversal.zip", traversalEntries()},
          {"tar_traversal", "traversal.tar.gz", traversalEntries()},
          {"symlink_archive", "links.tar.gz", linkEntries()}};
}

// ---- rubrics ------------------------------------------------------------------------------------

/// A copy of `rubric` in `dir` with every time limit cut to `seconds` (for the cases whose
/// code never returns: the correct checks take well under a tenth of a second each).
inline fs::path withTimeLimit(const fs::path& rubric, const fs::path& dir, double seconds) {
  const std::regex limit("^time_limit *= *[0-9.]+", std::regex::multiline);
  const fs::path fast = dir / "fast_rubric.toml";
  writeAll(fast,
           std::regex_replace(readAll(rubric), limit, "time_limit = " + std::to_string(seconds)));
  return fast;
}

}  // namespace a6::test::staging
