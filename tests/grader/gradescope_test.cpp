// The Gradescope autograder zip (scripts/gradescope-package.sh), built and run as Gradescope runs
// it (shared/reference/gradescope.md): the zip is unpacked into a fake /autograder, setup.sh
// builds the grader there from scratch (apt skipped: the packages are installed here), then
// run_autograder grades submissions into results/results.json, which must always be valid.
//
// The cases share one package and one build, so they run in order, in one process (one ctest
// entry, gradescope_package); each prints how long it took, and the last the total.
//
// Also checked: nothing of solution/ is in the zip, by path or by content (no line of a solution
// file that the starter does not have), and student code runs as a sandbox user and cannot read the
// grader's files, with and without the mount namespace Docker may refuse (Gradescope's
// containers): setup.sh's file permissions must then protect them.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "harness/tasks.h"
#include "rubric/rubric.h"
#include "run_command.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

using a6::kTaskFiles;  // harness/tasks.h

using Outcome = a6::test::CommandRun;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
std::string quote(const fs::path& p) { return quote(p.string()); }

Outcome run(const std::string& command) { return a6::test::runCommand(command); }

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string tail(const std::string& text, std::size_t chars = 6000) {
  return text.size() <= chars ? text : "...\n" + text.substr(text.size() - chars);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// What the cases share: the zip, the fake /autograder it is unpacked and built in.
struct Package {
  fs::path dir;   // a fresh folder under /tmp (nobody must be able to enter it)
  fs::path zip;   // dir/a6_autograder.zip
  fs::path root;  // dir/autograder: source/, submission/, results/, submission_metadata.json
  bool unpacked = false;
  bool built = false;
  Clock::time_point start = Clock::now();
};

Package& package() {
  static Package p;
  return p;
}

void report(const std::string& what, double seconds) {
  std::printf("[gradescope] %s: %.1f s\n", what.c_str(), seconds);
  std::fflush(stdout);
}

// A submission folder holding `files` (name -> content), replacing the previous one.
void makeSubmission(const std::map<std::string, std::string>& files) {
  const fs::path submission = package().root / "submission";
  fs::remove_all(submission);
  fs::create_directories(submission);
  for (const auto& [name, content] : files) std::ofstream(submission / name) << content;
}

std::map<std::string, std::string> solutionFiles() {
  std::map<std::string, std::string> files;
  for (const std::string& f : kTaskFiles)
    files[f] = readAll(fs::path(A6_SOURCE_DIR) / "solution" / f);
  return files;
}

// run_autograder as Gradescope runs it: from /autograder, with what it was copied as.
Outcome runAutograder(const std::string& prefix = "") {
  const Package& p = package();
  return run("cd " + quote(p.root) + " && " + prefix + " env A6_AUTOGRADER_ROOT=" + quote(p.root) +
             " " + quote(p.root / "run_autograder"));
}

// Gradescope's results.json format (shared/reference/gradescope.md), checked field by field.
void expectValidResults(const json& r) {
  static const std::set<std::string> kVisibility = {"visible", "hidden", "after_due_date",
                                                    "after_published"};
  static const std::set<std::string> kFormats = {"text", "html", "simple_format", "md", "ansi"};
  ASSERT_TRUE(r.is_object()) << r;
  ASSERT_TRUE(r.contains("score") && r["score"].is_number()) << "score: " << r.dump(2);
  ASSERT_TRUE(r.contains("execution_time") && r["execution_time"].is_number()) << r.dump(2);
  EXPECT_GE(r["execution_time"].get<double>(), 0);
  for (const char* key : {"visibility", "stdout_visibility"}) {
    if (r.contains(key)) {
      EXPECT_EQ(kVisibility.count(r[key].get<std::string>()), 1u) << key;
    }
  }
  for (const char* key : {"output_format", "test_output_format", "test_name_format"}) {
    if (r.contains(key)) {
      EXPECT_EQ(kFormats.count(r[key].get<std::string>()), 1u) << key;
    }
  }
  if (r.contains("output")) {
    EXPECT_TRUE(r["output"].is_string());
  }
  if (r.contains("extra_data")) {
    EXPECT_TRUE(r["extra_data"].is_object());
  }
  ASSERT_TRUE(r.contains("tests") && r["tests"].is_array()) << r.dump(2);
  // Without tests the score must be there (a submission with nothing to grade: a6_grade exit 2).
  if (r["tests"].empty()) {
    ASSERT_TRUE(r.contains("score") && r["score"].is_number()) << r.dump(2);
    return;
  }
  double sum = 0;
  for (const json& t : r["tests"]) {
    ASSERT_TRUE(t.is_object()) << t;
    ASSERT_TRUE(t.contains("name") && t["name"].is_string()) << t;
    EXPECT_FALSE(t["name"].get<std::string>().empty()) << t;
    ASSERT_TRUE(t.contains("score") && t["score"].is_number()) << t;
    ASSERT_TRUE(t.contains("max_score") && t["max_score"].is_number()) << t;
    EXPECT_GE(t["max_score"].get<double>(), 0) << t;
    ASSERT_TRUE(t.contains("status") && t["status"].is_string()) << t;
    EXPECT_TRUE(t["status"] == "passed" || t["status"] == "failed") << t;
    ASSERT_TRUE(t.contains("visibility") && t["visibility"].is_string()) << t;
    EXPECT_EQ(kVisibility.count(t["visibility"].get<std::string>()), 1u) << t;
    if (t.contains("number")) {
      EXPECT_TRUE(t["number"].is_string()) << t;
    }
    if (t.contains("output")) {
      EXPECT_TRUE(t["output"].is_string()) << t;
    }
    if (t.contains("output_format")) {
      EXPECT_EQ(kFormats.count(t["output_format"].get<std::string>()), 1u) << t;
    }
    if (t.contains("tags")) {
      EXPECT_TRUE(t["tags"].is_array()) << t;
      for (const json& tag : t["tags"]) EXPECT_TRUE(tag.is_string()) << t;
    }
    sum += t["score"].get<double>();
  }
  EXPECT_NEAR(r["score"].get<double>(), sum, 1e-6) << "the score is the sum of the tests'";
}

// The results of the last run, checked; `output` is run_autograder's (for failure messages).
json results(const Outcome& outcome) {
  const fs::path file = package().root / "results" / "results.json";
  const std::string text = readAll(file);
  EXPECT_FALSE(text.empty()) << "no results.json\n" << tail(outcome.output);
  const json r = json::parse(text, nullptr, false);
  EXPECT_FALSE(r.is_discarded()) << "results.json is not JSON:\n" << text;
  if (!r.is_discarded()) {
    expectValidResults(r);
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << tail(outcome.output);
    }
  }
  return r;
}

