// a6_grade: grades one submission (grader/DESIGN.md).
//
//   a6_grade SUBMISSION --out DIR [--rubric FILE] [--seed N] [--kit FILE] [--jobs N]
//            [--time-budget S] [--tests FILTER] [--hide PATH]... [--sandbox-uid UID]
//            [--quiet] [--color]
//   a6_grade --list-tests [--rubric FILE]
//   a6_grade --check-rubric [--rubric FILE]
//
// Stages: intake -> build -> run the physics suite (and the golden-image checks) in this process
// against the sandboxed probe -> score with the rubric -> DIR/results.json (Gradescope),
// DIR/report.html, a summary on stdout. Student code never runs in this process: the suite's
// a6::test::student() is the probe.
//
// Exit status: 0 when grading completed, whatever the score (a submission that does not build
// gets its zero with the reasons in the report); 1 when the grader itself failed (missing kit,
// an environment that cannot run the checks, a report that could not be written): results.json
// is still written, with score 0 and the error; 2, before any build, when there is nothing to
// grade (a bad command line, no such submission, no task file in it, an archive that cannot be
// read) or the rubric cannot be used (invalid, or not matching the checks).
#include <gtest/gtest.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "comparisons.h"
#include "gtest_flags.h"
#include "harness/student_code.h"
#include "process.h"
#include "report.h"
#include "rubric.h"
#include "suite.h"

#ifdef A6_GRADE_HAVE_INTAKE
#include "intake.h"
#endif
#ifdef A6_GRADE_HAVE_BUILD
#include "build.h"
#endif
#ifdef A6_GRADE_HAVE_PROBE
#include "probe_client.h"
#endif
#ifdef A6_GRADE_HAVE_GOLDEN
// The golden-image checks, when tests/golden provides them for the grader (target
// a6_golden_checks): registerGoldenChecks(failuresDir) registers GoldenTask<N>.<image> tests that
// run scenes through a6::test::student() and render and compare here; a failing one records the
// properties student_image, reference_image and difference_image (paths of PNGs it wrote).
#include "golden_checks.h"
#endif

#ifndef A6_DEFAULT_RUBRIC
#define A6_DEFAULT_RUBRIC "rubric.toml"
#endif

namespace fs = std::filesystem;
using namespace a6;
using namespace a6::grader;

namespace {

#ifdef A6_FORCE_MODELS
// The reference force models (tasks 1 and 2 solved; in a student release, empty: the student's
// own). They stay in this process: the probe of tasks 3 and 5 asks for each force over a pipe
// (harness/force_channel.h).
#include A6_FORCE_MODELS
#else
a6::ForceModel referenceForceModel() { return {}; }
#endif

using Clock = std::chrono::steady_clock;

constexpr double kDefaultTimeLimit = 10;            // s, for a test that matches no item
constexpr std::size_t kProbeOutputCap = 64u << 10;  // what the report keeps of the probe's output
// A check whose requests crash the probe (or run out of time) gets this many probe starts; its
// other requests then fail at once. So code that crashes on every call costs its own checks,
// not the probe's restarts for every task after it.
constexpr int kStartsPerCheck = 3;
// How long a probe may take to reach main and answer a request that runs no student code.
constexpr double kStartupSeconds = 5;
// The time the student's code may take over all checks together (--time-budget), s: well within
// Gradescope's default of 10 minutes for the whole run, which would otherwise end it with a 0.
constexpr double kDefaultTimeBudget = 420;

// The student's code as the suite sees it in the grader: the probe, within the running test's
// time budget. Without a probe (the build failed) every request fails with the reason, so each
// check fails with a message instead of the grader stopping.
class BudgetedStudent final : public harness::StudentCode {
 public:
  /// `newCheck` runs when a check starts (it gives the probe client the check's restarts).
  BudgetedStudent(harness::StudentCode* probe, std::function<void(double)> setTimeout,
                  std::function<void()> newCheck, std::string unavailable)
      : probe_(probe),
        setTimeout_(std::move(setTimeout)),
        newCheck_(std::move(newCheck)),
        unavailable_(std::move(unavailable)) {}

  /// Why the probe could not be started at all (a grader problem), or "".
  const std::string& startError() const { return startError_; }

  /// All checks together may use `seconds` of the student's code's time, from now on.
  void setTotalBudget(double seconds) {
    budget_ = seconds;
    budgetEnd_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(seconds));
  }

  /// Counts the forces the grader answered the probe (ProbePair::forceAnswers): a check gets
  /// forceWaitAllowance for them on top of its time limit.
  void setForceAnswers(std::function<std::size_t()> forceAnswers) {
    forceAnswers_ = std::move(forceAnswers);
  }

  /// A new check starts: its requests share `seconds` of wall-clock time (plus the allowance for
  /// the forces the grader answers meanwhile).
  void startTest(double seconds) {
    limit_ = seconds;
    answersAtStart_ = forceAnswers_ ? forceAnswers_() : 0;
    deadline_ = Clock::now() +
                std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    lastFailure_.clear();
    closeCheck();
    if (newCheck_) newCheck_();
  }

