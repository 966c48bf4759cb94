// Taking a submission in (grader/intake/intake.*): folders, zips, tarballs, Gradescope's flat
// layout, and hostile archives. Archives are written here, at run time, with libarchive's writer.
#include "intake/intake.h"

#include <archive.h>
#include <archive_entry.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using a6::grader::Intake;
using a6::grader::IntakeLimits;
using a6::grader::kTaskFiles;
using a6::grader::takeSubmission;

namespace {

// One entry of an archive written by a test.
struct Entry {
  std::string path;
  std::string data;
  enum class Type { File, Dir, Symlink, Hardlink, CharDevice, Fifo } type = Type::File;
  std::string link = "";  // target of a symlink or hard link
};

Entry file(std::string path, std::string data) {
  return {std::move(path), std::move(data), Entry::Type::File, ""};
}

enum class Format { Zip, Tar, TarGz };

void writeArchive(const fs::path& out, Format format, const std::vector<Entry>& entries) {
  archive* a = archive_write_new();
  if (format == Format::Zip) {
    archive_write_set_format_zip(a);
  } else {
    archive_write_set_format_pax_restricted(a);
    if (format == Format::TarGz) archive_write_add_filter_gzip(a);
  }
  ASSERT_EQ(archive_write_open_filename(a, out.c_str()), ARCHIVE_OK) << archive_error_string(a);
  for (const Entry& e : entries) {
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, e.path.c_str());
    archive_entry_set_perm(entry, 0644);
    archive_entry_set_mtime(entry, 1700000000, 0);
    switch (e.type) {
      case Entry::Type::File:
        archive_entry_set_filetype(entry, AE_IFREG);
        archive_entry_set_size(entry, static_cast<la_int64_t>(e.data.size()));
        break;
      case Entry::Type::Dir:
        archive_entry_set_filetype(entry, AE_IFDIR);
        archive_entry_set_perm(entry, 0755);
        break;
      case Entry::Type::Symlink:
        archive_entry_set_filetype(entry, AE_IFLNK);
        archive_entry_set_symlink(entry, e.link.c_str());
        break;
      case Entry::Type::Hardlink:
        archive_entry_set_filetype(entry, AE_IFREG);
        archive_entry_set_hardlink(entry, e.link.c_str());
        archive_entry_set_size(entry, 0);
        break;
      case Entry::Type::CharDevice:
        archive_entry_set_filetype(entry, AE_IFCHR);
        archive_entry_set_rdevmajor(entry, 1);
        archive_entry_set_rdevminor(entry, 3);
        break;
      case Entry::Type::Fifo:
        archive_entry_set_filetype(entry, AE_IFIFO);
        break;
    }
    ASSERT_GE(archive_write_header(a, entry), ARCHIVE_WARN) << archive_error_string(a);
    if (e.type == Entry::Type::File && !e.data.empty()) {
      ASSERT_EQ(archive_write_data(a, e.data.data(), e.data.size()),
                static_cast<la_ssize_t>(e.data.size()));
    }
    archive_entry_free(entry);
  }
  ASSERT_EQ(archive_write_close(a), ARCHIVE_OK) << archive_error_string(a);
  archive_write_free(a);
}

std::string source(const std::string& file) {
  return "// " + file + "\n#include \"a6/spring.h\"\nint marker_" + std::to_string(file.size()) +
         " = 1;\n";
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeFile(const fs::path& p, const std::string& data) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << data;
}

std::string allNotes(const Intake& in) {
  std::string s;
  for (const std::string& n : in.notes) s += n + "\n";
  return s;
}

bool anyNoteHas(const Intake& in, const std::string& a, const std::string& b = "") {
  for (const std::string& n : in.notes) {
    if (n.find(a) != std::string::npos && n.find(b) != std::string::npos) return true;
  }
  return false;
}

double secondsOf(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

class Intake_ : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "a6-intake-XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    root = tmpl;
    dest = root / "out" / "work" / "src";
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  // Every task file taken is a copy inside dest with the expected content.
  void expectTaken(const Intake& in, const std::string& name, const std::string& content) {
    ASSERT_TRUE(in.files.count(name)) << name << " was not taken; notes:\n" << allNotes(in);
    EXPECT_EQ(in.files.at(name), dest / name);
    EXPECT_EQ(readAll(dest / name), content) << name;
  }
  fs::path root, dest;
};

std::vector<Entry> sixFiles(const std::string& prefix) {
  std::vector<Entry> out;
  for (const std::string& f : kTaskFiles) out.push_back(file(prefix + f, source(f)));
  return out;
}

