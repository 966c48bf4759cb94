// Building a submission's probe (grader/build/build.*): each file alone, in the sandbox, against
// the kit; a broken, missing, hostile or slow file costs its own task only.
#include "build/build.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "intake/intake.h"
#include "sandbox_user.h"

namespace fs = std::filesystem;
using namespace a6::grader;
using Status = TaskBuild::Status;

namespace {

const fs::path kRepo = A6_SOURCE_DIR;

// The kit of this build tree (A6_TEST_KIT overrides it, to try another kit by hand).
fs::path kitPath() {
  const char* env = std::getenv("A6_TEST_KIT");
  return env != nullptr ? fs::path(env) : defaultKitPath();
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeFile(const fs::path& p, const std::string& data) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << data;
}

const char* statusName(Status s) {
  switch (s) {
    case Status::Compiled:
      return "Compiled";
    case Status::Missing:
      return "Missing";
    case Status::CompileError:
      return "CompileError";
    case Status::TimedOut:
      return "TimedOut";
    case Status::LinkError:
      return "LinkError";
  }
  return "?";
}

std::string describe(const Build& b) {
  std::string s = "build error: " + (b.error.empty() ? std::string("(none)") : b.error) + "\n";
  for (const TaskBuild& t : b.tasks) {
    s += "  " + t.file + ": " + statusName(t.status) + "\n";
    if (!t.messages.empty()) s += t.messages + "\n";
  }
  return s;
}

class BuildProbe : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    kit_ = new Kit(loadKit(kitPath()));
    kit_->uid = a6::test::sandboxUid();  // ours alone: other tests compile beside us
  }
  static void TearDownTestSuite() {
    delete kit_;
    kit_ = nullptr;
  }
  void SetUp() override {
    ASSERT_TRUE(kit_->ok()) << kit_->error;
    std::string tmpl = (fs::temp_directory_path() / "a6-build-XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    root_ = tmpl;
    // The sandbox may compile as another user: it must reach the work folder.
    fs::permissions(root_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                               fs::perms::others_read | fs::perms::others_exec);
    submission_ = root_ / "submission";
    fs::create_directories(submission_);
    for (const std::string& f : kTaskFiles) fs::copy_file(kRepo / "solution" / f, submission_ / f);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  Build build(const Limits& limits = defaultCompileLimits()) { return buildIn("work", limits); }
  // A build in root_/`work`.
  Build buildIn(const std::string& work, const Limits& limits = defaultCompileLimits()) {
    const Intake in = takeSubmission(submission_, root_ / work / "src");
    EXPECT_TRUE(in.ok()) << in.error;
    Build b = buildProbe(*kit_, in, root_ / work / "build", limits, 2, kDefaultBuildBudget);
    if (std::getenv("A6_TEST_VERBOSE") != nullptr) std::cout << describe(b);
    return b;
  }
  const TaskBuild& task(const Build& b, const std::string& file) {
    for (const TaskBuild& t : b.tasks) {
      if (t.file == file) return t;
    }
    throw std::runtime_error("no task " + file);
  }
  // The probe linked, and every task but `except` compiled.
  void expectLinkedWithOthersCompiled(const Build& b, const std::string& except) {
    ASSERT_TRUE(b.ok()) << describe(b);
    EXPECT_EQ(::access(b.probe.c_str(), X_OK), 0) << b.probe;
    ASSERT_EQ(b.tasks.size(), kTaskFiles.size());
    for (const TaskBuild& t : b.tasks) {
      if (t.file != except) {
        EXPECT_EQ(t.status, Status::Compiled) << t.file << "\n" << describe(b);
      }
    }
  }

  // Submits `file` alone: the other tasks link the starter's objects, so no honest compile runs
  // under a test's short time limit (on a loaded machine one could pass it by chance).
  void submitOnly(const std::string& file, const std::string& text) {
    for (const std::string& f : kTaskFiles) fs::remove(submission_ / f);
    writeFile(submission_ / file, text);
  }
  // The probe linked, `file` failed within `limitSeconds` (and the few seconds a kill and the
  // sandbox's start may take), and every other task kept the starter's stub.
  void expectStoppedAndLinked(const Build& b, const std::string& file, double limitSeconds) {
    ASSERT_TRUE(b.ok()) << describe(b);
    EXPECT_EQ(::access(b.probe.c_str(), X_OK), 0) << b.probe;
    EXPECT_LT(task(b, file).seconds, limitSeconds + 10) << describe(b);
    for (const TaskBuild& t : b.tasks) {
      if (t.file != file) {
        EXPECT_EQ(t.status, Status::Missing) << t.file << "\n" << describe(b);
      }
    }
  }

  static Kit* kit_;
  fs::path root_, submission_;
};
Kit* BuildProbe::kit_ = nullptr;

TEST(Kit, StagesOnlyTheStudentApiHeaders) {
  const Kit kit = loadKit(kitPath());
  ASSERT_TRUE(kit.ok()) << kit.error;
  int headers = 0;
  for (const auto& e : fs::recursive_directory_iterator(kit.dir / "include")) {
    if (e.is_directory()) {
      EXPECT_EQ(e.path(), kit.dir / "include" / "a6");
      continue;
    }
    EXPECT_EQ(e.path().parent_path(), kit.dir / "include" / "a6") << e.path();
    EXPECT_EQ(e.path().extension(), ".h") << e.path();
    ++headers;
  }
  EXPECT_GE(headers, 6);
  for (const std::string& f : kTaskFiles) {
    const std::string stem = fs::path(f).stem().string();
    EXPECT_TRUE(fs::is_regular_file(kit.starterObjects / (stem + ".o"))) << stem;
    EXPECT_FALSE(readAll(kit.starterObjects / (stem + ".syms")).empty()) << stem;
  }
  EXPECT_FALSE(kit.secrets.empty());
}

TEST(Kit, ThePrecompiledHeaderIsUsed) {
  const Kit kit = loadKit(kitPath());
  ASSERT_TRUE(kit.ok()) << kit.error;
  char tmpl[] = "/tmp/a6-pch-XXXXXX.cpp";
  const int fd = ::mkstemps(tmpl, 4);
  ASSERT_GE(fd, 0);
  ::close(fd);
  writeFile(tmpl, "#include \"a6/spring.h\"\n");
  // -H lists the headers read; "! x.gch" is a precompiled header used, "x x.gch" one refused.
  std::string command = kit.compiler;
  for (const std::string& f : kit.compileFlags) command += " '" + f + "'";
  command += " -H -fsyntax-only " + std::string(tmpl) + " 2>&1";
  std::string out;
  if (FILE* p = ::popen(command.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    EXPECT_EQ(::pclose(p), 0) << out;
  }
  fs::remove(tmpl);
  EXPECT_NE(out.find("! " + (kit.dir / "pch" / "a6_pch.h.gch").string()), std::string::npos)
      << "the kit's precompiled header was not used (compiles take four times longer):\n"
      << out.substr(0, 4000);
}

TEST(Kit, AMissingOrMalformedKitSaysWhatToDo) {
  const Kit missing = loadKit("/nonexistent/kit.json");
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.error.find("/nonexistent/kit.json"), std::string::npos) << missing.error;
  EXPECT_NE(missing.error.find("a6_grader_kit"), std::string::npos) << missing.error;
  char tmpl[] = "/tmp/a6-kit-XXXXXX";
  const int fd = ::mkstemp(tmpl);
  ASSERT_GE(fd, 0);
  ::close(fd);
  writeFile(tmpl, "{\"compiler\": 3}");
  const Kit bad = loadKit(tmpl);
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.error.find("malformed"), std::string::npos) << bad.error;
  fs::remove(tmpl);
  Build b = buildProbe(bad, Intake{}, "/tmp/unused");
  EXPECT_FALSE(b.ok());
}