  /// How the probes' stopped requests are counted (ProbePair::incidents().timeouts).
  void setProbeTimeouts(std::function<int()> probeTimeouts) {
    probeTimeouts_ = std::move(probeTimeouts);
  }

  /// How many checks ran out of their time (a request stopped at its limit, or the check's
  /// limit reached between requests), each counted once, plus one when the time budget of all
  /// checks was spent.
  int checksOutOfTime() {
    closeCheck();
    return checksOutOfTime_ + (budgetSpent_ ? 1 : 0);
  }

  harness::SpringForceResult springForce(const harness::SpringForceRequest& r) override {
    return call<harness::SpringForceResult>([&] { return probe_->springForce(r); });
  }
  harness::ForcesResult forces(const harness::ForcesRequest& r) override {
    return call<harness::ForcesResult>([&] { return probe_->forces(r); });
  }
  harness::SimulateResult simulate(const harness::SimulateRequest& r) override {
    return call<harness::SimulateResult>([&] { return probe_->simulate(r); });
  }
  harness::ClothResult buildCloth(const ClothSpec& s) override {
    return call<harness::ClothResult>([&] { return probe_->buildCloth(s); });
  }
  harness::ParticlesResult emit(const harness::EmitRequest& r) override {
    return call<harness::ParticlesResult>([&] { return probe_->emit(r); });
  }
  harness::ParticlesResult runParticles(const harness::ParticleRunRequest& r) override {
    return call<harness::ParticlesResult>([&] { return probe_->runParticles(r); });
  }
  harness::Box2DResult runBox2D(const harness::Box2DRequest& r) override {
    return call<harness::Box2DResult>([&] { return probe_->runBox2D(r); });
  }
  harness::SceneResult runScene(const harness::SceneRequest& r) override {
    return call<harness::SceneResult>([&] { return probe_->runScene(r); });
  }

 private:
  template <class Result, class Call>
  Result call(Call&& forward) {
    Result result;
    if (probe_ == nullptr) {
      result.error = unavailable_;
      return result;
    }
    const double overall = std::chrono::duration<double>(budgetEnd_ - Clock::now()).count();
    if (overall < 0.01) {
      std::ostringstream out;
      out << "not run: the checks before it used up the time all checks together may take ("
          << budget_ << " s; their messages say which ran out of time)";
      result.error = out.str();
      budgetSpent_ = true;
      return result;
    }
#ifdef A6_GRADE_HAVE_PROBE
    const double allowance =
        forceAnswers_ ? forceWaitAllowance(forceAnswers_() - answersAtStart_, limit_) : 0;
#else
    const double allowance = 0;
#endif
    double remaining = std::chrono::duration<double>(deadline_ - Clock::now()).count() + allowance;
    if (remaining < 0.01) {
      std::ostringstream out;
      out << "this check's time limit of " << limit_
          << " s ran out (is there an endless loop, or a loop that runs far too often?)";
      result.error = out.str();
      outOfTime_ = true;
      return result;
    }
    remaining = std::min(remaining, overall);
    if (setTimeout_) setTimeout_(remaining);
    try {
      result = forward();
      // The probe client's own words (never the probe's): the sandbox could not start it.
      if (result.error.rfind("could not start the probe", 0) == 0 && startError_.empty()) {
        startError_ = result.error;
      }
      // This check used up its probe starts: say why, in the check's terms.
      if (result.error.rfind("the probe was started ", 0) == 0) {
        result.error = "your code crashed or ran out of time " + std::to_string(kStartsPerCheck) +
                       " times in this check, so its other requests were not run" +
                       (lastFailure_.empty() ? "" : "; the last time: " + lastFailure_);
      } else if (!result.error.empty()) {
        lastFailure_ = result.error;
      }
      return result;
    } catch (const std::exception& e) {
      result.error = std::string("the grader could not run your code: ") + e.what();
    } catch (...) {
      result.error = "the grader could not run your code (unknown error)";
    }
    return result;
  }

  harness::StudentCode* probe_;
  std::function<void(double)> setTimeout_;
  std::function<void()> newCheck_;
  std::string unavailable_;
  std::string lastFailure_;  // the last failed request of the running check
  std::string startError_;
  // The running check ran out of its time between requests; the probes' time-outs when it began.
  bool outOfTime_ = false;
  int timeoutsAtStart_ = 0;
  int checksOutOfTime_ = 0;
  bool budgetSpent_ = false;
  std::function<int()> probeTimeouts_;

  // Counts the check that just ended if it ran out of time, once however many of its requests
  // did.
  void closeCheck() {
    const int timeouts = probeTimeouts_ ? probeTimeouts_() : 0;
    if (outOfTime_ || timeouts > timeoutsAtStart_) ++checksOutOfTime_;
    timeoutsAtStart_ = timeouts;
    outOfTime_ = false;
  }
  double limit_ = kDefaultTimeLimit;
  Clock::time_point deadline_ = Clock::now();
  std::function<std::size_t()> forceAnswers_;
  std::size_t answersAtStart_ = 0;
  double budget_ = kDefaultTimeBudget;
  Clock::time_point budgetEnd_ = Clock::time_point::max();
};

