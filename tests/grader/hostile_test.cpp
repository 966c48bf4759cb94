// The trust boundary, proved: hostile and broken submissions graded by a6_grade.
//
// Each case is a submission that attacks the grader or breaks in a nasty way: the fixtures in
// tests/grader/submissions/<case>/ (the files that differ from the solution; each opens with a
// comment saying what it does and what it must get) or an archive written here. Every case is
// graded by the real a6_grade, as a TA would run it, and must get
//
//   - exactly its honest score: the tasks it breaks earn what the starter's code earns there (its
//     "twin", the solution with the starter's files for those tasks, is graded beside it), every
//     other task keeps its full points (from the rubric's points, for the physics checks), and
//     the total is never more than the rubric's points of the tasks it does not break;
//   - a clear reason, in the items of the tasks it breaks (or in the report);
//   - and a6_grade must exit with 0, having written a valid results.json that is its own (not one
//     the submission planted), within the wall time the grader promises (maxGradingSeconds: its
//     budgets and its own work) and within the case's bound on CPU time (a bound that other work
//     on the machine hardly moves, so that a grader gone slow fails here, not a loaded machine).
//
// Each case is its own ctest entry (--gtest_filter), so they run in parallel. The table of cases
// and the scores they get is in docs/instructor.md, "Hostile submissions".
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/fnv1a.h"
#include "common/limits.h"
#include "poisoner.h"
#include "rubric/rubric.h"
#include "run_command.h"
#include "staging.h"