TEST_F(BuildProbe, TheSolutionBuildsAndLinksIntoAProbe) {
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "");
  double compile = 0;
  for (const TaskBuild& t : b.tasks) compile += t.seconds;
  std::cout << "[ timing ] 2 jobs: seven files compiled in " << compile << " s (CPU-side sum), "
            << "linked in " << b.linkSeconds << " s, " << b.seconds << " s in all\n";
  RecordProperty("build_seconds", std::to_string(b.seconds));
  // One at a time (Gradescope's half a vCPU gains nothing from two).
  const Intake in = takeSubmission(submission_, root_ / "work1" / "src");
  const Build one = buildProbe(*kit_, in, root_ / "work1" / "build", defaultCompileLimits(), 1);
  expectLinkedWithOthersCompiled(one, "");
  std::cout << "[ timing ] 1 job: " << one.seconds << " s in all; per file:";
  double oneByOne = 0;
  for (const TaskBuild& t : one.tasks) {
    std::cout << " " << t.file << " " << t.seconds;
    oneByOne += t.seconds;
  }
  std::cout << "\n";
  // --jobs 1 is honoured: one compile at a time, so the compiles' times add up to no more than
  // the build's (two at once would add up to more, however loaded the machine).
  EXPECT_LE(oneByOne, one.seconds - one.linkSeconds + 0.05) << describe(one);
}