BudgetedStudent* gStudent = nullptr;

#ifdef A6_GRADE_HAVE_PROBE
// What the probe sees (an allow-list, grader/sandbox.h): the system's libraries, /proc, the
// devices null, zero and urandom, and its own program and work folder; nothing else of the
// machine: not the grader's trees (`secrets`, named first where nothing can be hidden), not the
// rest of the work folder (the rendered images), not /tmp or any folder others may write to.
SandboxView viewOfProbe(const std::vector<fs::path>& secrets) { return allowOnly({}, secrets); }
#endif

#ifdef A6_GRADE_HAVE_PROBE
// Whether a probe reaches main and serves: "" when it answers, twice, a request that runs no
// student code (a scene request with an invalid frame, refused before any scene is made);
// otherwise why not (it crashed, exited or hung before main: a static initializer, typically).
std::string startupFailure(const fs::path& probe, const fs::path& runDir, const SandboxView& view,
                           uid_t uid, gid_t gid) {
  ProbeClient client(probe, runDir, Limits{});
  client.setHidden(view.hide, view.reveal);
  client.setUser(uid, gid);
  client.setRequestTimeout(kStartupSeconds);
  client.setMaxStarts(1);
  harness::SceneRequest ping;
  ping.frames = {-1};
  for (int k = 0; k < 2; ++k) {
    const harness::SceneResult r = client.runScene(ping);
    if (r.error.rfind("runScene: frame -1", 0) == 0) continue;
    if (r.error.rfind("your code took longer", 0) == 0) {
      std::ostringstream out;
      out << "it did not reach main within " << kStartupSeconds << " s (is there an endless "
          << "loop in code that runs before main, such as a static initializer?)";
      return out.str();
    }
    return r.error.empty() ? "it answered a request it must refuse" : r.error;
  }
  return "";
}
#endif

// Records every test's outcome, from GoogleTest's events, and gives each test its time limit.
class Collector : public ::testing::EmptyTestEventListener {
 public:
  Collector(const Rubric& rubric, std::vector<TestOutcome>& out, bool progress)
      : rubric_(rubric), out_(out), progress_(progress) {}

  int skipped() const { return skipped_; }

  void OnTestStart(const ::testing::TestInfo& info) override {
    current_ = TestOutcome{};
    current_.name = std::string(info.test_suite_name()) + "." + info.name();
    skipMessage_.clear();
    const int item = rubric_.itemFor(current_.name);
    const double limit = item >= 0 ? rubric_.items[static_cast<std::size_t>(item)].timeLimitSeconds
                                   : kDefaultTimeLimit;
    if (gStudent != nullptr) gStudent->startTest(limit);
  }

  void OnTestPartResult(const ::testing::TestPartResult& part) override {
    if (part.skipped()) {
      skipMessage_ += part.message();
      return;
    }
    if (!part.failed()) return;
    if (!current_.message.empty()) current_.message += "\n";
    current_.message += part.message();
  }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    const ::testing::TestResult& result = *info.result();
    current_.seconds = static_cast<double>(result.elapsed_time()) / 1000.0;
    if (result.Skipped()) {
      // A skipped check is the grader's environment failing (no GL for the images, say): it
      // earns nothing, and the run reports a grader error.
      ++skipped_;
      current_.passed = false;
      current_.message = "not run: " + (skipMessage_.empty() ? "skipped" : skipMessage_) +
                         (current_.message.empty() ? "" : "\n" + current_.message);
    } else {
      current_.passed = result.Passed();
    }
    // Kept only beyond double rounding: the report's float note reads it (comparisons.h).
    const double agreement = a6::test::comparisonsOf(info).agreement;
    current_.agreement = agreement > a6::test::kBeyondDoubleRounding ? agreement : 0;
    // Golden-image checks name their images (student, reference, difference) as properties.
    std::string images[3];
    for (int k = 0; k < result.test_property_count(); ++k) {
      const ::testing::TestProperty& p = result.GetTestProperty(k);
      const std::string key = p.key();
      if (key == "student_image" || key == "actual_image") images[0] = p.value();
      if (key == "reference_image" || key == "expected_image") images[1] = p.value();
      if (key == "difference_image" || key == "diff_image") images[2] = p.value();
    }
    if (!images[0].empty()) {
      for (const std::string& image : images) {
        if (!image.empty()) current_.images.push_back(image);
      }
    }
    if (progress_) {
      std::fprintf(stderr, "  %-6s %s (%.2f s)\n", current_.passed ? "ok" : "FAILED",
                   current_.name.c_str(), current_.seconds);
    }
    out_.push_back(std::move(current_));
  }

 private:
  const Rubric& rubric_;
  std::vector<TestOutcome>& out_;
  bool progress_;
  TestOutcome current_;
  std::string skipMessage_;
  int skipped_ = 0;
};