namespace {

namespace fs = std::filesystem;
using a6::grader::Rubric;
using a6::grader::RubricItem;
using nlohmann::json;

// The submissions are prepared in staging.h (batch_test.cpp grades the same ones in a batch).
using a6::test::staging::kFixtures;
using a6::test::staging::kSource;
using a6::test::staging::kTaskFiles;
using a6::test::staging::readAll;
using a6::test::staging::stage;
using a6::test::staging::writeArchive;
const char* const kMarker = "a6_hostile_was_here";  // what write_files tries to leave behind

// This case's folder, inside the build tree (ctest's working directory), emptied.
fs::path caseDir(const std::string& name) {
  const fs::path dir = fs::absolute("hostile_out") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// ---- running a6_grade ---------------------------------------------------------------------------

struct Graded {
  int status = -1;
  double seconds = 0;
  double cpuSeconds = 0;  // a6_grade's and everything it waited for
  std::string output;     // stdout and stderr
  json results;           // results.json (null when missing or invalid)
  fs::path out;
};

Graded grade(const fs::path& submission, const fs::path& out, const fs::path& rubric,
             const std::string& extra = "") {
  const a6::test::CommandRun run = a6::test::runCommand(
      std::string(A6_GRADE_COMMAND) + " '" + submission.string() + "' --out '" + out.string() +
      "' --rubric '" + rubric.string() + "' --quiet " + extra);
  Graded g;
  g.out = out;
  g.status = run.status;
  g.seconds = run.seconds;
  g.cpuSeconds = run.cpuSeconds;
  g.output = run.output;
  g.results = json::parse(readAll(out / "results.json"), nullptr, false);
  if (g.results.is_discarded()) g.results = nullptr;
  return g;
}

// The twin of a case that breaks `broken` (the solution with the starter's files of those
// tasks), graded with the case's rubric. Most cases break task 1, so they share twins: the first
// case to need one grades it, under a lock, and the others read its results. A twin's folder is
// named by what decides its grading (the grader's file, the rubric's text, the files graded), so
// a rebuilt grader or a changed file grades it anew.
Graded gradeTwin(const fs::path& dir, const std::set<int>& broken, const fs::path& rubric,
                 const std::string& extra = "") {
  const fs::path submission = stage(dir / "twin", "", broken);
  a6::grader::Fnv1a key;
  key.add(extra);
  std::error_code ec;
  key.add(std::to_string(fs::file_size(A6_GRADE_COMMAND, ec)));
  key.add(std::to_string(fs::last_write_time(A6_GRADE_COMMAND, ec).time_since_epoch().count()));
  key.add(readAll(rubric));
  for (const std::string& file : kTaskFiles) key.add(readAll(submission / file));
  const fs::path shared = fs::absolute("hostile_out") / "twins" / key.hex();
  fs::create_directories(shared.parent_path());
  const int lock = open((shared.string() + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock >= 0) flock(lock, LOCK_EX);
  Graded g;
  if (fs::exists(shared / "done")) {
    g.status = 0;
    g.out = shared / "out";
    g.results = json::parse(readAll(g.out / "results.json"), nullptr, false);
  } else {
    fs::remove_all(shared);
    g = grade(submission, shared / "out", rubric, extra);
    if (g.status == 0 && g.results.is_object()) a6::test::staging::writeAll(shared / "done", "");
  }
  if (lock >= 0) close(lock);  // (and so unlocked)
  return g;
}

// The default rubric, or a copy with every time limit cut to `seconds` (for the cases whose code
// never returns: the correct checks take well under a tenth of a second each).
fs::path rubricFor(const fs::path& dir, double seconds = 0) {
  const fs::path standard = A6_DEFAULT_RUBRIC;
  if (seconds <= 0) return standard;
  return a6::test::staging::withTimeLimit(standard, dir, seconds);
}

// ---- what a result must be ----------------------------------------------------------------------

// An item's name in results.json is "<rubric item name> (p/n checks)".
std::map<std::string, const json*> itemsByName(const json& results) {
  std::map<std::string, const json*> items;
  if (!results.is_object() || !results.contains("tests")) return items;
  for (const json& t : results["tests"]) {
    std::string name = t.value("name", "");
    const std::size_t at = name.rfind(" (");
    if (at != std::string::npos) name.resize(at);
    items[name] = &t;
  }
  return items;
}

// Only GoogleTest physics checks (suites Task1Spring ... Task6Joints), no images.
bool physicsOnly(const RubricItem& item) {
  return std::all_of(item.tests.begin(), item.tests.end(),
                     [](const std::string& glob) { return glob.rfind("Task", 0) == 0; });
}

std::string describe(const Graded& g) {
  std::ostringstream out;
  out << "a6_grade exited with " << g.status << " after " << g.seconds << " s (" << g.cpuSeconds
      << " s of CPU); it printed:\n"
      << g.output.substr(0, 4000);
  if (g.results.is_object()) out << "\nresults.json output:\n" << g.results.value("output", "");
  return out.str();
}

// Valid results.json of a completed run, written by the grader within the wall time it promises
// for `timeBudget` and within `maxCpuSeconds` of CPU.
void expectValidResults(const Graded& g, double maxCpuSeconds,
                        double timeBudget = a6::grader::kDefaultTimeBudget) {
  EXPECT_EQ(g.status, 0) << describe(g);
  EXPECT_LT(g.seconds, a6::grader::maxGradingSeconds(timeBudget)) << describe(g);
  EXPECT_LT(g.cpuSeconds, maxCpuSeconds) << describe(g);
  ASSERT_TRUE(g.results.is_object()) << "no valid results.json\n" << describe(g);
  ASSERT_TRUE(g.results.contains("score") && g.results["score"].is_number()) << g.results;
  ASSERT_TRUE(g.results.contains("tests") && g.results["tests"].is_array()) << g.results;
  EXPECT_FALSE(g.results["tests"].empty());
  for (const json& t : g.results["tests"]) {
    EXPECT_TRUE(t.contains("name") && t.contains("score") && t.contains("max_score") &&
                t.contains("status"))
        << t;
  }
  EXPECT_EQ(g.results["extra_data"]["errors"], json::array())
      << "a grader error, not a submission problem\n"
      << describe(g);
  const std::string output = g.results.value("output", "");
  EXPECT_EQ(output.find("FAKE"), std::string::npos) << "a planted results.json\n" << output;
  EXPECT_EQ(output.find("grading did not finish"), std::string::npos) << output;
}

// The score a submission that breaks `broken` deserves: compared item by item with the rubric
// (physics items: full points outside `broken`, nothing inside) and with its twin (the solution
// with the starter's files for `broken`), whose score is the honest one for the image items too.
// `exact`: the broken files behave as the starter's (they return zero), so every item scores as
// the twin's; otherwise (they crash, throw, loop, return NaN) no item scores more than the
// twin's: an image whose scene crashes fails all its frames, even those a stub draws right.
void expectHonestScore(const Graded& g, const Rubric& rubric, const std::set<int>& broken,
                       const Graded* twin, bool exact) {
  ASSERT_TRUE(rubric.ok()) << rubric.error;
  const auto items = itemsByName(g.results);
  const auto twinItems = twin != nullptr ? itemsByName(twin->results) : items;
  double full = 0, bound = 0;
  for (const RubricItem& item : rubric.items) {
    full += item.points;
    if (!broken.count(item.task)) bound += item.points;
    const auto found = items.find(item.name);
    ASSERT_NE(found, items.end()) << "no item '" << item.name << "' in results.json";
    const double score = (*found->second)["score"].get<double>();
    const std::string where = "item '" + item.name + "' (task " + std::to_string(item.task) + ")";
    if (physicsOnly(item)) {
      EXPECT_DOUBLE_EQ(score, broken.count(item.task) ? 0.0 : item.points)
          << where << "\n"
          << (*found->second)["output"].get<std::string>().substr(0, 3000);
    }
    if (twin != nullptr) {
      const auto other = twinItems.find(item.name);
      ASSERT_NE(other, twinItems.end()) << "no item '" << item.name << "' in the twin's results";
      const double honest = (*other->second)["score"].get<double>();
      if (exact) {
        EXPECT_DOUBLE_EQ(score, honest)
            << where << ": the twin (the starter's code for the broken tasks) got another score\n"
            << (*found->second)["output"].get<std::string>().substr(0, 3000);
      } else {
        EXPECT_LE(score, honest + 1e-9)
            << where << ": more than the twin (the starter's code for the broken tasks)\n"
            << (*found->second)["output"].get<std::string>().substr(0, 3000);
      }
    } else {
      EXPECT_DOUBLE_EQ(score, item.points)
          << where << "\n"
          << (*found->second)["output"].get<std::string>().substr(0, 3000);
    }
  }
  const double total = g.results["score"].get<double>();
  EXPECT_LE(total, bound + 1e-9) << "more than the points of the tasks it does not break";
  if (twin != nullptr && exact) {
    EXPECT_DOUBLE_EQ(total, twin->results["score"].get<double>()) << describe(g);
  } else if (twin != nullptr) {
    EXPECT_LE(total, twin->results["score"].get<double>() + 1e-9) << describe(g);
  } else {
    EXPECT_DOUBLE_EQ(total, full) << describe(g);
  }
}

// The score docs/instructor.md's table of hostile cases gives the case `name` (the leading number
// of its row's score column) is the one it got: the table cannot drift from the grader. Its
// header says the rubric its scores are for ("score (of 100 + 13 extra credit)"); graded with
// another (an instructor's), the rows are not compared.
void expectDocumentedScore(const std::string& name, const Graded& g, const Rubric& rubric) {
  std::istringstream guide(readAll(kSource / "docs" / "instructor.md"));
  const std::string header = "| case | what the submission does | score (of ";
  const std::string key = "`" + name + "`";
  double points = -1, extra = -1;
  for (std::string line; std::getline(guide, line);) {
    if (line.rfind(header, 0) == 0) {
      std::sscanf(line.c_str() + header.size(), "%lf + %lf", &points, &extra);
      double ours = 0;
      for (const RubricItem& item : rubric.items) ours += item.extraCredit ? item.points : 0;
      if (points != rubric.totalPoints || extra != ours) {
        std::printf("[ hostile  ] the guide's table is for a rubric of %g + %g: not compared\n",
                    points, extra);
        return;
      }
    }
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (points < 0 || line.rfind("| `", 0) != 0 || cells.size() < 4 ||
        cells[1].find(key) == std::string::npos) {
      continue;
    }
    const double documented = std::strtod(cells[3].c_str(), nullptr);
    EXPECT_DOUBLE_EQ(documented, g.results.value("score", -1.0))
        << "docs/instructor.md's table of hostile cases gives " << name << " " << cells[3];
    return;
  }
  ADD_FAILURE() << "docs/instructor.md's table of hostile cases (its header \"" << header
                << "...\") has no row for " << key;
}

// `reason` appears in what the students see for the broken tasks (the items' outputs), or, with
// no broken task, in the top-level output or the HTML report.
void expectReason(const Graded& g, const Rubric& rubric, const std::set<int>& broken,
                  const std::string& reason) {
  if (reason.empty()) return;
  const auto items = itemsByName(g.results);
  for (const int task : broken) {
    std::string text;
    for (const RubricItem& item : rubric.items) {
      if (item.task != task || item.points <= 0 || !physicsOnly(item)) continue;
      const auto found = items.find(item.name);
      if (found != items.end()) text += (*found->second)["output"].get<std::string>();
    }
    EXPECT_NE(text.find(reason), std::string::npos)
        << "task " << task << " does not say '" << reason << "':\n"
        << text.substr(0, 3000);
  }
  if (broken.empty()) {
    const std::string text = g.results.value("output", "") + readAll(g.out / "report.html");
    EXPECT_NE(text.find(reason), std::string::npos) << "'" << reason << "' not in the report";
  }
}

struct Case {
  Case(std::set<int> brokenTasks, std::string why, double cpuSeconds = 120, double limit = 0,
       std::vector<std::string> left = {})
      : broken(std::move(brokenTasks)),
        reason(std::move(why)),
        maxCpuSeconds(cpuSeconds),
        timeLimit(limit),
        omit(std::move(left)) {}
  /// The broken files crash, throw, loop or return NaN rather than return what a stub does.
  Case& crashes() {
    exact = false;
    return *this;
  }
  /// Only the checks of `filter` run (a GoogleTest filter), in the case and in its twin.
  Case& only(std::string filter) {
    tests = std::move(filter);
    return *this;
  }
  std::set<int> broken;           // tasks that honestly earn what the starter's code earns
  std::string reason;             // what the broken tasks' items (or the report) must say
  double maxCpuSeconds;           // a6_grade's CPU time stays under this (the case, not its twin)
  double timeLimit;               // > 0: every rubric time limit cut to this, s
  std::vector<std::string> omit;  // task files left out of the submission
  bool exact = true;              // every item scores exactly as the twin's (see crashes())
  std::string tests;              // not empty: a6_grade --tests this (see only())
};

struct Outcome {
  Graded graded;
  Rubric rubric;
  fs::path dir;
};

// Grades `submission` (already staged, or an archive), and its twin when it breaks a task, and
// checks everything every case must satisfy.
Outcome check(const std::string& name, const fs::path& dir, const fs::path& submission,
              const Case& c) {
  Outcome o;
  o.dir = dir;
  const fs::path rubricFile = rubricFor(dir, c.timeLimit);
  o.rubric = a6::grader::loadRubric(rubricFile);
  EXPECT_TRUE(o.rubric.ok()) << o.rubric.error;
  const std::string extra = c.tests.empty() ? "" : "--tests '" + c.tests + "'";
  o.graded = grade(submission, dir / "out", rubricFile, extra);
  std::printf("[ hostile  ] %s: score %s in %.1f s (%.1f s of CPU)\n", name.c_str(),
              o.graded.results.is_object() ? o.graded.results["score"].dump().c_str() : "none",
              o.graded.seconds, o.graded.cpuSeconds);
  expectValidResults(o.graded, c.maxCpuSeconds);
  if (::testing::Test::HasFatalFailure()) return o;
  Graded twin;
  if (!c.broken.empty()) {
    twin = gradeTwin(dir, c.broken, rubricFile, extra);
    expectValidResults(twin, 300);
    if (::testing::Test::HasFatalFailure()) return o;
  }
  expectHonestScore(o.graded, o.rubric, c.broken, c.broken.empty() ? nullptr : &twin, c.exact);
  expectReason(o.graded, o.rubric, c.broken, c.reason);
  expectDocumentedScore(name, o.graded, o.rubric);
  return o;
}

// A fixture folder staged over the solution, graded and checked.
Outcome checkFixture(const std::string& name, const Case& c) {
  const fs::path dir = caseDir(name);
  return check(name, dir, stage(dir / "submission", name, {}, c.omit), c);
}

// Processes still running whose program lies under `dir` (a probe and what it forked).
std::vector<std::string> processesUnder(const fs::path& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::directory_iterator it("/proc", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string pid = it->path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::error_code lec;
    const std::string exe = fs::read_symlink(it->path() / "exe", lec).string();
    std::string cmdline = readAll(it->path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (exe.rfind(dir.string(), 0) == 0 || cmdline.rfind(dir.string(), 0) == 0) {
      found.push_back(pid + " " + exe + " " + cmdline);
    }
  }
  return found;
}

void expectNoProcessLeft(const fs::path& dir) {
  // The grader kills what is left before it exits; give the kernel a moment to reap.
  std::vector<std::string> left;
  for (int k = 0; k < 20; ++k) {
    left = processesUnder(dir);
    if (left.empty()) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  std::string list;
  for (const std::string& p : left) {
    list += p + "\n";
    kill(static_cast<pid_t>(std::stol(p)), SIGKILL);  // do not leave them to the next test
  }
  ADD_FAILURE() << "processes of the submission outlived a6_grade:\n" << list;
}

// The grader's out folder holds only what the grader writes: results.json, report.html and its
// scratch folder, whose probe folders are removed when the probes end.
void expectOnlyGraderFiles(const fs::path& out) {
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "results.json" || name == "report.html" || name == "work")
        << "unexpected " << entry.path();
  }
  for (const fs::path& run : {out / "work" / "run", out / "work" / "startup"}) {
    if (!fs::exists(run)) continue;
    for (const auto& entry : fs::directory_iterator(run)) {
      if (entry.path().filename().string().rfind("probe-", 0) == 0) {
        ADD_FAILURE() << "a probe's working folder was not removed: " << entry.path();
      }
    }
  }
}

// ---- archives -----------------------------------------------------------------------------------

// An archive whose spring.cpp (the solution's) only comes with paths that leave it: relative
// ('..'), through a folder ('sub/../..'), and absolute. The other five files are the solution's.
void checkTraversal(const std::string& name, bool zip) {
  const fs::path dir = caseDir(name);
  const fs::path archive = dir / (zip ? "traversal.zip" : "traversal.tar.gz");
  ASSERT_EQ(writeArchive(archive, zip, a6::test::staging::traversalEntries()), "");
  fs::remove_all("/tmp/a6_traversal_abs");

  const Outcome o = check(name, dir, archive, {{1}, ""});
  const std::string output = o.graded.results.value("output", "");
  EXPECT_NE(output.find("Not found (the starter code was used): spring.cpp"), std::string::npos)
      << output;
  EXPECT_NE(output.find(".."), std::string::npos) << "the refused entries are noted\n" << output;
  // Nothing landed where the entries point.
  for (const fs::path& p :
       {dir / "out" / "work" / "spring.cpp", dir / "out" / "spring.cpp", dir / "spring.cpp",
        dir.parent_path() / "a6_traversal_spring.cpp", fs::path("/tmp/a6_traversal_abs")}) {
    EXPECT_FALSE(fs::exists(p)) << p << " was written";
  }
  for (fs::path p = dir; p != p.root_path(); p = p.parent_path()) {
    EXPECT_FALSE(fs::exists(p / "a6_traversal_spring.cpp")) << p;
  }
}

// ---- the cases ----------------------------------------------------------------------------------

// Printing or planting results changes nothing.
TEST(Hostile, FakeResults) {
  const bool hadAutograder = fs::exists("/autograder");
  const Outcome o = checkFixture("fake_results", {{1}, "actual:   (0, 0)"});
  expectOnlyGraderFiles(o.dir / "out");
  const std::string results = readAll(o.dir / "out" / "results.json");
  EXPECT_EQ(results.find("FAKE"), std::string::npos) << "the planted results.json is in place";
  if (!hadAutograder) {
    EXPECT_FALSE(fs::exists("/autograder")) << "the probe created /autograder";
    fs::remove_all("/autograder");
  }
}

TEST(Hostile, FakeTestOutput) {
  const Outcome o = checkFixture("fake_gtest_lines", {{1}, "actual:   (0, 0)"});
  // What it printed is in the report, for the instructor, and changed nothing.
  EXPECT_NE(readAll(o.dir / "out" / "report.html").find("A6-SUMMARY 1:14:0"), std::string::npos);
}

// Code before main: the file that holds it costs its own task, as a file that does not compile.
TEST(Hostile, ExitBeforeMain) {
  checkFixture("static_exit", {{1}, "did not start: the probe crashed: exited with 0"});
}

TEST(Hostile, AbortBeforeMain) {
  checkFixture("static_abort", {{1}, "did not start: the probe crashed: killed by SIGABRT"});
}

TEST(Hostile, EndlessLoopBeforeMain) {
  checkFixture("static_infinite_loop", {{1}, "did not reach main within", 120});
}

TEST(Hostile, WritesFilesEverywhere) {
  const fs::path dir = fs::absolute("hostile_out") / "write_files";
  std::vector<fs::path> places = {kSource,
                                  kSource / "solution",
                                  kSource / "tests" / "golden",
                                  "/tmp",
                                  "/var/tmp",
                                  "/dev/shm",
                                  "/run/lock",
                                  "/root",
                                  "/autograder/results",
                                  "/",
                                  dir / "out",
                                  dir / "out" / "work",
                                  dir / "out" / "work" / "run"};
  for (fs::path p = dir; p != p.root_path(); p = p.parent_path()) places.push_back(p);
  std::error_code ec;
  for (const fs::path& p : places) fs::remove(p / kMarker, ec);  // from an earlier run

  const Outcome o = checkFixture("write_files", {{}, "could not write /tmp/a6_hostile_was_here"});
  for (const fs::path& p : places) EXPECT_FALSE(fs::exists(p / kMarker)) << p / kMarker;
  for (const auto& entry : fs::recursive_directory_iterator(o.dir / "out")) {
    EXPECT_NE(entry.path().filename(), kMarker) << entry.path();
  }
  expectOnlyGraderFiles(o.dir / "out");
  // The probe said what it could not do. Its static initialisers run under the probe's filter
  // (grader/probe/filter.h), so it could not even write in its own working directory.
  const std::string report = readAll(o.dir / "out" / "report.html");
  EXPECT_NE(report.find("hostile: could not write ./a6_hostile_was_here"), std::string::npos);
  EXPECT_EQ(report.find("hostile: WROTE ./a6_hostile_was_here"), std::string::npos);
  EXPECT_EQ(report.find("hostile: WROTE ./.."), std::string::npos);
  EXPECT_EQ(report.find("hostile: WROTE /"), std::string::npos);
}

// The solution and the goldens cannot be reached, at compile time or at run time.
TEST(Hostile, IncludesTheSolution) { checkFixture("include_solution", {{1}, "actual:   (0, 0)"}); }

TEST(Hostile, IncludesTheGoldens) { checkFixture("include_goldens", {{1}, "actual:   (0, 0)"}); }

TEST(Hostile, OpensTheSolutionAndTheGoldens) {
  const Outcome o = checkFixture("fopen_secrets", {{1}, "actual:   (0, 0)"});
  const std::string report = readAll(o.dir / "out" / "report.html");
  EXPECT_NE(report.find("hostile: could not read " + kSource.string() + "/solution/spring.cpp"),
            std::string::npos);
  EXPECT_EQ(report.find("hostile: READ"), std::string::npos);
}

// Two checks of task 1 and one of its images, with every check of tasks 2 to 7 and the Box2D
// images: for the cases whose spring makes each check or image that calls it cost seconds (it
// loops, answers what is costly to parse, or prints on every call), the same decisions in a
// fraction of the time. (Whatever the filter leaves out, the case and its twin both lose.) The
// three checks still end one after another in their limits, each with its probes started again:
// what the other checks of task 1 would repeat. The replays, off with a filter, skip a scene
// whose images failed anyway.
const char* const kFewSpringChecks =
    "Task1Spring.AtRest*:Task1Spring.Stretched*:GoldenTask1.single_spring_f20:Task2*:Task3*:"
    "Task4*:Task5*:Task6*:Task7*:GoldenTask6*";

// An endless loop in one task's code costs that task's checks only, each within its time limit.
TEST(Hostile, EndlessLoop) {
  // Every time limit cut to 1 s (the correct checks take a few hundredths each): each check of
  // task 1 and each image that runs the spring waits that long twice (a time-out is run again).
  checkFixture("infinite_loop", Case({1}, "time limit", 300, 1).crashes().only(kFewSpringChecks));
}

// Each allowance is counted once: a step that asks for forces without end, graded with a time
// budget of 15 s, takes the build, those 15 s and the grader's own work; with a budget of 30 s it
// took 142 s when the force allowance was handed on as the next request's limit and added again.
// The budget is a deadline, so the checks stage ends soon after its 15 s (the probes' start
// before them, the refusals and replays after them: a fraction of a second idle, a few seconds
// beside CI's load); its own seconds, in results.json, show it.
TEST(Hostile, AsksForForcesWithoutEnd) {
  const double budget = 15;
  const fs::path dir = caseDir("endless_forces");
  const fs::path submission = stage(dir / "submission", "endless_forces");
  const Graded g =
      grade(submission, dir / "out", rubricFor(dir), "--time-budget " + std::to_string(budget));
  expectValidResults(g, 60, budget);
  const double checks = g.results["extra_data"]["seconds_by_stage"].value("checks", 1e9);
  EXPECT_LT(checks, budget + 10) << "the checks stage outlived the time budget\n" << describe(g);
  std::cout << "[ timing ] endless forces: " << g.seconds << " s in all, " << checks
            << " s of checks, " << g.cpuSeconds << " s of CPU, --time-budget " << budget << "\n";
  int task3Failed = 0;
  for (const auto& [check, outcome] : g.results["extra_data"]["tests"].items()) {
    if (check.rfind("Task3", 0) == 0 && outcome == "failed") ++task3Failed;
  }
  EXPECT_GT(task3Failed, 0) << "the endless step costs task 3";
}

TEST(Hostile, ForksInItsCode) {
  const Outcome o = checkFixture("fork_in_code", {{}, ""});
  expectNoProcessLeft(o.dir);
}

TEST(Hostile, ForkBombBeforeMain) {
  const Outcome o = checkFixture("fork_bomb", {{}, "hostile: fork bomb over"});
  expectNoProcessLeft(o.dir);
}

TEST(Hostile, ChildEscapesTheProcessGroup) {
  const Outcome o = checkFixture("fork_escape", {{}, "hostile: forked"});
  expectNoProcessLeft(o.dir);
}

TEST(Hostile, HugeAllocation) { checkFixture("huge_alloc", Case({1}, "bad_alloc").crashes()); }

TEST(Hostile, HugeOutput) {
  const Outcome o = checkFixture("huge_output", {{}, "", 90});
  // Capped: the report keeps 64 KiB of what was printed; nothing large was written.
  EXPECT_LT(fs::file_size(o.dir / "out" / "results.json"), 1u << 20);
  EXPECT_LT(fs::file_size(o.dir / "out" / "report.html"), 4u << 20);
  const std::string report = readAll(o.dir / "out" / "report.html");
  // What the probe printed is a run of 'A's (the report's base64 images and replays hold 'A's
  // too, in short runs): at most the 64 KiB kept.
  std::size_t run = 0, longest = 0;
  for (const char c : report) longest = std::max(longest, run = c == 'A' ? run + 1 : 0);
  EXPECT_LT(longest, 80000u);
  std::uintmax_t written = 0;
  for (const auto& entry : fs::recursive_directory_iterator(o.dir / "out")) {
    if (entry.is_regular_file() && entry.path().extension() != ".o" &&
        entry.path().filename() != "a6_probe") {
      written += entry.file_size();
    }
  }
  EXPECT_LT(written, 8u << 20) << "bytes written besides the objects and the probe";
}

TEST(Hostile, Segfault) {
  checkFixture("segfault", Case({1}, "the probe crashed: killed by SIGSEGV").crashes());
}

TEST(Hostile, NaN) { checkFixture("nan", Case({1}, "actual:   (nan, nan)").crashes()); }

TEST(Hostile, ThrowsAnException) {
  const Outcome o =
      checkFixture("exception", Case({1}, "hostile: thrown from computeForce").crashes());
  // Its message of nearly 4 MiB, kept for each failed request, is cut where the answer is decoded
  // (to 4 KiB, WireResults.ALongErrorIsCutToItsFirst4KiB): 106 MiB instead of 1,960.
  EXPECT_LT(o.graded.results["extra_data"].value("grader_peak_rss_mib", 1e9), 300);
  // Every answer is decoded: none is refused for its size, unread.
  EXPECT_EQ(readAll(o.dir / "out" / "report.html").find("bytes announced"), std::string::npos);
}

TEST(Hostile, ExitsInItsCode) {
  checkFixture("exit_in_code", Case({1}, "the probe crashed: exited with 0").crashes());
}

TEST(Hostile, WritesOnTheAnswerPipe) {
  checkFixture("garbage_on_answer_pipe", Case({1}, "garbage from the probe").crashes());
}

// The probe's filter: on before any static initializer, not made of functions a submission can
// replace, on every thread (grader/probe/filter.h).
TEST(Hostile, ReplacesTheFilterFunctions) {
  const Outcome o = checkFixture("filter_override", {{}, "hostile: open refused"});
  EXPECT_EQ(readAll(o.dir / "out" / "report.html").find("hostile: READ"), std::string::npos);
}

// The reference forces stay in the grader, which answers them only to the probe of tasks 3 and
// 5: the spring that asks for them gets nothing.
TEST(Hostile, AsksTheGraderForTheReferenceSpringForce) {
  const Outcome o = checkFixture(
      "ask_reference_forces", Case({1}, "actual:   (nan, nan)").crashes().only(kFewSpringChecks));
  const std::string report = readAll(o.dir / "out" / "report.html");
  EXPECT_NE(report.find("hostile: no force channel"), std::string::npos);
  EXPECT_EQ(report.find("hostile: the grader answered"), std::string::npos);
}

TEST(Hostile, StartsAThreadBeforeMain) {
  const Outcome o = checkFixture("thread_before_main", {{}, "hostile: no thread before main"});
  const std::string report = readAll(o.dir / "out" / "report.html");
  EXPECT_EQ(report.find("hostile: READ"), std::string::npos);
  EXPECT_EQ(report.find("hostile: a thread runs"), std::string::npos);
}

TEST(Hostile, AnIfuncResolverRunsBeforeTheFilter) {
  checkFixture("ifunc_resolver", {{1}, "an ifunc symbol"});
}

TEST(Hostile, APreinitArrayEntryOfItsOwn) {
  checkFixture("preinit_entry", {{1}, "a .preinit_array section"});
}

// Answers the grader must not read whole: bounded before they are read and before they are
// parsed.
TEST(Hostile, AnnouncesAnAnswerOfTwoGigabytes) {
  const Outcome o = checkFixture("huge_answer", Case({1}, "over the limit").crashes());
  EXPECT_LT(o.graded.results["extra_data"].value("grader_peak_rss_mib", 1e9), 300);
}

TEST(Hostile, SendsTheCostliestAnswersToParse) {
  const Outcome o = checkFixture(
      "wide_answer", Case({1}, "garbage from the probe").crashes().only(kFewSpringChecks));
  const double peak = o.graded.results["extra_data"].value("grader_peak_rss_mib", 1e9);
  std::printf("[ hostile  ] a6_grade's peak RSS against maximal answers: %.1f MiB\n", peak);
  EXPECT_LT(peak, 300);
  // Each refused for what it is, before it was decoded (the checks' output says why).
  const std::string said = o.graded.results.dump();
  EXPECT_NE(said.find("garbage from the probe: an answer larger than"), std::string::npos);
  EXPECT_NE(said.find("garbage from the probe: an answer nested deeper than"), std::string::npos);
}

// The compiler sees an allow-list of the machine: not another readable checkout of the
// repository (a TA's), which no deny-list of the grader's own trees would cover.
TEST(Hostile, IncludesTheSolutionOfAnotherCheckout) {
  if (geteuid() != 0) GTEST_SKIP() << "only root hides the machine (mount namespaces)";
  // Beside the grader's trees, readable by everyone, as a TA's second checkout would be.
  const fs::path other = fs::path("/var/tmp/a6_other_checkout" + kSource.string());
  fs::create_directories(other / "solution");
  fs::copy_file(kSource / "solution" / "spring.cpp", other / "solution" / "spring.cpp",
                fs::copy_options::overwrite_existing);
  for (fs::path p = other; p != "/var/tmp"; p = p.parent_path()) {
    fs::permissions(p, fs::perms::others_read | fs::perms::others_exec, fs::perm_options::add);
  }
  checkFixture("include_other_checkout", {{1}, "actual:   (0, 0)"});
  fs::remove_all(other);
}

// The compiler sees no device but null, zero and urandom: it cannot be made to block.
TEST(Hostile, IncludesADevice) {
  checkFixture("include_device", {{1}, "spring.cpp did not compile", 90});
}

// A poisoner of another grading's (or left by one, its a6_grade killed with SIGKILL): a process
// of a sandbox user in a session of its own, named with a newline, that kills every process of
// its user in a loop. A grading beside it draws another user, gets full marks, and never
// signals it (it did not start it).
TEST(Hostile, APoisonerLeftByAnotherGradingCostsNothing) {
  if (geteuid() != 0) GTEST_SKIP() << "only root changes the sandbox's user";
  constexpr uid_t kUid = 64321;
  const pid_t poisoner = a6::test::startPoisoner(kUid);
  ASSERT_GT(poisoner, 0);
  const fs::path dir = caseDir("poisoner");
  const Graded g = grade(stage(dir / "submission", "", {}), dir / "out", rubricFor(dir));
  expectValidResults(g, 300);
  const Rubric rubric = a6::grader::loadRubric(rubricFor(dir));
  EXPECT_GE(g.results.value("score", -1.0), rubric.totalPoints) << "full marks\n" << g.output;
  EXPECT_EQ(waitpid(poisoner, nullptr, WNOHANG), 0)
      << "the grading signalled a process it did not start";
  kill(poisoner, SIGKILL);
  waitpid(poisoner, nullptr, 0);
}

// Broken, not hostile.
TEST(Broken, CompileErrorInOneFile) {
  checkFixture("compile_error", {{2}, "forces.cpp did not compile"});
}

TEST(Broken, MissingFile) {
  const auto omitted = a6::test::staging::omittedBy("missing_file");
  checkFixture("missing_file", {{4}, "cloth.cpp missing from the submission", 120, 0, omitted});
}

// Archives and links.
TEST(Hostile, ZipWithPathTraversal) { checkTraversal("zip_traversal", true); }

TEST(Hostile, TarWithPathTraversal) { checkTraversal("tar_traversal", false); }

TEST(Hostile, SymlinkInTheFolderToTheSolution) {
  ASSERT_TRUE(fs::is_symlink(kFixtures / "symlink_folder" / "spring.cpp"));
  const Outcome o = checkFixture("symlink_folder", {{1}, ""});
  const std::string output = o.graded.results.value("output", "");
  EXPECT_NE(output.find("Not found (the starter code was used): spring.cpp"), std::string::npos)
      << output;
  EXPECT_NE(output.find("link"), std::string::npos) << "the refused link is noted\n" << output;
}

TEST(Hostile, LinksInTheArchiveToTheSolution) {
  const fs::path dir = caseDir("symlink_archive");
  ASSERT_EQ(writeArchive(dir / "links.tar.gz", false, a6::test::staging::linkEntries()), "");
  const Outcome o = check("symlink_archive", dir, dir / "links.tar.gz", {{1, 2}, ""});
  const std::string output = o.graded.results.value("output", "");
  EXPECT_NE(output.find("Not found (the starter code was used): spring.cpp, forces.cpp"),
            std::string::npos)
      << output;
}

// Every fixture folder is graded by a case above.
TEST(Hostile, EveryFixtureHasACase) {
  const std::set<std::string> graded = {"fake_results",
                                        "fake_gtest_lines",
                                        "static_exit",
                                        "static_abort",
                                        "static_infinite_loop",
                                        "write_files",
                                        "include_solution",
                                        "include_goldens",
                                        "fopen_secrets",
                                        "filter_override",
                                        "ask_reference_forces",
                                        "thread_before_main",
                                        "ifunc_resolver",
                                        "preinit_entry",
                                        "huge_answer",
                                        "wide_answer",
                                        "include_device",
                                        "include_other_checkout",
                                        "infinite_loop",
                                        "endless_forces",
                                        "fork_in_code",
                                        "fork_bomb",
                                        "fork_escape",
                                        "huge_alloc",
                                        "huge_output",
                                        "segfault",
                                        "nan",
                                        "exception",
                                        "exit_in_code",
                                        "garbage_on_answer_pipe",
                                        "compile_error",
                                        "missing_file",
                                        "symlink_folder"};
  for (const auto& entry : fs::directory_iterator(kFixtures)) {
    if (entry.is_directory()) {
      EXPECT_TRUE(graded.count(entry.path().filename().string())) << entry.path();
    }
  }
  for (const std::string& name : graded) EXPECT_TRUE(fs::is_directory(kFixtures / name)) << name;
}

}  // namespace