TEST_F(BuildProbe, ACompileErrorCostsOnlyItsTask) {
  writeFile(submission_ / "cloth.cpp",
            "#include \"a6/cloth.h\"\n\nint broken() { return undeclared_name; }\n");
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "cloth.cpp");
  const TaskBuild& t = task(b, "cloth.cpp");
  EXPECT_EQ(t.status, Status::CompileError) << describe(b);
  EXPECT_TRUE(t.usesStarter());
  // The compiler's own words, naming the file as the student knows it.
  EXPECT_NE(t.messages.find("cloth.cpp:3:"), std::string::npos) << t.messages;
  EXPECT_NE(t.messages.find("undeclared_name"), std::string::npos) << t.messages;
  EXPECT_EQ(t.messages.find(root_.string()), std::string::npos) << t.messages;
}

TEST_F(BuildProbe, WarningsReachTheStudent) {
  writeFile(submission_ / "spring.cpp",
            readAll(kRepo / "solution" / "spring.cpp") +
                "\nnamespace { int unusedHelper(int x) { int y; return x; } }\n");
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "");
  EXPECT_NE(task(b, "spring.cpp").messages.find("warning"), std::string::npos)
      << task(b, "spring.cpp").messages;
}

TEST_F(BuildProbe, AMissingFileUsesTheStarter) {
  fs::remove(submission_ / "joints.cpp");
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "joints.cpp");
  EXPECT_EQ(task(b, "joints.cpp").status, Status::Missing);
  EXPECT_NE(task(b, "joints.cpp").messages.find("starter"), std::string::npos);
}

TEST_F(BuildProbe, NothingSubmittedStillLinksTheStarter) {
  for (const std::string& f : kTaskFiles) fs::remove(submission_ / f);
  const Build b = build();
  ASSERT_TRUE(b.ok()) << describe(b);
  for (const TaskBuild& t : b.tasks) EXPECT_EQ(t.status, Status::Missing) << t.file;
  EXPECT_EQ(::access(b.probe.c_str(), X_OK), 0);
}

TEST_F(BuildProbe, TheSolutionIsHiddenFromTheCompiler) {
  if (::geteuid() != 0) GTEST_SKIP() << "hiding paths needs root (mount namespaces)";
  const fs::path solution = kRepo / "solution" / "spring.cpp";
  const fs::path src = root_ / "work" / "src";
  const std::string includes[] = {
      solution.string(), solution.lexically_relative(src).string(),
      "/proc/" + std::to_string(::getpid()) + "/root" + solution.string(),
      "/proc/1/root" + solution.string(), "a6/../../../../solution/spring.cpp"};
  std::vector<std::string> sources;
  for (const std::string& inc : includes) sources.push_back("#include \"" + inc + "\"\n");
  // The assembler reads files too.
  sources.push_back("asm(\".incbin \\\"" + solution.string() + "\\\"\");\n");
  for (const std::string& text : sources) {
    const std::string& inc = text;
    writeFile(submission_ / "spring.cpp", text);
    const Build b = build();
    const TaskBuild& t = task(b, "spring.cpp");
    EXPECT_NE(t.status, Status::Compiled) << inc << " compiled\n" << describe(b);
    EXPECT_EQ(t.messages.find("restLength"), std::string::npos)
        << "the solution leaked into the messages:\n"
        << t.messages;
    expectLinkedWithOthersCompiled(b, "spring.cpp");
  }
}

