#include "checks/checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>

#include "checks/budgeted_student.h"
#include "checks/collector.h"
#include "checks/recording_student.h"
#include "checks/runs.h"
#include "golden_checks.h"
#include "gtest_flags.h"
#include "probe/probe_pair.h"
#include "suite.h"
#include "watched_student.h"

namespace fs = std::filesystem;

namespace a6::grader {
std::vector<std::string> failedChecks(const std::vector<TestOutcome>& tests) {
  std::vector<std::string> failed;
  for (const TestOutcome& t : tests) {
    if (!t.passed) failed.push_back(t.name);
  }
  return failed;
}

// The reference force models (tasks 1 and 2 solved; in a student release, empty: the student's
// own). They stay in this process: the probe of tasks 3 and 5 asks for each force over a pipe
// (harness/force_channel.h). In a namespace of this file's own, which no other file of its
// bundle sees (cmake/A6FastBuild.cmake, a6_bundled).
namespace checks_models {
#include A6_FORCE_MODELS
}  // namespace checks_models

namespace {

// Runs `step`; its failure becomes a note for the report ("<what> failed: ..."), never silence.
template <typename Step>
void noting(const char* what, std::vector<std::string>& notes, Step step) {
  try {
    step();
  } catch (const std::exception& e) {
    notes.push_back(std::string(what) + " failed: " + e.what());
  } catch (...) {
    notes.push_back(std::string(what) + " failed: an error of no known kind");
  }
}

constexpr std::size_t kProbeOutputCap = 64u << 10;  // what the report keeps of the probe's output

// The student's code while the checks run (a6::test::student()): the budgeted probe, recorded.
harness::StudentCode* gStudent = nullptr;

// Where a rubric item is written, for messages: "rubric.toml:45".
std::string placeOf(const Rubric& rubric, const RubricItem& item) {
  return rubric.file.string() + ":" + std::to_string(item.line);
}

void pinFlags(std::uint64_t seed, const std::string& filter) {
  A6_GTEST_FLAG_SET(filter, filter.empty() ? std::string("*") : filter);
  A6_GTEST_FLAG_SET(also_run_disabled_tests, false);
  A6_GTEST_FLAG_SET(shuffle, false);
  A6_GTEST_FLAG_SET(repeat, 1);
  A6_GTEST_FLAG_SET(fail_fast, false);
  A6_GTEST_FLAG_SET(break_on_failure, false);
  A6_GTEST_FLAG_SET(throw_on_failure, false);
  A6_GTEST_FLAG_SET(catch_exceptions, true);
  A6_GTEST_FLAG_SET(output, std::string());
  A6_GTEST_FLAG_SET(brief, true);
  // GoogleTest's seed (1..99999), for checks that draw their inputs at random.
  A6_GTEST_FLAG_SET(random_seed, static_cast<std::int32_t>(seed % 99999 + 1));
}

// The two probes as one StudentCode, each started as the sandbox's user with the probe's view.
std::unique_ptr<ProbePair> startProbes(const ChecksInput& in) {
  auto client = [&](const fs::path& program, const char* runDir) {
    auto c = std::make_unique<ProbeClient>(program, in.work / runDir, Limits{});
    const SandboxView view = probeView(in.secrets);
    c->setHidden(view.hide, view.reveal);
    c->setUser(in.uid, in.gid);
    return c;
  };
  std::unique_ptr<ProbeClient> models = client(in.modelsProbe, "run-models");
  models->serveForces(checks_models::referenceForceModel());
  return std::make_unique<ProbePair>(client(in.probe, "run"), std::move(models));
}

// RUN_ALL_TESTS with a Collector into `tests`; how many checks were skipped.
int runAll(const Rubric& rubric, std::vector<TestOutcome>& tests, BudgetedStudent& student,
           bool progress) {
  Collector collector(
      rubric, tests, [&student](double limit) { student.startTest(limit); },
      [&student](TestOutcome& t) {
        t.machineMayHaveEndedIt = student.machineMayHaveEndedIt();
        t.graderFailedIt = student.graderFailedIt();
      },
      progress);
  // Appended for this run only, released however it ends (GoogleTest would delete it).
  struct Listening {
    ::testing::TestEventListeners& listeners;
    Collector& collector;
    ~Listening() { listeners.Release(&collector); }
  } listening{::testing::UnitTest::GetInstance()->listeners(), collector};
  listening.listeners.Append(&collector);
  // Its status only repeats what the collector saw.
  if (RUN_ALL_TESTS() != 0 && progress) std::fprintf(stderr, "a6_grade: some checks failed\n");
  return collector.skipped();
}

// The failed checks that the machine may have ended (a time limit, a probe killed or that did
// not start, a grader error) run again, once, while the time budget lasts: only a failure that
// repeats is charged, named for what it is. One that the grader alone failed twice makes the
// grading the machine's failure (an error: a6_batch grades it again), never a silent 0.
void runAgainWhatTheMachineEnded(const Rubric& rubric, const std::string& filter, ChecksRun& run,
                                 BudgetedStudent& student, bool progress) {
  std::string again;
  int count = 0;
  for (const TestOutcome& t : run.tests) {
    if (t.passed || !t.machineMayHaveEndedIt) continue;
    // As a filter pattern: '-' would start the negative patterns, ':' the next one.
    std::string pattern = t.name;
    std::replace_if(
        pattern.begin(), pattern.end(), [](char c) { return c == '-' || c == ':'; }, '?');
    again += (again.empty() ? "" : ":") + pattern;
    ++count;
  }
  if (count == 0 || student.budgetLeft() < 1) return;
  A6_GTEST_FLAG_SET(filter, again);
  std::vector<TestOutcome> second;
  runAll(rubric, second, student, progress);
  A6_GTEST_FLAG_SET(filter, filter.empty() ? std::string("*") : filter);
  int passed = 0;
  for (TestOutcome& t : second) {
    passed += t.passed ? 1 : 0;
    t.ranAgain = true;
    for (TestOutcome& first : run.tests) {
      if (first.name == t.name) first = std::move(t);
    }
  }
  run.notes.push_back(std::to_string(count) +
                      " checks were run again because the machine may have ended them (a time "
                      "limit, a probe killed or not started): " +
                      std::to_string(passed) + " passed the second time");
}

// A check the grader alone failed (twice, or once with no time left to run it again): the
// grading cannot stand.
void flagMachineFailures(ChecksRun& run) {
  for (const TestOutcome& t : run.tests) {
    if (t.passed || !t.graderFailedIt) continue;
    run.errors.push_back("regrade: the grading machine failed (" + t.name +
                         ": the probe could not be started or the grader erred, " +
                         (t.ranAgain ? "twice)" : "and no time was left to run it again)"));
    return;
  }
}

// What the probes did, for the report.
void collectIncidents(const ProbePair& pair, BudgetedStudent& student, ChecksRun& run) {
  run.probeOutput = pair.output(kProbeOutputCap);
  for (const std::string& note : pair.notes()) run.notes.push_back("sandbox: " + note);
  const ProbeIncidents incidents = pair.incidents();
  run.incidents.crashes = incidents.crashes;
  run.incidents.timeouts = student.checksOutOfTime();
  run.incidents.startFailures = incidents.startFailures;
  if (pair.restarts() > 0) {
    run.notes.push_back("the probes were restarted " + std::to_string(pair.restarts()) +
                        " times (after crashes or time limits)");
  }
}

}  // namespace

void registerChecks(std::uint64_t seed, const std::string& filter, const fs::path& imagesDir,
                    bool inReportOnly) {
  static char program[] = "a6_grade";
  static char* argv[] = {program, nullptr};
  int argc = 1;
  ::testing::InitGoogleTest(&argc, argv);
  pinFlags(seed, filter);
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());
  a6::test::registerGoldenChecks(imagesDir.string(), inReportOnly
                                                         ? a6::test::ImagePaths::InTheReportOnly
                                                         : a6::test::ImagePaths::Shown);
}