// Lines of the solution that the starter does not have: non-trivial ones only (at least 25
// characters once blanks are removed; comments and lines that only open a block, such as
// `for (int i = 0; i <= n; ++i) {`, which any loop over a grid has, do not count).
std::string normalised(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const std::string s = line.substr(first);
  if (s.rfind("//", 0) == 0 || s.rfind("/*", 0) == 0 || s.rfind("*", 0) == 0) return "";
  std::string compact;
  for (const char c : s) {
    if (c != ' ' && c != '\t' && c != '\r') compact += c;
  }
  if (!compact.empty() && compact.back() == '{') return "";
  return compact.size() >= 25 ? compact : "";
}

std::set<std::string> linesOf(const fs::path& file) {
  std::set<std::string> lines;
  std::ifstream in(file, std::ios::binary);
  for (std::string line; std::getline(in, line);) {
    if (std::string n = normalised(line); !n.empty()) lines.insert(n);
  }
  return lines;
}

std::set<std::string> solutionOnlyLines() {
  std::set<std::string> starter, only;
  for (const std::string& f : kTaskFiles) {
    const std::set<std::string> s = linesOf(fs::path(A6_SOURCE_DIR) / "starter" / f);
    starter.insert(s.begin(), s.end());
  }
  for (const std::string& f : kTaskFiles) {
    for (const std::string& line : linesOf(fs::path(A6_SOURCE_DIR) / "solution" / f)) {
      if (starter.count(line) == 0) only.insert(line);
    }
  }
  return only;
}