TEST_F(BuildProbe, AWorkFolderInsideTheBuildTreeWorksAndStillHidesTheRest) {
  // The build tree is one of the kit's secrets: only the work folder's own path is kept.
  const fs::path buildTree = kit_->dir.parent_path().parent_path();
  std::string tmpl = (buildTree / "tests" / "grader" / "a6-build-inside-XXXXXX").string();
  fs::create_directories(fs::path(tmpl).parent_path());
  ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
  const fs::path inside = tmpl;
  fs::permissions(inside, fs::perms::owner_all | fs::perms::others_read | fs::perms::others_exec |
                              fs::perms::group_read | fs::perms::group_exec);
  // A hidden file reads as empty (it is covered by /dev/null), a file in a hidden folder is
  // not there at all.
  writeFile(submission_ / "forces.cpp",
            "#include \"" + (buildTree / "CMakeCache.txt").string() + "\"\n");
  writeFile(submission_ / "cloth.cpp",
            "#include \"" + (kRepo / "solution" / "cloth.cpp").string() + "\"\n");
  const Intake in = takeSubmission(submission_, inside / "src");
  const Build b = buildProbe(*kit_, in, inside / "build");
  ASSERT_TRUE(b.ok()) << describe(b);
  EXPECT_EQ(::access(b.probe.c_str(), X_OK), 0) << b.probe;
  for (const char* f : {"spring.cpp", "time_stepping.cpp", "particle_system.cpp"}) {
    EXPECT_EQ(task(b, f).status, Status::Compiled) << describe(b);
  }
  if (::geteuid() == 0) {
    EXPECT_NE(task(b, "forces.cpp").status, Status::Compiled) << describe(b);
    EXPECT_EQ(task(b, "forces.cpp").messages.find("CMAKE_"), std::string::npos) << describe(b);
    EXPECT_EQ(task(b, "cloth.cpp").status, Status::CompileError) << describe(b);
  }
  std::error_code ec;
  fs::remove_all(inside, ec);
}

TEST_F(BuildProbe, AFileDefiningMainIsIsolatedAtLink) {
  writeFile(submission_ / "time_stepping.cpp",
            readAll(kRepo / "solution" / "time_stepping.cpp") + "\nint main() { return 0; }\n");
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "time_stepping.cpp");
  const TaskBuild& t = task(b, "time_stepping.cpp");
  EXPECT_EQ(t.status, Status::LinkError) << describe(b);
  EXPECT_NE(t.messages.find("main"), std::string::npos) << t.messages;
}

TEST_F(BuildProbe, AFileRedefiningAFrameworkSymbolIsIsolatedAtLink) {
  writeFile(submission_ / "particle_system.cpp",
            readAll(kRepo / "solution" / "particle_system.cpp") +
                "\nnamespace a6 { double Random::uniform() { return 0.5; } }\n");
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "particle_system.cpp");
  EXPECT_EQ(task(b, "particle_system.cpp").status, Status::LinkError) << describe(b);
}

TEST_F(BuildProbe, ARenamedFunctionIsIsolatedAtLink) {
  // spring.cpp no longer defines Spring::computeForce: the framework's call is undefined.
  writeFile(submission_ / "spring.cpp",
            "#include \"a6/spring.h\"\n"
            "namespace a6 {\n"
            "Vec2 computeSpringForce(const Spring& s) { return s.p2->x - s.p1->x; }\n"
            "}\n");
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "spring.cpp");
  EXPECT_EQ(task(b, "spring.cpp").status, Status::LinkError) << describe(b);
  EXPECT_NE(task(b, "spring.cpp").messages.find("computeForce"), std::string::npos) << describe(b);
}