std::vector<std::string> registeredChecks() {
  std::vector<std::string> names;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int s = 0; s < unit.total_test_suite_count(); ++s) {
    const ::testing::TestSuite& suite = *unit.GetTestSuite(s);
    for (int t = 0; t < suite.total_test_count(); ++t) {
      names.push_back(std::string(suite.name()) + "." + suite.GetTestInfo(t)->name());
    }
  }
  return names;
}

std::vector<std::string> coverageProblems(const Rubric& rubric) {
  std::vector<int> used(rubric.items.size(), 0);
  std::vector<std::string> problems;
  for (const std::string& name : registeredChecks()) {
    const int item = rubric.itemFor(name);
    if (item >= 0) {
      ++used[static_cast<std::size_t>(item)];
    } else {
      problems.push_back("the check " + name +
                         " matches no item's 'tests': it would score nothing (add a glob that "
                         "matches it to an item)");
    }
  }
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i] > 0) continue;
    const RubricItem& item = rubric.items[i];
    problems.push_back(placeOf(rubric, item) + ": item '" + item.name +
                       "' matches no check, so its points could never be earned (fix its "
                       "'tests'; a6_grade --list-tests lists the checks)");
  }
  return problems;
}

int listChecks(const Rubric& rubric) {
  if (!rubric.ok()) {
    std::fprintf(stderr, "a6_grade: the rubric is invalid:\n%s\n", rubric.error.c_str());
    return 1;
  }
  for (const std::string& name : registeredChecks()) {
    const int item = rubric.itemFor(name);
    std::printf("%s\t%s\n", name.c_str(),
                item < 0 ? "-" : rubric.items[static_cast<std::size_t>(item)].name.c_str());
  }
  const std::vector<std::string> problems = coverageProblems(rubric);
  for (const std::string& p : problems) std::fprintf(stderr, "a6_grade: %s\n", p.c_str());
  return problems.empty() ? 0 : 1;
}