// The names of every registered test, in run order.
std::vector<std::string> registeredTests() {
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

// GoogleTest with pinned flags: nothing from the environment (GTEST_FILTER, ...) changes what
// runs, and its own printer stays quiet (the summary is ours).
void initGoogleTest(std::uint64_t seed, const std::string& filter) {
  static char program[] = "a6_grade";
  static char* argv[] = {program, nullptr};
  int argc = 1;
  ::testing::InitGoogleTest(&argc, argv);
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
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());
}

// The default seed: a hash of the six files taken, so the same submission always gets the same
// inputs and a different one cannot know its own in advance.
std::uint64_t seedOf(const std::map<std::string, fs::path>& files) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  auto mix = [&h](const std::string& bytes) {
    for (const unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  };
  for (const auto& [name, path] : files) {
    mix(name);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    mix(text.str());
  }
  return h % 1000000007ull;  // short enough to type in a regrade
}

fs::path besideProgram(const std::string& name) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path(name) : self.parent_path() / name;
}

fs::path defaultRubric() {
  if (fs::exists(A6_DEFAULT_RUBRIC)) return A6_DEFAULT_RUBRIC;
  return besideProgram("rubric.toml");
}

// Where a rubric item is written, for messages: "rubric.toml:45".
std::string placeOf(const Rubric& rubric, const RubricItem& item) {
  return rubric.file.string() + ":" + std::to_string(item.line);
}