// A spring.cpp: the solution's, with a static initializer that prints who it runs as and tries
// to read the grader's files (before main: the probe's own seccomp filter is not on yet, so only
// the sandbox's user, its mount namespace and the file permissions stand in the way).
std::string whoAmISpring(const fs::path& source) {
  std::string text =
      "#include <cstdio>\n#include <unistd.h>\nnamespace {\nstruct A6Who {\n  A6Who() {\n"
      "    std::printf(\"A6-WHO euid=%d\\n\", static_cast<int>(geteuid()));\n"
      "    const char* secrets[] = {\n";
  for (const char* secret :
       {"tests/golden/manifest.json", "grader/reference/physics.inc", "grader/rubric.toml",
        "build/grader/a6_grade", "build/grader/kit.json"}) {
    text += "        \"" + (source / secret).string() + "\",\n";
  }
  text +=
      "    };\n"
      "    for (const char* s : secrets) {\n"
      "      std::FILE* f = std::fopen(s, \"rb\");\n"
      "      std::printf(\"A6-WHO %s %s\\n\", f != nullptr ? \"READ\" : \"denied\", s);\n"
      "      if (f != nullptr) std::fclose(f);\n"
      "    }\n"
      "    std::fflush(stdout);\n"
      "  }\n"
      "} a6Who;\n"
      "}  // namespace\n";
  return text + readAll(fs::path(A6_SOURCE_DIR) / "solution" / "spring.cpp");
}

// Every point and the extra credit, every check passed, the report written, no scratch files
// left, and the summary on Gradescope's stdout.
void expectEveryPoint(const json& j, const Outcome& r) {
  const a6::grader::Rubric rubric = a6::grader::loadRubric(A6_DEFAULT_RUBRIC);
  ASSERT_TRUE(rubric.ok()) << rubric.error;
  double extra = 0;
  for (const auto& item : rubric.items) extra += item.extraCredit ? item.points : 0;
  EXPECT_DOUBLE_EQ(j["score"].get<double>(), rubric.totalPoints + extra) << tail(r.output);
  for (const json& t : j["tests"]) EXPECT_EQ(t["status"], "passed") << t;
  EXPECT_TRUE(fs::exists(package().root / "results" / "report.html"));
  EXPECT_FALSE(fs::exists(package().root / "results" / "work")) << "scratch files left";
  EXPECT_TRUE(contains(r.output, "total")) << "the summary goes to Gradescope's stdout";
  EXPECT_TRUE(contains(r.output, "report.html")) << "where instructors find the report";
}

// What whoAmISpring printed: a user of its own, every graders' file denied; `docker`: the
// namespace was refused (so the run proved the file permissions).
void expectNoSecretRead(const json& j, const fs::path& source, bool docker) {
  const std::string html = readAll(package().root / "results" / "report.html");
  std::smatch who;
  ASSERT_TRUE(std::regex_search(html, who, std::regex("A6-WHO euid=([0-9]+)"))) << tail(html);
  EXPECT_GE(std::stol(who[1].str()), 60001) << "the probe must run as a sandbox user of its own";
  EXPECT_FALSE(contains(html, "A6-WHO READ")) << "student code read a grader's file";
  EXPECT_TRUE(contains(html, "A6-WHO denied " + (source / "tests/golden/manifest.json").string()))
      << "the probe's attempt was not seen";
  if (!docker) return;
  std::string notes;
  for (const json& n : j["extra_data"]["notes"]) notes += n.get<std::string>() + "\n";
  EXPECT_TRUE(contains(notes, "could not hide the grader's files"))
      << "the namespace was not refused, so this case tested nothing new:\n"
      << notes;
}

class Environment final : public ::testing::Environment {
 public:
  void TearDown() override {
    Package& p = package();
    report("total", std::chrono::duration<double>(Clock::now() - p.start).count());
    if (p.dir.empty()) return;
    if (std::getenv("A6_KEEP_GRADESCOPE_TEST") != nullptr ||
        ::testing::UnitTest::GetInstance()->failed_test_count() > 0) {
      std::printf("[gradescope] kept %s for inspection\n", p.dir.c_str());
    } else {
      std::error_code ec;
      fs::remove_all(p.dir, ec);
    }
  }
};
[[maybe_unused]] const auto* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new Environment);

#define REQUIRE_BUILT()                                                            \
  if (!package().built) {                                                          \
    FAIL() << "needs the autograder that setup.sh builds (see the failure above)"; \
  }

// --- the cases, in order --------------------------------------------------------------------