TEST_F(BuildProbe, TwoFilesClashingCostOneTask) {
  const std::string helper = "\ndouble sharedHelper(double x) { return x; }\n";
  writeFile(submission_ / "forces.cpp", readAll(kRepo / "solution" / "forces.cpp") + helper);
  writeFile(submission_ / "cloth.cpp", readAll(kRepo / "solution" / "cloth.cpp") + helper);
  const Build b = build();
  ASSERT_TRUE(b.ok()) << describe(b);
  int linkErrors = 0;
  for (const TaskBuild& t : b.tasks) linkErrors += t.status == Status::LinkError;
  EXPECT_EQ(linkErrors, 1) << describe(b);
}

// Two probes from the same objects: the one that serves every request, and the one with the
// reference force models for tasks 3 and 5. Both stripped: no symbol table to search.
TEST_F(BuildProbe, BothProbesAreLinkedAndStripped) {
  const Build b = build();
  expectLinkedWithOthersCompiled(b, "");
  for (const fs::path& probe : {b.probe, b.modelsProbe}) {
    EXPECT_EQ(::access(probe.c_str(), X_OK), 0) << probe;
    std::ifstream in(probe, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_GT(bytes.size(), 1000u);
    EXPECT_EQ(bytes.find(std::string(".symtab\0", 8)), std::string::npos)
        << probe << " is not stripped";
  }
}

// The whole build has a time budget: slow files after it is used up are not compiled at all.
TEST_F(BuildProbe, TheWholeBuildStaysWithinItsBudget) {
  std::string slow =
      "constexpr long spin(long k) { long s = 0; for (long i = 0; i < 2000; ++i)"
      " for (long j = 0; j < 2000; ++j) s += i ^ j ^ k; return s; }\n";
  for (int i = 0; i < 200; ++i) {
    slow += "constexpr long c" + std::to_string(i) + " = spin(" + std::to_string(i) + ");\n";
  }
  for (const char* file : {"spring.cpp", "forces.cpp", "cloth.cpp", "joints.cpp"}) {
    writeFile(submission_ / file, slow);
  }
  const Intake in = takeSubmission(submission_, root_ / "work" / "src");
  const auto t0 = std::chrono::steady_clock::now();
  const Build b = buildProbe(*kit_, in, root_ / "work" / "build", defaultCompileLimits(), 1, 6);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(b.ok()) << describe(b);
  int unbuilt = 0;
  for (const char* file : {"spring.cpp", "forces.cpp", "cloth.cpp", "joints.cpp"}) {
    EXPECT_EQ(task(b, file).status, Status::TimedOut) << describe(b);
    if (task(b, file).messages.find("time budget") != std::string::npos) ++unbuilt;
  }
  EXPECT_GE(unbuilt, 2) << "files never compiled once the budget was used up\n" << describe(b);
  EXPECT_LT(s, 60.0) << "a 6 s budget, the link and the two other files";
}

TEST_F(BuildProbe, ACompileThatNeverEndsTimesOut) {
  // Each constant costs the compiler about a second (4M loop iterations, under GCC's limits on
  // constexpr evaluation); two hundred of them, minutes.
  std::string text =
      "constexpr long spin(long k) { long s = 0; for (long i = 0; i < 2000; ++i)"
      " for (long j = 0; j < 2000; ++j) s += i ^ j ^ k; return s; }\n";
  for (int i = 0; i < 200; ++i) {
    text += "constexpr long c" + std::to_string(i) + " = spin(" + std::to_string(i) + ");\n";
  }
  submitOnly("forces.cpp", text);
  Limits limits = defaultCompileLimits();
  limits.wallSeconds = 3;
  const Build b = build(limits);
  EXPECT_EQ(task(b, "forces.cpp").status, Status::TimedOut) << describe(b);
  EXPECT_GE(task(b, "forces.cpp").seconds, limits.wallSeconds - 0.1) << "killed by its time limit";
  expectStoppedAndLinked(b, "forces.cpp", limits.wallSeconds);
}

TEST_F(BuildProbe, RunawayCompilesFailWithinTheLimits) {
  const std::string sources[] = {
      // Without a base case: GCC stops at its instantiation depth.
      "template <int N, int M> struct F { static constexpr long v = F<N - 1, 2 * M>::v + "
      "F<N - 1, 2 * M + 1>::v; };\nlong x = F<60, 0>::v;\n",
      // With one: 2^40 distinct instantiations, until time or memory runs out.
      "template <int N, long M> struct F { static constexpr long v = F<N - 1, 2 * M>::v + "
      "F<N - 1, 2 * M + 1>::v; };\ntemplate <long M> struct F<0, M> { static constexpr long v = "
      "M; };\nlong x = F<40, 0>::v;\n",
      // An endless file.
      "#include \"/dev/zero\"\n",
      // A device that blocks: not there for the compiler.
      "#include \"/dev/ptmx\"\n", "#include \"/dev/tty\"\n"};
  Limits limits = defaultCompileLimits();
  limits.wallSeconds = 5;
  for (const std::string& text : sources) {
    submitOnly("cloth.cpp", text);
    const Build b = build(limits);
    const TaskBuild& t = task(b, "cloth.cpp");
    EXPECT_TRUE(t.status == Status::TimedOut || t.status == Status::CompileError) << describe(b);
    expectStoppedAndLinked(b, "cloth.cpp", limits.wallSeconds);
  }
}

// Nothing compiled from a submission is shared with another grading: a file equal byte for
// byte to the solution's gets the kit's known object (compiled by the grader's own build), any
// other text is compiled in its own grading, every time.
TEST_F(BuildProbe, OnlyTheKitsOwnTextsAreNotCompiled) {
  if (kit_->knownObjects.empty()) GTEST_SKIP() << "no solution in this build: no known objects";
  const Build solution = buildIn("solution");
  expectLinkedWithOthersCompiled(solution, "");
  for (const TaskBuild& t : solution.tasks) EXPECT_TRUE(t.known) << t.file;
  writeFile(submission_ / "forces.cpp",
            readAll(kRepo / "solution" / "forces.cpp") + "\n// changed\n");
  for (const std::string work : {"first", "second"}) {
    const Build b = buildIn(work);
    expectLinkedWithOthersCompiled(b, "");
    for (const TaskBuild& t : b.tasks) EXPECT_EQ(t.known, t.file != "forces.cpp") << t.file;
    EXPECT_EQ(task(b, "forces.cpp").object.string().rfind((root_ / work).string(), 0), 0u)
        << "compiled in this grading's own folder";
  }
}

// A compile sees no other task file, nor the kit's known objects (the solution's texts).
TEST_F(BuildProbe, ACompileSeesNoOtherTaskFileNorTheKnownObjects) {
  if (::geteuid() != 0) GTEST_SKIP() << "hiding paths needs root (mount namespaces)";
  submitOnly("spring.cpp",
             "#define A6_SIBLING_SEEN 1\n" + readAll(kRepo / "solution" / "spring.cpp"));
  // A hidden file reads as empty: forces.cpp compiles, without spring.cpp's text.
  writeFile(submission_ / "forces.cpp",
            "#include \"spring.cpp\"\n#ifdef A6_SIBLING_SEEN\n#error the compile saw spring.cpp\n"
            "#endif\n" +
                readAll(kRepo / "solution" / "forces.cpp"));
  const fs::path known =
      kit_->knownObjects.empty() ? kit_->dir.parent_path() / "known" : kit_->knownObjects;
  writeFile(submission_ / "cloth.cpp", "#include \"" + (known / "cloth.cpp").string() + "\"\n");
  const Build b = buildIn("work");
  ASSERT_TRUE(b.ok()) << describe(b);
  EXPECT_EQ(task(b, "spring.cpp").status, Status::Compiled) << describe(b);
  EXPECT_EQ(task(b, "forces.cpp").status, Status::Compiled) << describe(b);
  EXPECT_EQ(task(b, "cloth.cpp").status, Status::CompileError) << describe(b);
  EXPECT_NE(task(b, "cloth.cpp").messages.find("No such file"), std::string::npos) << describe(b);
}

}  // namespace