int listItems(const Rubric& rubric) {
  if (!rubric.ok()) {
    std::fprintf(stderr, "a6_grade: the rubric is invalid:\n%s\n", rubric.error.c_str());
    return 1;
  }
  std::vector<int> counted(rubric.items.size(), 0);
  for (const std::string& name : registeredChecks()) {
    const int item = rubric.itemFor(name);
    if (item >= 0) ++counted[static_cast<std::size_t>(item)];
  }
  double extra = 0;
  for (std::size_t i = 0; i < rubric.items.size(); ++i) {
    const RubricItem& item = rubric.items[i];
    if (item.extraCredit) extra += item.points;
    std::printf("%s\t%g\t%d\t%s\t%s\n", item.name.c_str(), item.points, counted[i],
                item.extraCredit ? "extra" : "regular", toString(item.visibility));
  }
  std::printf("total\t%g\t%zu\t%g\n", rubric.totalPoints, registeredChecks().size(), extra);
  return 0;
}

int checkRubricAgainstChecks(const Rubric& rubric) {
  if (!rubric.ok()) {
    std::fprintf(stderr, "a6_grade: the rubric is invalid:\n%s\n", rubric.error.c_str());
    return 2;
  }
  const std::vector<std::string> problems = coverageProblems(rubric);
  for (const std::string& p : problems) std::fprintf(stderr, "a6_grade: %s\n", p.c_str());
  if (!problems.empty()) return 2;
  double extra = 0;
  int hidden = 0;
  for (const RubricItem& item : rubric.items) {
    if (item.extraCredit) extra += item.points;
    if (item.visibility != Visibility::Visible) ++hidden;
    // Gradescope hides a student's total while any test is unseen, except tests marked hidden
    // ("they should only be used for tests which don't contribute points").
    if (item.visibility == Visibility::Hidden && item.points > 0) {
      std::fprintf(stderr,
                   "a6_grade: warning: %s: item '%s' is 'hidden' and has points: Gradescope "
                   "shows students their total all the same, so these points show in it (use "
                   "after_due_date or after_published to keep them unseen)\n",
                   placeOf(rubric, item).c_str(), item.name.c_str());
    }
  }
  std::printf(
      "%s: valid: %zu items (%d shown to students only later), %g points + %g extra "
      "credit, %zu checks, each counted by an item\n",
      rubric.file.string().c_str(), rubric.items.size(), hidden, rubric.totalPoints, extra,
      registeredChecks().size());
  return 0;
}