// What makes a valid rubric unusable with the checks this a6_grade holds: an item that matches
// no check (its points could never be earned) and a check that matches no item (it would score
// nothing). One line each, with the place and the fix; empty when every check counts.
std::vector<std::string> coverageProblems(const Rubric& rubric) {
  std::vector<int> used(rubric.items.size(), 0);
  std::vector<std::string> problems;
  for (const std::string& name : registeredTests()) {
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

// --list-tests: every check and the item it counts for; 1 when some check or item is unmatched.
int listTests(const Rubric& rubric) {
  if (!rubric.ok()) {
    std::fprintf(stderr, "a6_grade: the rubric is invalid:\n%s\n", rubric.error.c_str());
    return 1;
  }
  for (const std::string& name : registeredTests()) {
    const int item = rubric.itemFor(name);
    std::printf("%s\t%s\n", name.c_str(),
                item < 0 ? "-" : rubric.items[static_cast<std::size_t>(item)].name.c_str());
  }
  const std::vector<std::string> problems = coverageProblems(rubric);
  for (const std::string& p : problems) std::fprintf(stderr, "a6_grade: %s\n", p.c_str());
  return problems.empty() ? 0 : 1;
}

// --check-rubric: the rubric read and matched against every check, before anything is graded.
// 0 and a one-line summary when it can be used; 2 and each problem (place and fix) when not.
int checkRubric(const Rubric& rubric) {
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
      registeredTests().size());
  return 0;
}

struct Options {
  std::string submission;
  std::string out;
  std::string rubric;
  std::string kit;
  std::vector<std::string> hide;    // more secrets: a batch's other submissions and results
  std::optional<uid_t> sandboxUid;  // who compiles and runs the probe, as root (default: a
                                    // free uid claimed for this grading, grader/process.h)
  std::optional<std::uint64_t> seed;
  int jobs = 2;  // files compiled at once
  double timeBudget = kDefaultTimeBudget;
  std::string filter;
  bool listTests = false;
  bool checkRubric = false;
  std::string publicRubric;
  bool quiet = false;
  bool color = false;
};

#if defined(A6_GRADE_HAVE_BUILD) && defined(A6_GRADE_HAVE_PROBE)
// Code that runs before main (static initializers) can keep the whole probe from serving: an
// exit(), an abort(), a crash or an endless loop there would fail every check of every task.
// So the probe must first start up (startupFailure); if it does not, each compiled file is tried
// alone among the starter's objects, and the files whose probe does not start are replaced by
// the starter's: they cost their own task, as a file that does not compile does. Returns why no
// probe can serve at all (every check then fails at once with that reason), or "".
std::string checkStartup(const Kit& kit, GradeReport& report, const fs::path& work,
                         const std::vector<fs::path>& secrets) {
  const SandboxView view = viewOfProbe(secrets);
  const std::string failure =
      startupFailure(report.build.probe, work / "startup", view, kit.uid, kit.gid);
  if (failure.empty()) return "";

  // Each compiled file alone among the starter's objects: relinked, never compiled again.
  std::set<std::string> compiled;
  for (const TaskBuild& task : report.build.tasks) {
    if (task.status == TaskBuild::Status::Compiled) compiled.insert(task.file);
  }
  std::map<std::string, std::string> culprits;  // task file -> why its probe did not start
  for (const std::string& file : compiled) {
    std::set<std::string> others = compiled;
    others.erase(file);
    const fs::path dir = work / "startup" / fs::path(file).stem();
    const Build solo = relinkProbe(kit, report.build, others, dir / "build");
    if (!solo.ok()) continue;
    const std::string why = startupFailure(solo.probe, dir / "run", view, kit.uid, kit.gid);
    if (!why.empty()) culprits[file] = why;
  }
  const std::string whole =
      "the program built from your files did not start: " + failure +
      "\n(Code that runs before main, such as the initializer of a global or static variable, "
      "must not exit, abort, crash or loop.)";
  if (culprits.empty()) return whole;  // only the files together fail: nothing to single out

  std::set<std::string> starterFor;
  for (const auto& [file, why] : culprits) starterFor.insert(file);
  Build rebuilt =
      relinkProbe(kit, report.build, starterFor, work / "build-without-startup-failures");
  if (!rebuilt.ok()) return whole;
  for (std::size_t i = 0; i < rebuilt.tasks.size() && i < report.build.tasks.size(); ++i) {
    TaskBuild& task = rebuilt.tasks[i];
    const auto culprit = culprits.find(task.file);
    if (culprit == culprits.end()) continue;
    task = report.build.tasks[i];
    task.status = TaskBuild::Status::LinkError;
    task.messages += task.file +
                     " compiled, but the program built with it did not start: " + culprit->second +
                     "\nCode that runs before main, such as the initializer of a global or static "
                     "variable, must not exit, abort, crash or loop. Task " +
                     std::to_string(i + 1) + " is graded with the starter's stub.\n";
  }
  rebuilt.seconds += report.build.seconds;
  report.build = rebuilt;
  if (const std::string still =
          startupFailure(report.build.probe, work / "startup", view, kit.uid, kit.gid);
      !still.empty()) {
    return "the program built from your files did not start, even with the starter's code in "
           "place of the files that kept it from starting: " +
           still;
  }
  return "";
}
#endif

// As root, the sandbox runs the compiler and the probe as a user claimed for this grading, in
// the group nogroup: they must be able to enter every folder down to the work folder. Such a
// user has no account, so what it may enter is what "others" may.
constexpr uid_t kNobody = 65534;
constexpr gid_t kSandboxGid = 65534;

bool enterableBy(const fs::path& dir, uid_t uid, gid_t gid) {
  for (fs::path p = dir;; p = p.parent_path()) {
    struct stat st;
    if (stat(p.c_str(), &st) == 0) {
      const mode_t x = st.st_uid == uid ? S_IXUSR : st.st_gid == gid ? S_IXGRP : S_IXOTH;
      if ((st.st_mode & x) == 0) return false;
    }
    if (p.empty() || p == p.root_path()) return true;
  }
}

// A fresh scratch folder that the sandbox's user can enter, or "" when none can be made.
fs::path enterableScratch() {
  std::error_code ec;
  fs::path base = fs::temp_directory_path(ec);
  if (ec || !enterableBy(base, kNobody, kSandboxGid)) base = "/tmp";
  std::string name = (base / "a6_grade.XXXXXX").string();
  if (mkdtemp(name.data()) == nullptr) return {};
  fs::permissions(name,
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                      fs::perms::others_read | fs::perms::others_exec,
                  ec);
  return name;
}

// One grading run. Every stage is guarded: a failure becomes an error in the report.
int grade(const Options& options, const Rubric& rubric) {
  const auto start = Clock::now();
  GradeReport report;
  report.submission = options.submission;
  report.rubricTitle = rubric.title;
  report.rubricFile = rubric.file;
  report.maxScore = rubric.ok() ? rubric.totalPoints : 0;
  const fs::path out = fs::absolute(options.out);
  const fs::path results = out / "results.json";
  fs::path work = out / "work";
  fs::path scratch;  // the work folder when `out` is out of the sandbox's reach; removed at the end
  bool graderFailed = false;
  auto fail = [&](const std::string& what) {
    report.errors.push_back(what);
    graderFailed = true;
  };

  // A results.json from the start: if this process dies, Gradescope still reads a zero with a
  // reason instead of "the autograder failed to execute correctly".
  {
    GradeReport early = report;
    early.errors.push_back("grading did not finish (the grader was killed or ran out of time)");
    if (const std::string e = writeResultsJson(early, results); !e.empty()) {
      std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
      return 1;
    }
  }
  // What cannot be graded stops here, before any build: results.json says why (score 0), the
  // terminal one line per problem. Nothing to grade in the submission, or a rubric that cannot
  // be used: exit status 2; the grader's own failure: 1. The student reads the reason only when
  // it is the submission's; the rest (it may name hidden checks) goes to the instructors.
  enum class Stop { NothingToGrade, UnusableRubric, GraderFailed };
  auto stop = [&](Stop kind, const std::string& why) {
    if (kind == Stop::NothingToGrade) {
      report.refused = why;
    } else {
      report.errors.push_back(why);
      report.refused = kind == Stop::UnusableRubric
                           ? "the grader's rubric cannot be used (a grader problem, not yours: "
                             "your instructor has been told)"
                           : "the grader could not take your files in (a grader problem, not "
                             "yours: your instructor has been told)";
    }
    for (const std::string& e :
         {writeResultsJson(report, results), writeHtml(report, out / "report.html")}) {
      if (!e.empty()) std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
    }
    std::error_code ignored;
    if (!scratch.empty()) fs::remove_all(scratch, ignored);
    std::fprintf(stderr, "a6_grade: %s\n", why.c_str());
    for (const std::string& note : report.intake.notes)
      std::fprintf(stderr, "a6_grade:   note: %s\n", note.c_str());
    return kind == Stop::GraderFailed ? 1 : 2;
  };
  if (!rubric.ok()) return stop(Stop::UnusableRubric, "the rubric is invalid:\n" + rubric.error);

  // The sandbox's user, ours alone for this grading (grader/process.h).
  std::string claimError;
  process::UidClaim claim = process::claimUid(options.sandboxUid, claimError);
  const uid_t sandboxUid = claim.held() ? claim.uid() : options.sandboxUid.value_or(kNobody);
  if (geteuid() == 0 && !claim.held()) {
    fail("no sandbox user could be claimed for this grading: " + claimError);
  }

  // The compiler and the probe could not read the submission's files under `out` (a home folder
  // of mode 0700, say): then the scratch files go where they can, and are removed afterwards.
  if (geteuid() == 0 && !enterableBy(out, sandboxUid, kSandboxGid)) {
    scratch = enterableScratch();
    if (!scratch.empty()) {
      work = scratch;
      report.notes.push_back("the output folder " + out.string() +
                             " cannot be entered by the sandbox's user (uid " +
                             std::to_string(sandboxUid) + "), so the scratch files went to " +
                             work.string() + " (removed afterwards)");
    }
  }

  std::error_code ec;
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec) fail("cannot create " + work.string() + ": " + ec.message());

    // 1. Intake.
#ifdef A6_GRADE_HAVE_INTAKE
  try {
    report.intake = takeSubmission(options.submission, work / "src");
  } catch (const std::exception& e) {
    report.intake.error = std::string("reading the submission failed: ") + e.what();
    report.intake.graderFault = true;
  }
#else
  report.intake.error = "this a6_grade was built without the intake library (grader/intake.cpp)";
  fail(report.intake.error);
#endif
  if (!report.intake.ok()) {
    return stop(report.intake.graderFault ? Stop::GraderFailed : Stop::NothingToGrade,
                report.intake.error);
  }
  if (report.intake.files.empty()) {
    return stop(Stop::NothingToGrade,
                "none of the six task files (spring.cpp, forces.cpp, time_stepping.cpp, "
                "cloth.cpp, particle_system.cpp, joints.cpp) could be taken from " +
                    options.submission + ": nothing to grade");
  }
  report.seed = options.seed ? *options.seed : seedOf(report.intake.files);

  // The checks, registered now so that the rubric is matched against them before any build.
  try {
    initGoogleTest(report.seed, options.filter);
#ifdef A6_GRADE_HAVE_GOLDEN
    // The images: the grader's alone (the sandbox's user may not read them, whatever its view).
    fs::create_directories(work / "images", ec);
    fs::permissions(work / "images", fs::perms::owner_all, ec);
    a6::test::registerGoldenChecks((work / "images").string(),
                                   a6::test::ImagePaths::InTheReportOnly);
#endif
  } catch (const std::exception& e) {
    fail(std::string("registering the checks failed: ") + e.what());
  }
  if (const std::vector<std::string> problems = coverageProblems(rubric); !problems.empty()) {
    std::string why = "the rubric does not fit the checks:";
    for (const std::string& p : problems) why += "\n" + p;
    return stop(Stop::UnusableRubric, why);
  }

  // 2. Build.
  std::string unavailable;
  std::vector<fs::path> secrets;  // what the probe must not see either
#ifdef A6_GRADE_HAVE_BUILD
  try {
    Kit kit = loadKit(options.kit.empty() ? defaultKitPath() : fs::path(options.kit));
    for (const std::string& path : options.hide) kit.secrets.push_back(fs::absolute(path));
    kit.uid = sandboxUid;
    kit.gid = kSandboxGid;
    if (geteuid() == 0 && !claim.held()) {
      unavailable = "the grader could not build your code (a grader problem, not yours)";
    } else if (!kit.ok()) {
      fail("the grader's kit is unusable: " + kit.error);
      unavailable = "the grader could not build your code (a grader problem, not yours)";
    } else if (const std::string shut = kitUnreadableInSandbox(kit, work); !shut.empty()) {
      fail(shut);
      unavailable = "the grader could not build your code (a grader problem, not yours)";
    } else {
      secrets = kit.secrets;
      report.build = buildProbe(kit, report.intake, work / "build", defaultCompileLimits(),
                                std::max(1, options.jobs));
      // Each task already fell back to the starter where it had to: a probe that still does
      // not link is the kit's fault, not the submission's.
      if (!report.build.ok()) {
        fail("no probe could be linked, so no check could pass (see the build error)");
        unavailable =
            "the grader could not build a program from your files (a grader problem, "
            "not yours; your instructor sees the details)";
      }
#ifdef A6_GRADE_HAVE_PROBE
      else {
        unavailable = checkStartup(kit, report, work, secrets);
        // No program could start at all: every check fails at once, a TA should look.
        if (!unavailable.empty()) ++report.incidents.startFailures;
      }
#endif
    }
  } catch (const std::exception& e) {
    fail(std::string("building the submission failed: ") + e.what());
    unavailable = "the grader could not build your code (a grader problem, not yours)";
  }
#else
  fail("this a6_grade was built without the build library (grader/build.cpp)");
  unavailable = "the grader could not build your code (a grader problem, not yours)";
#endif

  // 3. Run the checks here, against the probe.
  std::unique_ptr<harness::StudentCode> probe;
  std::function<void(double)> setTimeout;
  std::function<void()> newCheck;
  std::function<std::size_t()> forceAnswers;
  std::function<int()> probeTimeouts;
#ifdef A6_GRADE_HAVE_PROBE
  if (unavailable.empty()) {
    try {
      auto client = [&](const fs::path& program, const char* runDir) {
        auto c = std::make_unique<ProbeClient>(program, work / runDir, Limits{});
        const SandboxView view = viewOfProbe(secrets);
        c->setHidden(view.hide, view.reveal);
        c->setUser(sandboxUid, kSandboxGid);
        return c;
      };
      std::unique_ptr<ProbeClient> models = client(report.build.modelsProbe, "run-models");
      models->serveForces(referenceForceModel());
      auto pair = std::make_unique<ProbePair>(client(report.build.probe, "run"), std::move(models));
      ProbePair* raw = pair.get();
      setTimeout = [raw](double seconds) { raw->setRequestTimeout(seconds); };
      forceAnswers = [raw] { return raw->forceAnswers(); };
      probeTimeouts = [raw] { return raw->incidents().timeouts; };
      newCheck = [raw] { raw->allowMoreStarts(kStartsPerCheck); };
      probe = std::move(pair);
    } catch (const std::exception& e) {
      fail(std::string("starting the probe failed: ") + e.what());
      unavailable = "the grader could not start your code (a grader problem, not yours)";
    }
  }
#else
  if (unavailable.empty()) {
    fail("this a6_grade was built without the probe client (grader/probe_client.cpp)");
    unavailable = "the grader could not run your code (a grader problem, not yours)";
  }
#endif
  BudgetedStudent student(probe.get(), setTimeout, newCheck, unavailable);
  if (forceAnswers) student.setForceAnswers(forceAnswers);
  if (probeTimeouts) student.setProbeTimeouts(probeTimeouts);
  student.setTotalBudget(options.timeBudget);
  gStudent = &student;
  int skipped = 0;
  try {
    auto* collector = new Collector(rubric, report.tests, !options.quiet);
    ::testing::UnitTest::GetInstance()->listeners().Append(collector);  // GoogleTest owns it
    if (!options.quiet)
      std::fprintf(stderr, "a6_grade: running the checks (seed %llu)\n",
                   static_cast<unsigned long long>(report.seed));
    // Its status only repeats what the collector saw.
    if (RUN_ALL_TESTS() != 0 && !options.quiet)
      std::fprintf(stderr, "a6_grade: some checks failed\n");
    skipped = collector->skipped();
  } catch (const std::exception& e) {
    fail(std::string("running the checks failed: ") + e.what());
  }
  if (!student.startError().empty()) {
    fail("the sandbox could not start the probe, so checks failed that may not have: " +
         student.startError());
  }
  if (skipped > 0) {
    fail(std::to_string(skipped) +
         " checks were skipped (the grader's environment could not run them; see each check's "
         "message): they earned nothing");
  }
#ifdef A6_GRADE_HAVE_PROBE
  if (probe != nullptr) {
    try {
      const auto* client = static_cast<ProbePair*>(probe.get());
      report.probeOutput = client->output(kProbeOutputCap);
      for (const std::string& note : client->notes()) report.notes.push_back("sandbox: " + note);
      const ProbeIncidents incidents = client->incidents();
      report.incidents.crashes = incidents.crashes;
      report.incidents.timeouts = student.checksOutOfTime();
      report.incidents.startFailures += incidents.startFailures;
      if (client->restarts() > 0) {
        report.notes.push_back("the probes were restarted " + std::to_string(client->restarts()) +
                               " times (after crashes or time limits)");
      }
    } catch (...) {
    }
  }
#endif
  gStudent = nullptr;
  probe.reset();
  // Whatever the submission left running: our re-parented children, and every process of its
  // user (a new session, any name).
  process::endStrayChildren({});
  if (claim.held()) {
    if (const std::string e = process::endProcessesOf(claim.uid()); !e.empty()) fail(e);
  }

  // 4. Score, 5. report.
  try {
    score(report, rubric);
  } catch (const std::exception& e) {
    fail(std::string("scoring failed: ") + e.what());
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  rusage self{};
  if (getrusage(RUSAGE_SELF, &self) == 0)
    report.peakRssMiB = static_cast<double>(self.ru_maxrss) / 1024;
  int status = graderFailed ? 1 : 0;
  if (const std::string e = writeResultsJson(report, results); !e.empty()) {
    std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
    status = 1;
  }
  if (const std::string e = writeHtml(report, out / "report.html"); !e.empty()) {
    std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
    status = 1;
  }
  if (!scratch.empty()) fs::remove_all(scratch, ec);
  std::fputs(terminalSummary(report, options.color).c_str(), stdout);
  std::printf("results: %s\nreport:  %s\n", results.c_str(), (out / "report.html").c_str());
  std::fflush(stdout);
  return status;
}

}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gStudent; }
}  // namespace a6::test