// The zip, made by scripts/gradescope-package.sh in a fresh folder others may enter.
void makeTheZip(Package& p) {
  for (const char* tool : {"zip", "unzip"}) {
    ASSERT_EQ(run(std::string("command -v ") + tool).status, 0)
        << "the '" << tool << "' command is missing: run scripts/install-deps.sh (as root)";
  }
  char dir[] = "/tmp/a6_gradescope_test.XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  p.dir = dir;
  fs::permissions(p.dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
  p.zip = p.dir / "a6_autograder.zip";
  p.root = p.dir / "autograder";

  const Outcome packaged = run(
      quote(fs::path(A6_SOURCE_DIR) / "scripts" / "gradescope-package.sh") + " " + quote(p.zip));
  ASSERT_EQ(packaged.status, 0) << packaged.output;
  report("scripts/gradescope-package.sh", packaged.seconds);
  std::printf("[gradescope] zip: %ju bytes\n", static_cast<std::uintmax_t>(fs::file_size(p.zip)));
}

// The entries, by path: the two files at the root, no solution, no build tree, and the
// autograder's secrets, which travel with it.
void expectTheEntries(const Package& p) {
  const Outcome listed = run("unzip -Z1 " + quote(p.zip));
  ASSERT_EQ(listed.status, 0) << listed.output;
  std::set<std::string> entries;
  std::istringstream lines(listed.output);
  for (std::string line; std::getline(lines, line);) entries.insert(line);
  EXPECT_EQ(entries.count("setup.sh"), 1u) << "setup.sh must be at the zip's root";
  EXPECT_EQ(entries.count("run_autograder"), 1u) << "run_autograder must be at the zip's root";
  for (const std::string& e : entries) {
    for (const char* banned : {"solution/", "tests/wrong/", "tests/alternative/", "tests/bench/",
                               "tests/grader/", "framework/viewer/", ".ci/", "out/"}) {
      EXPECT_NE(e.rfind(banned, 0), 0u) << e << " must not be in the zip";
    }
    // A build tree: a root folder build*/, or CMake's files anywhere (grader/build/ is the
    // grader's build stage, sources).
    EXPECT_FALSE(e.rfind("build", 0) == 0 || contains(e, "CMakeFiles/") ||
                 contains(e, "CMakeCache.txt"))
        << e << ": a build folder";
  }
  std::vector<std::string> needed = {"tests/golden/manifest.json", "grader/rubric.toml",
                                     "starter/spring.cpp", "scripts/install-deps.sh"};
  for (const char* secret_dir : {"tests/hidden", "tests/golden/hidden", "grader/reference"}) {
    const fs::path d = fs::path(A6_SOURCE_DIR) / secret_dir;
    if (!fs::is_directory(d)) continue;
    for (const auto& f : fs::recursive_directory_iterator(d)) {
      if (f.is_regular_file()) needed.push_back(fs::relative(f.path(), A6_SOURCE_DIR).string());
    }
  }
  for (const std::string& n : needed) EXPECT_EQ(entries.count(n), 1u) << n << " missing";
}

// Unpacked as Gradescope does: into /autograder/source.
void unpackAsGradescopeDoes(const Package& p) {
  fs::create_directories(p.root / "source");
  fs::create_directories(p.root / "results");
  fs::create_directories(p.root / "submission");
  const Outcome unzipped = run("unzip -q " + quote(p.zip) + " -d " + quote(p.root / "source"));
  ASSERT_EQ(unzipped.status, 0) << unzipped.output;
  for (const char* f : {"setup.sh", "run_autograder"}) {
    const fs::perms perms = fs::status(p.root / "source" / f).permissions();
    EXPECT_NE(perms & fs::perms::owner_exec, fs::perms::none) << f << " must be executable";
  }
}

// By content: no line of the solution that the starter lacks, in any file. The autograder's
// own hidden material (the hidden checks, the reference physics) computes the right
// answers to check against, so it may share a line or two with the solution (a cloth's grid
// spacing, say): those are printed, and only more than kSharedLinesAllowed in one such file (a
// copied function) fails.
void expectNoLineOfTheSolution(const Package& p) {
  constexpr std::size_t kSharedLinesAllowed = 2;
  const std::set<std::string> secret = solutionOnlyLines();
  ASSERT_GE(secret.size(), 20u) << "too few solution-only lines for the check to mean anything";
  int scanned = 0;
  for (const auto& f : fs::recursive_directory_iterator(p.root / "source")) {
    if (!f.is_regular_file()) continue;
    ++scanned;
    const std::string name = fs::relative(f.path(), p.root / "source").string();
    const bool hiddenMaterial =
        name.rfind("tests/hidden/", 0) == 0 || name.rfind("grader/reference/", 0) == 0;
    std::vector<std::string> shared;
    for (const std::string& line : linesOf(f.path())) {
      if (secret.count(line) != 0) shared.push_back(line);
    }
    if (hiddenMaterial && shared.size() <= kSharedLinesAllowed) {
      for (const std::string& line : shared) {
        std::printf("[gradescope] note: %s shares a line with the solution: %s\n", name.c_str(),
                    line.c_str());
      }
      continue;
    }
    for (const std::string& line : shared) {
      ADD_FAILURE() << name << " holds a line of the solution: " << line;
    }
  }
  std::printf("[gradescope] %d files scanned for %zu solution-only lines\n", scanned,
              secret.size());
}

TEST(Gradescope, TheZipHasItsTwoFilesAtTheRootAndNothingOfTheSolution) {
  Package& p = package();
  makeTheZip(p);
  if (HasFatalFailure()) return;
  expectTheEntries(p);
  if (HasFatalFailure()) return;
  unpackAsGradescopeDoes(p);
  if (HasFatalFailure()) return;
  expectNoLineOfTheSolution(p);
  if (HasFatalFailure()) return;
  p.unpacked = true;
}

TEST(Gradescope, SetupBuildsTheGraderFromScratchInUnderFiveMinutes) {
  Package& p = package();
  ASSERT_TRUE(p.unpacked) << "needs the unpacked zip (see the failure above)";
  std::ofstream(p.root / "submission_metadata.json")
      << R"({"id": 123456789, "created_at": "2026-01-01T12:00:00.000000-08:00",)"
      << R"( "assignment": {"title": "Assignment 6", "total_points": "100.0"},)"
      << R"( "previous_submissions": []})"
      << "\n";
  // The time it takes is measured as CPU time (the build's processes, all reaped by then): the
  // wall-clock time on a machine whose two cores others share says more about them than about
  // the build. 300 CPU seconds are under 3 minutes on 2 idle cores; building more than
  // a6_grade and its kit (every test binary, say) takes several times that.
  const double cpuBefore = a6::test::childrenCpuSeconds();
  const Outcome setup = run("cd " + quote(p.root) + " && env A6_AUTOGRADER_ROOT=" + quote(p.root) +
                            " A6_SKIP_APT=1 bash " + quote(p.root / "source" / "setup.sh"));
  const double cpu = a6::test::childrenCpuSeconds() - cpuBefore;
  report("setup.sh (configure, build a6_grade and its kit, smoke check)", setup.seconds);
  report("setup.sh, CPU time (user + system)", cpu);
  ASSERT_EQ(setup.status, 0) << tail(setup.output);
  EXPECT_TRUE(contains(setup.output, "smoke check passed")) << tail(setup.output);
  EXPECT_LT(cpu, 300) << "setup.sh must stay well under 5 minutes on 2 cores: build fewer targets";
  // Gradescope copies run_autograder to /autograder and runs it from there.
  fs::copy_file(p.root / "source" / "run_autograder", p.root / "run_autograder",
                fs::copy_options::overwrite_existing);
  p.built = true;
}

TEST(Gradescope, AZipOfTheStarterGetsZero) {
  REQUIRE_BUILT();
  const fs::path submission = package().root / "submission";
  makeSubmission({});
  const Outcome zipped = run("cd " + quote(fs::path(A6_SOURCE_DIR) / "starter") + " && zip -q " +
                             quote(submission / "my_assignment.zip") + " *.cpp");
  ASSERT_EQ(zipped.status, 0) << zipped.output;
  const Outcome r = runAutograder();
  report("run_autograder on a zip of the starter", r.seconds);
  EXPECT_EQ(r.status, 0) << tail(r.output);
  const json j = results(r);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["score"].get<double>(), 0) << tail(r.output);
  const std::string output = j.value("output", "");
  for (const std::string& f : kTaskFiles) {
    EXPECT_TRUE(contains(output, f + ": compiled")) << "the zip's " << f << " was graded\n"
                                                    << output;
  }
}