namespace {

// After every check has been collected, while the probe is up: what the report adds (so none of
// it can change a score). The incidents first; then the replays, the diagnosis's designed inputs
// and the failed stepping checks' first divergences.
void afterTheChecks(const ChecksInput& in, ProbePair* probes, BudgetedStudent& student,
                    const RecordingStudent& recorded, ChecksRun& run) {
  noting("counting the incidents", run.notes, [&] {
    if (probes != nullptr) collectIncidents(*probes, student, run);
  });
  // A student release has no reference replays, and so no replays.
  noting("running the replays", run.notes, [&] {
    run.replayFolder = a6::test::replayFolder();
    if (in.replays && fs::is_directory(run.replayFolder)) {
      run.replays = runReplays(student, a6::test::imagedScenes());
      run.particleTrajectories =
          runParticleTrajectories(student, recorded.transcript(), failedChecks(run.tests));
    }
  });
  noting("asking the diagnosis's inputs", run.notes,
         [&] { run.measured = askDesigned(student, in.designed); });
  noting("finding the first divergences", run.notes, [&] {
    run.divergences =
        findDivergences(student, recorded.transcript(), failedChecks(run.tests), in.reference);
  });
}

}  // namespace

ChecksRun runChecks(const ChecksInput& in, const Rubric& rubric) {
  ChecksRun run;
  std::string unavailable = in.unavailable;
  std::unique_ptr<ProbePair> probes;
  if (unavailable.empty() && in.linked == nullptr) {
    try {
      probes = startProbes(in);
    } catch (const std::exception& e) {
      run.errors.push_back(std::string("starting the probe failed: ") + e.what());
      unavailable = "the grader could not start your code (a grader problem, not yours)";
    }
  }
  harness::StudentCode* code = in.linked != nullptr ? in.linked : probes.get();
  BudgetedStudent student(code, probes.get(), unavailable);
  student.setTotalBudget(in.timeBudget);
  RecordingStudent recorded(student);
  a6::test::WatchedStudent watched(recorded);
  gStudent = &watched;
  int skipped = 0;
  try {
    skipped = runAll(rubric, run.tests, student, in.progress);
    runAgainWhatTheMachineEnded(rubric, in.filter, run, student, in.progress);
    flagMachineFailures(run);
  } catch (const std::exception& e) {
    run.errors.push_back(std::string("running the checks failed: ") + e.what());
  }
  if (!student.startError().empty()) {
    run.errors.push_back(
        "the sandbox could not start the probe, so checks failed that may not "
        "have: " +
        student.startError());
  }
  if (skipped > 0) {
    run.errors.push_back(std::to_string(skipped) +
                         " checks were skipped (the grader's environment could not run them; see "
                         "each check's message): they earned nothing");
  }
  if (code != nullptr) afterTheChecks(in, probes.get(), student, recorded, run);
  gStudent = nullptr;
  run.transcript = recorded.takeTranscript();
  return run;
}

}  // namespace a6::grader

namespace a6::test {
harness::StudentCode& student() { return *a6::grader::gStudent; }
}  // namespace a6::test