int main(int argc, char** argv) {
  // What a probe leaves running when it ends is reparented here, to be ended
  // (process::endStrayChildren).
  prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
  Options options;
  CLI::App app{"a6_grade: grades one Assignment 6 submission (docs/instructor.md)"};
  app.add_option("submission", options.submission,
                 "the submission: a folder, or an archive (zip, tar, tar.gz or tgz, tar.bz2, "
                 "tar.xz; recognised by content), or one task file");
  app.add_option("--out", options.out, "where results.json and report.html go (created)");
  app.add_option("--rubric", options.rubric, "the rubric (default: grader/rubric.toml)");
  app.add_option("--seed", options.seed,
                 "the seed of the randomised checks (default: derived from the submission's "
                 "files); the report records it for a regrade");
  app.add_option("--kit", options.kit, "the kit description (default: BUILD/grader/kit.json)");
  app.add_option("--hide", options.hide,
                 "hide this folder or file from the compiler and the probe too, except this "
                 "run's own work folder (a6_batch hides the other submissions and results); "
                 "repeatable")
      ->allow_extra_args(false);  // one path per --hide: never the submission after it
  app.add_option("--sandbox-uid", options.sandboxUid,
                 "as root, run the compiler and the probe as this user id (default: a free uid "
                 "from 65533 down, claimed for this grading by a lock in /run/lock). Every "
                 "process of this uid is killed before and after the grading, so never give the "
                 "uid of an account that runs anything else")
      ->check(CLI::Range(1u, 4294967294u));
  app.add_option("--jobs", options.jobs,
                 "how many of the six files are compiled at once (default 2; a6_batch gives 1, "
                 "since it grades several submissions at once)")
      ->check(CLI::Range(1, 64));
  app.add_option("--time-budget", options.timeBudget,
                 "seconds the student's code may take over all checks together (default 420); "
                 "checks after that fail unrun, so that a submission that loops in many places "
                 "still gets its results within Gradescope's limit")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_option("--tests", options.filter,
                 "only the checks matching this GoogleTest filter (debugging: the score is then "
                 "partial)");
  app.add_flag("--list-tests", options.listTests,
               "print every check and the rubric item it counts for, then exit");
  app.add_flag("--check-rubric", options.checkRubric,
               "check the rubric (--rubric, or the default) against every check, then exit: 0 "
               "when it can be used, 2 and each problem with its line and fix when not");
  app.add_option("--public-rubric", options.publicRubric,
                 "write the rubric without its items on hidden checks (for a student release) "
                 "to this file, then exit");
  app.add_flag("--quiet,-q", options.quiet, "no progress on stderr");
  app.add_flag("--color", options.color, "colour the summary");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }

  Rubric rubric;
  try {
    rubric = loadRubric(options.rubric.empty() ? defaultRubric() : fs::path(options.rubric));
  } catch (const std::exception& e) {
    rubric.error = std::string("cannot load the rubric: ") + e.what();
  }

  if (!options.publicRubric.empty()) {
    if (!rubric.ok()) {
      std::fprintf(stderr, "a6_grade: %s\n", rubric.error.c_str());
      return 1;
    }
    std::ofstream out(options.publicRubric, std::ios::binary | std::ios::trunc);
    out << publicRubricToml(rubric);
    if (!out.flush()) {
      std::fprintf(stderr, "a6_grade: cannot write %s\n", options.publicRubric.c_str());
      return 1;
    }
    return 0;
  }
  if (options.listTests || options.checkRubric) {
    initGoogleTest(1, options.filter);
#ifdef A6_GRADE_HAVE_GOLDEN
    a6::test::registerGoldenChecks((fs::temp_directory_path() / "a6_grade_list").string());
#endif
    return options.listTests ? listTests(rubric) : checkRubric(rubric);
  }
  if (options.submission.empty() || options.out.empty()) {
    std::fprintf(stderr, "a6_grade: give a SUBMISSION and --out DIR (a6_grade --help)\n");
    return 2;
  }
  try {
    return grade(options, rubric);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "a6_grade: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "a6_grade: internal error\n");
  }
  return 1;
}