TEST(Gradescope, AnEmptySubmissionGetsZeroAndIsToldWhichFilesWereMissing) {
  REQUIRE_BUILT();
  makeSubmission({});
  const Outcome r = runAutograder();
  report("run_autograder on an empty submission", r.seconds);
  EXPECT_EQ(r.status, 0) << tail(r.output);
  const json j = results(r);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["score"].get<double>(), 0);
  const std::string output = j.value("output", "");
  EXPECT_TRUE(contains(output, "Not graded: none of the task files (spring.cpp")) << output;
  for (const std::string& f : kTaskFiles) EXPECT_TRUE(contains(output, f)) << f << "\n" << output;
}

// The solution gets every point and the extra credit, and its code runs as a sandbox user of its
// own that cannot read the graders' files. As root, its spring also prints its user and tries to
// open them before main; it is graded as run here (a private mount namespace hides the trees),
// then as in an unprivileged Docker container, where the namespace is refused and only
// setup.sh's file permissions protect them.
TEST(Gradescope, TheSolutionGetsEveryPointAsAUserThatCannotReadTheGradersFiles) {
  REQUIRE_BUILT();
  const bool root = geteuid() == 0;
  const fs::path source = package().root / "source";
  std::map<std::string, std::string> files = solutionFiles();
  if (root) files["spring.cpp"] = whoAmISpring(source);
  const bool canDrop = root && run("command -v setpriv").status == 0;
  if (!root) std::printf("[gradescope] not root: the sandbox changes user only as root\n");
  if (root && !canDrop) std::printf("[gradescope] setpriv missing: no run without namespaces\n");
  for (const bool docker : {false, true}) {
    if (docker && !canDrop) continue;
    SCOPED_TRACE(docker ? "without CAP_SYS_ADMIN (no mount namespace)" : "as run here");
    makeSubmission(files);
    const Outcome r =
        runAutograder(docker ? "setpriv --bounding-set -sys_admin --inh-caps -sys_admin --" : "");
    report(docker ? "run_autograder on the solution without mount namespaces"
                  : "run_autograder on the solution",
           r.seconds);
    EXPECT_EQ(r.status, 0) << tail(r.output);
    const json j = results(r);
    ASSERT_FALSE(j.is_discarded());
    expectEveryPoint(j, r);
    if (root) expectNoSecretRead(j, source, docker);
  }
}