// ---- the layouts a submission comes in ----

TEST_F(Intake_, FolderWithTheTaskFilesAtItsRootLikeGradescope) {
  const fs::path sub = root / "autograder" / "submission";
  for (const std::string& f : kTaskFiles) writeFile(sub / f, source(f));
  writeFile(sub / "README.md", "hello");
  writeFile(sub / "main.cpp", "int main() {}");
  const Intake in = takeSubmission(sub, dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_EQ(in.files.size(), kTaskFiles.size());
  for (const std::string& f : kTaskFiles) expectTaken(in, f, source(f));
  EXPECT_TRUE(in.notes.empty()) << allNotes(in);
  // Nothing but the task files is written.
  EXPECT_EQ(std::distance(fs::directory_iterator(dest), fs::directory_iterator()),
            static_cast<std::ptrdiff_t>(kTaskFiles.size()));
}

TEST_F(Intake_, ZipOfAFolderHoldingTheFiles) {
  auto entries = sixFiles("my_a6/src/");
  entries.insert(entries.begin(), Entry{"my_a6/", "", Entry::Type::Dir});
  entries.push_back(file("my_a6/build/CMakeCache.txt", "junk"));
  writeArchive(root / "sub.zip", Format::Zip, entries);
  const Intake in = takeSubmission(root / "sub.zip", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  for (const std::string& f : kTaskFiles) expectTaken(in, f, source(f));
}

TEST_F(Intake_, TarGzDetectedByContentNotByName) {
  writeArchive(root / "submission.bin", Format::TarGz, sixFiles("a6/"));
  const Intake in = takeSubmission(root / "submission.bin", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_EQ(in.files.size(), kTaskFiles.size());
  expectTaken(in, "cloth.cpp", source("cloth.cpp"));
}

TEST_F(Intake_, PlainTarAndWindowsSeparators) {
  writeArchive(root / "s.tar", Format::Tar,
               {file("proj\\spring.cpp", "A"), file("forces.cpp", "B")});
  const Intake in = takeSubmission(root / "s.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "spring.cpp", "A");
  expectTaken(in, "forces.cpp", "B");
}

TEST_F(Intake_, ASingleTaskFileOnItsOwn) {
  writeFile(root / "joints.cpp", source("joints.cpp"));
  const Intake in = takeSubmission(root / "joints.cpp", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_EQ(in.files.size(), 1u);
  expectTaken(in, "joints.cpp", source("joints.cpp"));
}

TEST_F(Intake_, OnlyTheTaskFilesAreTakenAndStaleCopiesAreRemoved) {
  writeFile(dest / "cloth.cpp", "left over from an earlier run");
  writeFile(dest / "spring.cpp", "left over from an earlier run");
  writeArchive(root / "s.zip", Format::Zip,
               {file("spring.cpp", "new"), file("notes.txt", "x"), file("cloth.h", "y")});
  const Intake in = takeSubmission(root / "s.zip", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_EQ(in.files.size(), 1u);
  expectTaken(in, "spring.cpp", "new");
  EXPECT_FALSE(fs::exists(dest / "cloth.cpp")) << "a stale cloth.cpp would be graded";
  EXPECT_FALSE(fs::exists(dest / "notes.txt"));
}

TEST_F(Intake_, TheShallowestCopyWinsAndTheOthersAreNoted) {
  writeArchive(root / "s.zip", Format::Zip,
               {file("a6/old/spring.cpp", "deepest"), file("a6/spring.cpp", "shallowest"),
                file("a6/backup/spring.cpp", "deeper"), file("b/forces.cpp", "b"),
                file("a/forces.cpp", "a")});
  const Intake in = takeSubmission(root / "s.zip", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "spring.cpp", "shallowest");
  // Same depth: the path that sorts first, whatever the archive's order.
  expectTaken(in, "forces.cpp", "a");
  EXPECT_TRUE(
      anyNoteHas(in, "spring.cpp: 3 copies found; took 'a6/spring.cpp'", "a6/old/spring.cpp"))
      << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "forces.cpp: 2 copies", "'b/forces.cpp'")) << allNotes(in);
}

TEST_F(Intake_, TheSamePathTwiceTakesTheLaterCopyLikeTarDoes) {
  // tar -rf appends a newer version under the same name; extracting leaves the last one.
  writeArchive(root / "s.tar", Format::Tar,
               {file("a6/spring.cpp", "v1"), file("a6/spring.cpp", "v2")});
  const Intake in = takeSubmission(root / "s.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "spring.cpp", "v2");
  EXPECT_FALSE(anyNoteHas(in, "copies found")) << allNotes(in);
}

TEST_F(Intake_, ABinaryTaskFileIsRefusedAndTheNextCopyTaken) {
  writeArchive(
      root / "s.zip", Format::Zip,
      {file("spring.cpp", std::string("int x;\0\0\0binary", 16)), file("v2/spring.cpp", "good")});
  const Intake in = takeSubmission(root / "s.zip", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "spring.cpp", "good");
  EXPECT_TRUE(anyNoteHas(in, "'spring.cpp': refused", "NUL")) << allNotes(in);
}

TEST_F(Intake_, NonUtf8TextIsTakenWithANote) {
  const std::string latin1 = "// caf\xe9\nint x;\n";
  writeArchive(root / "s.tar", Format::Tar, {file("cloth.cpp", latin1)});
  const Intake in = takeSubmission(root / "s.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "cloth.cpp", latin1);
  EXPECT_TRUE(anyNoteHas(in, "cloth.cpp", "UTF-8")) << allNotes(in);
}

TEST_F(Intake_, NearMissNamesAndNestedArchivesAreNoted) {
  writeArchive(root / "s.zip", Format::Zip,
               {file("Spring.cpp", "x"), file("inner/submission.zip", "PK...")});
  const Intake in = takeSubmission(root / "s.zip", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_TRUE(in.files.empty());
  EXPECT_TRUE(anyNoteHas(in, "'Spring.cpp'", "exactly 'spring.cpp'")) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'inner/submission.zip'", "nested archive, not opened"))
      << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "no task file was found", "not opened")) << allNotes(in);
}

// ---- hostile archives ----

TEST_F(Intake_, DotDotPathsAreRefusedAndNothingIsWrittenOutsideDest) {
  writeArchive(root / "s.tar", Format::Tar,
               {file("../../evil/spring.cpp", "evil"), file("a/../../../evil/forces.cpp", "evil"),
                file("joints.cpp", "fine")});
  const Intake in = takeSubmission(root / "s.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_EQ(in.files.size(), 1u);
  expectTaken(in, "joints.cpp", "fine");
  EXPECT_TRUE(anyNoteHas(in, "'../../evil/spring.cpp': refused", "'..'")) << allNotes(in);
  for (const fs::path& base : {dest, dest.parent_path(), fs::current_path(), root}) {
    EXPECT_FALSE(fs::exists(base / "../../evil/spring.cpp")) << base;
    EXPECT_FALSE(fs::exists(base / "../../evil/forces.cpp")) << base;
  }
  EXPECT_FALSE(fs::exists(dest / "spring.cpp"));
}

TEST_F(Intake_, AbsolutePathsAreRefused) {
  const fs::path target = "/tmp/a6-intake-abs-" + std::to_string(::getpid()) + "/spring.cpp";
  writeArchive(root / "s.tar", Format::Tar, {file(target.string(), "evil")});
  const Intake in = takeSubmission(root / "s.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_TRUE(in.files.empty());
  EXPECT_TRUE(anyNoteHas(in, target.string(), "absolute path")) << allNotes(in);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_FALSE(fs::exists(target.parent_path()));
  EXPECT_FALSE(fs::exists(dest / "spring.cpp"));
}

TEST_F(Intake_, ASymlinkEntryIsNeverFollowed) {
  for (Format format : {Format::Zip, Format::TarGz}) {
    writeArchive(root / "s.arc", format,
                 {Entry{"spring.cpp", "", Entry::Type::Symlink, "/etc/passwd"},
                  Entry{"src", "", Entry::Type::Symlink, "/etc"}, file("src/forces.cpp", "f")});
    const Intake in = takeSubmission(root / "s.arc", dest);
    ASSERT_TRUE(in.ok()) << in.error;
    EXPECT_FALSE(in.files.count("spring.cpp"));
    EXPECT_FALSE(fs::exists(dest / "spring.cpp"));
    EXPECT_TRUE(anyNoteHas(in, "'spring.cpp': refused: a symbolic link to '/etc/passwd'"))
        << allNotes(in);
    // A file "under" a link entry is just a path in the archive: read from the archive.
    expectTaken(in, "forces.cpp", "f");
    fs::remove(root / "s.arc");
  }
}

TEST_F(Intake_, HardlinksDevicesAndFifosAreRefused) {
  writeArchive(
      root / "s.tar", Format::Tar,
      {file("notes.txt", "innocent"), Entry{"spring.cpp", "", Entry::Type::Hardlink, "notes.txt"},
       Entry{"forces.cpp", "", Entry::Type::CharDevice},
       Entry{"cloth.cpp", "", Entry::Type::Fifo}});
  const Intake in = takeSubmission(root / "s.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_TRUE(in.files.empty()) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'spring.cpp': refused: a hard link")) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'forces.cpp': refused: a device file")) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'cloth.cpp': refused: a named pipe")) << allNotes(in);
  EXPECT_TRUE(fs::is_empty(dest));
}

TEST_F(Intake_, AnOversizedTaskFileIsRefusedFast) {
  const std::string zeros(8u << 20, '\0');  // deflates to a few KiB: a small bomb
  writeArchive(root / "bomb.zip", Format::Zip,
               {file("spring.cpp", zeros), file("forces.cpp", "ok")});
  Intake in;
  const double s = secondsOf([&] { in = takeSubmission(root / "bomb.zip", dest); });
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_LT(s, 2.0);
  EXPECT_FALSE(in.files.count("spring.cpp"));
  expectTaken(in, "forces.cpp", "ok");
  EXPECT_TRUE(anyNoteHas(in, "'spring.cpp': refused: 8.0 MiB", "1.0 MiB limit")) << allNotes(in);
}

TEST_F(Intake_, ATarballStopsAtTheDataLimit) {
  writeArchive(root / "bomb.tgz", Format::TarGz,
               {file("big.bin", std::string(16u << 20, 'x')), file("spring.cpp", "late")});
  IntakeLimits limits;
  limits.maxTotalBytes = 1u << 20;
  Intake in;
  const double s = secondsOf([&] { in = takeSubmission(root / "bomb.tgz", dest, limits); });
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_LT(s, 2.0);
  EXPECT_TRUE(in.files.empty());
  EXPECT_TRUE(anyNoteHas(in, "'big.bin' holds 16.0 MiB: reading stopped there")) << allNotes(in);
}

TEST_F(Intake_, TooManyEntriesStopReadingFast) {
  std::vector<Entry> entries;
  for (int i = 0; i < 20000; ++i) entries.push_back(file("junk/" + std::to_string(i), ""));
  entries.push_back(file("spring.cpp", "after the limit"));
  writeArchive(root / "many.tar", Format::Tar, entries);
  Intake in;
  const double s = secondsOf([&] { in = takeSubmission(root / "many.tar", dest); });
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_LT(s, 2.0);
  EXPECT_TRUE(in.files.empty());
  EXPECT_TRUE(anyNoteHas(in, "reading stopped after 10000 entries")) << allNotes(in);
}

TEST_F(Intake_, PathsDeeperThanTheLimitAreSkipped) {
  std::string deep;
  for (int i = 0; i < 40; ++i) deep += "d/";
  writeArchive(root / "deep.tar", Format::Tar,
               {file(deep + "spring.cpp", "deep"), file("ok/forces.cpp", "ok")});
  const Intake in = takeSubmission(root / "deep.tar", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_FALSE(in.files.count("spring.cpp"));
  expectTaken(in, "forces.cpp", "ok");
  EXPECT_TRUE(anyNoteHas(in, "41 levels deep, over the limit of 32")) << allNotes(in);
}

TEST_F(Intake_, RandomBytesAfterAZipHeaderGiveAClearError) {
  std::string junk = "PK\x03\x04";
  std::mt19937 rng(7);
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>(rng() & 0xff);
  writeFile(root / "corrupt.zip", junk);
  const Intake in = takeSubmission(root / "corrupt.zip", dest);
  EXPECT_FALSE(in.ok());
  EXPECT_NE(in.error.find("corrupt.zip"), std::string::npos) << in.error;
  EXPECT_TRUE(in.files.empty());
}

TEST_F(Intake_, ATruncatedTarGzGivesAClearError) {
  std::string text;
  std::mt19937 rng(3);
  for (int i = 0; i < 200000; ++i) text += static_cast<char>('a' + rng() % 26);
  writeArchive(root / "t.tar.gz", Format::TarGz, {file("spring.cpp", text)});
  const std::string whole = readAll(root / "t.tar.gz");
  writeFile(root / "t.tar.gz", whole.substr(0, whole.size() / 2));
  const Intake in = takeSubmission(root / "t.tar.gz", dest);
  EXPECT_FALSE(in.ok());
  EXPECT_NE(in.error.find("damaged"), std::string::npos) << in.error;
  EXPECT_FALSE(fs::exists(dest / "spring.cpp"));
}

TEST_F(Intake_, ATarGzTruncatedAfterATaskFileKeepsItWithANote) {
  std::string text;
  std::mt19937 rng(5);
  for (int i = 0; i < 200000; ++i) text += static_cast<char>('a' + rng() % 26);
  writeArchive(root / "t.tgz", Format::TarGz, {file("spring.cpp", "early"), file("x.bin", text)});
  const std::string whole = readAll(root / "t.tgz");
  writeFile(root / "t.tgz", whole.substr(0, whole.size() / 2));
  const Intake in = takeSubmission(root / "t.tgz", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "spring.cpp", "early");
  EXPECT_TRUE(anyNoteHas(in, "damaged", "only the task files read before")) << allNotes(in);
}

TEST_F(Intake_, EmptyArchivesGiveNoFilesAndANote) {
  writeArchive(root / "empty.zip", Format::Zip, {});
  writeFile(root / "zero.zip", "");
  for (const char* name : {"empty.zip", "zero.zip"}) {
    const Intake in = takeSubmission(root / name, dest);
    ASSERT_TRUE(in.ok()) << name << ": " << in.error;
    EXPECT_TRUE(in.files.empty());
    EXPECT_TRUE(anyNoteHas(in, "is empty")) << name << ": " << allNotes(in);
  }
}

TEST_F(Intake_, AMissingOrUnreadableSubmissionGivesAClearError) {
  const Intake missing = takeSubmission(root / "nope.zip", dest);
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.error.find("does not exist"), std::string::npos) << missing.error;
  writeFile(root / "notes.txt", "just some text, not an archive\n");
  const Intake text = takeSubmission(root / "notes.txt", dest);
  EXPECT_FALSE(text.ok());
  EXPECT_NE(text.error.find("neither a folder nor a zip or tar archive"), std::string::npos)
      << text.error;
}

// ---- hostile folders ----

TEST_F(Intake_, FolderLinksAreNeverFollowed) {
  const fs::path sub = root / "sub";
  const fs::path outside = root / "outside";
  writeFile(outside / "forces.cpp", "outside");
  writeFile(sub / "cloth.cpp", "inside");
  fs::create_directories(sub);
  fs::create_symlink("/etc/passwd", sub / "spring.cpp");
  fs::create_directory_symlink(outside, sub / "linked_dir");
  ASSERT_EQ(::mkfifo((sub / "joints.cpp").c_str(), 0644), 0);
  const Intake in = takeSubmission(sub, dest);
  ASSERT_TRUE(in.ok()) << in.error;
  expectTaken(in, "cloth.cpp", "inside");
  EXPECT_EQ(in.files.size(), 1u) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'spring.cpp': refused: a symbolic link to '/etc/passwd'"))
      << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'linked_dir': refused: a symbolic link")) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'joints.cpp': refused: a named pipe")) << allNotes(in);
}

TEST_F(Intake_, FolderDepthAndSizeLimits) {
  const fs::path sub = root / "sub";
  fs::path deep = sub;
  for (int i = 0; i < 40; ++i) deep /= "d";
  writeFile(deep / "spring.cpp", "deep");
  writeFile(sub / "forces.cpp", std::string(2u << 20, 'x'));
  writeFile(sub / "v2" / "forces.cpp", "small");
  const Intake in = takeSubmission(sub, dest);
  ASSERT_TRUE(in.ok()) << in.error;
  EXPECT_FALSE(in.files.count("spring.cpp"));
  expectTaken(in, "forces.cpp", "small");
  EXPECT_TRUE(anyNoteHas(in, "not looked into: 32 levels deep")) << allNotes(in);
  EXPECT_TRUE(anyNoteHas(in, "'forces.cpp': refused: 2.0 MiB")) << allNotes(in);
}

TEST_F(Intake_, FilesAreWrittenReadableForTheSandboxUser) {
  writeArchive(root / "s.zip", Format::Zip, {file("spring.cpp", "x")});
  const Intake in = takeSubmission(root / "s.zip", dest);
  ASSERT_TRUE(in.ok()) << in.error;
  struct stat st {};
  ASSERT_EQ(::stat((dest / "spring.cpp").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
  ASSERT_EQ(::stat(dest.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0755u);
}

}  // namespace