TEST(Gradescope, WithoutAWorkingGraderResultsAreStillValid) {
  REQUIRE_BUILT();
  const fs::path grader = package().root / "source" / "build" / "grader" / "a6_grade";
  const fs::path saved = grader.string() + ".saved";
  fs::rename(grader, saved);
  makeSubmission(solutionFiles());

  // Missing.
  Outcome r = runAutograder();
  report("run_autograder without a6_grade", r.seconds);
  EXPECT_EQ(r.status, 0) << tail(r.output);
  json j = results(r);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["score"].get<double>(), 0);
  EXPECT_TRUE(contains(j.value("output", ""), "is missing")) << j.dump(2);

  // Gives no limits (run_autograder reads its time limits from a6_grade --list-limits).
  std::ofstream(grader) << "#!/bin/sh\nexit 1\n";
  fs::permissions(grader, fs::perms::owner_all);
  r = runAutograder();
  EXPECT_EQ(r.status, 0) << tail(r.output);
  j = results(r);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_TRUE(contains(j.value("output", ""), "gave no time limits")) << j.dump(2);

  // Crashes half-way, leaving its placeholder ("grading did not finish") behind; its limits are
  // the real grader's.
  std::ofstream(grader)
      << "#!/bin/sh\n"
      << "[ \"$1\" = --list-limits ] && exec '" << saved.string() << "' --list-limits\n"
      << "while [ $# -gt 0 ]; do [ \"$1\" = --out ] && out=$2; shift; done\n"
         "mkdir -p \"$out\"\n"
         "printf '{\"score\": 0, \"output\": \"grading did not finish (the grader was killed "
         "or ran out of time)\"}' "
         "> \"$out/results.json\"\n"
         "kill -SEGV $$\n";
  fs::permissions(grader, fs::perms::owner_all);
  r = runAutograder();
  report("run_autograder with a6_grade crashing", r.seconds);
  EXPECT_EQ(r.status, 0) << tail(r.output);
  j = results(r);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["score"].get<double>(), 0);
  EXPECT_TRUE(contains(j.value("output", ""), "crashed (killed by signal 11)")) << j.dump(2);

  fs::remove(grader);
  fs::rename(saved, grader);
}

}  // namespace
