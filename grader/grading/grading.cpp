#include "grading/grading.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>

#include "build/build.h"
#include "build/startup.h"
#include "common/fnv1a.h"
#include "common/read_all.h"
#include "harness/tasks.h"
#include "intake/intake.h"
#include "mistakes/measure.h"
#include "mistakes/mistakes.h"
#include "replay/replays.h"
#include "report/report.h"
#include "sandbox/process.h"

namespace fs = std::filesystem;

namespace a6::grader {
namespace {

using GradingClock = std::chrono::steady_clock;

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
  fs::permissions(name, kOpenFolder, ec);
  return name;
}

// The default seed: a hash of the seven files taken, so the same submission always gets the same
// inputs and a different one cannot know its own in advance.
std::uint64_t seedOf(const std::map<std::string, fs::path>& files) {
  Fnv1a h;  // the names and texts run together, without separators
  for (const auto& [name, path] : files) {
    h.addBytes(name.data(), name.size());
    const std::string bytes = readAll(path);  // a copy the intake wrote, bounded
    h.addBytes(bytes.data(), bytes.size());
  }
  return h.h % 1000000007ull;  // short enough to type in a regrade
}

const char* const kCouldNotBuild =
    "the grader could not build your code (a grader problem, not yours)";

// What cannot be graded stops before any build: nothing to grade in the submission (exit 2), a
// rubric that cannot be used (2), the grader's own failure (1).
enum class Stop { NothingToGrade, UnusableRubric, GraderFailed };

// One grading's shared state. run() calls each stage once, in order; none calls another.
class Grading {
 public:
  Grading(const GradeOptions& options, const Rubric& rubric)
      : options_(options), rubric_(rubric), start_(GradingClock::now()) {}

  int run() {
    if (!begin()) return 1;
    if (!rubric_.ok())
      return stop(Stop::UnusableRubric, "the rubric is invalid:\n" + rubric_.error);
    if (options_.linked != nullptr) return runLinked();
    claimSandboxUser();
    prepareWork();
    if (const std::optional<int> stopped = intake()) return *stopped;
    if (const std::optional<int> stopped = registerChecks()) return *stopped;
    report_.buildSeconds = secondsOf([this] { build(); });
    report_.checksSeconds = secondsOf([this] { check(); });
    endWhatWasLeftRunning();
    nameMistakes();
    buildReplays();
    return finish();
  }

 private:
  template <typename Stage>
  static double secondsOf(Stage stage) {
    const GradingClock::time_point start = GradingClock::now();
    stage();
    return process::secondsSince(start);
  }
  void fail(const std::string& what) {
    report_.errors.push_back(what);
    graderFailed_ = true;
  }
  bool begin();
  int stop(Stop kind, const std::string& why);
  void claimSandboxUser();
  void prepareWork();
  std::optional<int> intake();
  std::optional<int> registerChecks();
  void build();
  void buildWith(Kit& kit);
  void check();
  void endWhatWasLeftRunning();
  void nameMistakes();
  void buildReplays();
  int finish();

  // The stages after the build, against code linked into this program (GradeOptions::linked).
  int runLinked() {
    report_.seed = options_.seed.value_or(1);
    report_.linked = true;
    prepareWork();
    if (const std::optional<int> stopped = registerChecks()) return *stopped;
    report_.checksSeconds = secondsOf([this] { check(); });
    nameMistakes();
    buildReplays();
    return finish();
  }

  const GradeOptions& options_;
  const Rubric& rubric_;
  const GradingClock::time_point start_;
  GradeReport report_;
  fs::path out_, results_, work_;
  fs::path
      scratch_;  // the work folder when `out` is out of the sandbox's reach; removed at the end
  bool graderFailed_ = false;
  process::UidClaim claim_;
  uid_t sandboxUid_ = kNobody;
  std::vector<fs::path> secrets_;    // what the probe must not see either
  std::string unavailable_;          // why there is no probe to run the checks against, or ""
  Transcript transcript_;            // the public checks' requests and the student's answers
  Transcript measured_;              // the designed inputs' answers (mistakes/measure.h)
  std::vector<SceneRun> sceneRuns_;  // the imaged scenes run again, for the replays
  std::vector<ParticleTrajectory> particleTrajectories_;  // failed particle checks run again
  fs::path replayFolder_;                                 // the reference replays
};

// The report's heading, and a results.json from the start: if this process dies, Gradescope
// still reads a zero with a reason instead of "the autograder failed to execute correctly".
bool Grading::begin() {
  report_.submission = options_.submission;
  report_.rubricTitle = rubric_.title;
  report_.maxScore = rubric_.ok() ? rubric_.totalPoints : 0;
  out_ = fs::absolute(options_.out);
  results_ = out_ / "results.json";
  work_ = out_ / "work";
  GradeReport early = report_;
  early.errors.push_back("grading did not finish (the grader was killed or ran out of time)");
  if (const std::string e = writeResultsJson(early, results_); !e.empty()) {
    std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
    return false;
  }
  return true;
}

// results.json says why (score 0), the terminal one line per problem. The student reads the
// reason only when it is the submission's; the rest (it may name hidden checks) goes to the
// instructors.
int Grading::stop(Stop kind, const std::string& why) {
  if (kind == Stop::NothingToGrade) {
    report_.refused = why;
  } else {
    report_.errors.push_back(why);
    report_.refused = kind == Stop::UnusableRubric
                          ? "the grader's rubric cannot be used (a grader problem, not yours: "
                            "your instructor has been told)"
                          : "the grader could not take your files in (a grader problem, not "
                            "yours: your instructor has been told)";
  }
  for (const std::string& e :
       {writeResultsJson(report_, results_), writeHtml(report_, out_ / "report.html")}) {
    if (!e.empty()) std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
  }
  std::error_code ignored;
  if (!scratch_.empty()) fs::remove_all(scratch_, ignored);
  std::fprintf(stderr, "a6_grade: %s\n", why.c_str());
  for (const std::string& note : report_.intake.notes)
    std::fprintf(stderr, "a6_grade:   note: %s\n", note.c_str());
  return kind == Stop::GraderFailed ? 1 : 2;
}

// The sandbox's user, ours alone for this grading (sandbox/process.h).
void Grading::claimSandboxUser() {
  std::string claimError;
  claim_ = process::claimUid(options_.sandboxUid, claimError);
  sandboxUid_ = claim_.held() ? claim_.uid() : options_.sandboxUid.value_or(kNobody);
  if (geteuid() == 0 && !claim_.held()) {
    fail("no sandbox user could be claimed for this grading: " + claimError);
  }
}

// The work folder. When the compiler and the probe could not read the submission's files under
// `out` (a home folder of mode 0700, say), the scratch files go where they can, removed after.
void Grading::prepareWork() {
  if (geteuid() == 0 && !enterableBy(out_, sandboxUid_, kSandboxGid)) {
    scratch_ = enterableScratch();
    if (!scratch_.empty()) {
      work_ = scratch_;
      report_.notes.push_back("the output folder " + out_.string() +
                              " cannot be entered by the sandbox's user (uid " +
                              std::to_string(sandboxUid_) + "), so the scratch files went to " +
                              work_.string() + " (removed afterwards)");
    }
  }
  std::error_code ec;
  fs::remove_all(work_, ec);
  fs::create_directories(work_, ec);
  if (ec) fail("cannot create " + work_.string() + ": " + ec.message());
}

// 1. Intake: the seven task files, or why there is nothing to grade.
std::optional<int> Grading::intake() {
  try {
    report_.intake = takeSubmission(options_.submission, work_ / "src");
  } catch (const std::exception& e) {
    report_.intake.error = std::string("reading the submission failed: ") + e.what();
    report_.intake.graderFault = true;
  }
  if (!report_.intake.ok()) {
    return stop(report_.intake.graderFault ? Stop::GraderFailed : Stop::NothingToGrade,
                report_.intake.error);
  }
  if (report_.intake.files.empty()) {
    std::string names;
    for (const std::string& f : kTaskFiles) names += (names.empty() ? "" : ", ") + f;
    return stop(Stop::NothingToGrade, "none of the task files (" + names +
                                          ") could be taken from " + options_.submission +
                                          ": nothing to grade");
  }
  report_.seed = options_.seed ? *options_.seed : seedOf(report_.intake.files);
  return std::nullopt;
}

// The checks, registered now so that the rubric is matched against them before any build. The
// images are the grader's alone (the sandbox's user may not read them, whatever its view).
std::optional<int> Grading::registerChecks() {
  try {
    std::error_code ec;
    fs::create_directories(work_ / "images", ec);
    fs::permissions(work_ / "images", fs::perms::owner_all, ec);
    grader::registerChecks(report_.seed, options_.filter, work_ / "images", true);
  } catch (const std::exception& e) {
    fail(std::string("registering the checks failed: ") + e.what());
  }
  if (const std::vector<std::string> problems = coverageProblems(rubric_); !problems.empty()) {
    std::string why = "the rubric does not fit the checks:";
    for (const std::string& p : problems) why += "\n" + p;
    return stop(Stop::UnusableRubric, why);
  }
  return std::nullopt;
}

// 2. Build: the kit, then a probe that starts, or why there is none (unavailable_).
void Grading::build() {
  try {
    Kit kit = loadKit(options_.kit.empty() ? defaultKitPath() : fs::path(options_.kit));
    for (const std::string& path : options_.hide) kit.secrets.push_back(fs::absolute(path));
    kit.uid = sandboxUid_;
    kit.gid = kSandboxGid;
    if (geteuid() == 0 && !claim_.held()) {
      unavailable_ = kCouldNotBuild;
    } else if (!kit.ok()) {
      fail("the grader's kit is unusable: " + kit.error);
      unavailable_ = kCouldNotBuild;
    } else if (const std::string shut = kitUnreadableInSandbox(kit, work_); !shut.empty()) {
      fail(shut);
      unavailable_ = kCouldNotBuild;
    } else {
      buildWith(kit);
    }
  } catch (const std::exception& e) {
    fail(std::string("building the submission failed: ") + e.what());
    unavailable_ = kCouldNotBuild;
  }
}

void Grading::buildWith(Kit& kit) {
  secrets_ = kit.secrets;
  report_.build = buildProbe(kit, report_.intake, work_ / "build", defaultCompileLimits(),
                             std::max(1, options_.jobs), kDefaultBuildBudget);
  // For the TA, not the student's report: what the sandbox could not do, compiles done again.
  // (Not running as root is said once, in the summary's notes, by the checks' sandbox runs.)
  for (const std::string& note : report_.build.notes) {
    if (note != kNotRootNote) std::fprintf(stderr, "a6_grade: build: %s\n", note.c_str());
  }
  // Each task already fell back to the starter where it had to: a probe that still does not
  // link is the kit's fault, not the submission's.
  if (!report_.build.ok()) {
    fail("no probe could be linked, so no check could pass (see the build error)");
    unavailable_ =
        "the grader could not build a program from your files (a grader problem, not yours; "
        "your instructor sees the details)";
    return;
  }
  unavailable_ = ensureProbeStarts(kit, report_.build, work_, secrets_);
  // No program could start at all: every check fails at once, a TA should look.
  if (!unavailable_.empty()) ++report_.incidents.startFailures;
}

// 3. Run the checks here, against the probe.
void Grading::check() {
  ChecksInput in;
  in.linked = options_.linked;
  in.probe = report_.build.probe;
  in.modelsProbe = report_.build.modelsProbe;
  in.work = work_;
  in.secrets = secrets_;
  in.uid = sandboxUid_;
  in.gid = kSandboxGid;
  in.unavailable = unavailable_;
  in.timeBudget = options_.timeBudget;
  in.filter = options_.filter;
  in.progress = !options_.quiet;
  in.replays = options_.filter.empty();
  if (options_.filter.empty()) {
    in.designed = designedInputs();
    in.reference.simulate = [](const harness::SimulateRequest& r) {
      return r.implicit ? referenceImplicitSimulation(r) : referenceSimulation(r);
    };
    in.reference.particles = referenceParticleRun;
  }
  if (!options_.quiet)
    std::fprintf(stderr, "a6_grade: running the checks (seed %llu)\n",
                 static_cast<unsigned long long>(report_.seed));
  ChecksRun run = runChecks(in, rubric_);
  report_.tests = std::move(run.tests);
  for (const std::string& e : run.errors) fail(e);
  for (std::string& note : run.notes) {
    if (std::find(report_.notes.begin(), report_.notes.end(), note) == report_.notes.end()) {
      report_.notes.push_back(std::move(note));
    }
  }
  report_.probeOutput = std::move(run.probeOutput);
  report_.incidents.crashes = run.incidents.crashes;
  report_.incidents.timeouts = run.incidents.timeouts;
  report_.incidents.startFailures += run.incidents.startFailures;
  transcript_ = std::move(run.transcript);
  measured_ = std::move(run.measured);
  report_.divergences = std::move(run.divergences);
  sceneRuns_ = std::move(run.replays);
  particleTrajectories_ = std::move(run.particleTrajectories);
  replayFolder_ = run.replayFolder;
}

// Whatever the submission left running: our re-parented children; and where there are no pid
// namespaces (which end what a sandbox started with it), every process of its user.
void Grading::endWhatWasLeftRunning() {
  process::endStrayChildren({});
  if (claim_.held() && !process::pidNamespaces()) {
    if (const std::string e = process::endProcessesOf(claim_.uid()); !e.empty()) fail(e);
  }
}

// 4. The mistakes of the tasks whose physics checks failed: the known ones their answers match,
// else what the designed inputs measured.
void Grading::nameMistakes() {
  std::set<int> failing;
  for (const TestOutcome& t : report_.tests) {
    const SuiteOwner owner = courseTasks().ownerOfCheck(t.name);
    if (!t.passed && owner.task > 0 && isPhysics(owner.kind)) failing.insert(owner.task);
  }
  try {
    report_.diagnoses = diagnose(measured_, failing);
    report_.mistakes =
        combine(grader::nameMistakes(transcript_, mistakeLibrary(), failing), report_.diagnoses);
  } catch (const std::exception& e) {
    report_.notes.push_back(std::string("naming the mistakes failed: ") + e.what());
  }
}

// 5. The replays: each imaged scene's run beside the reference's, and the failed checks' runs
// (task 3's simulations, task 5's particles) beside the reference's, measured for the report.
void Grading::buildReplays() {
  try {
    report_.replays = grader::buildReplays(sceneRuns_, replayFolder_);
    for (ReplayView& v : trajectoryReplays(transcript_, failedChecks(report_.tests))) {
      for (const Divergence& d : report_.divergences) {
        if (d.check == v.scene) v.divergence = d.text;
      }
      report_.replays.push_back(std::move(v));
    }
    for (ReplayView& v : particleTrajectoryReplays(particleTrajectories_))
      report_.replays.push_back(std::move(v));
  } catch (const std::exception& e) {
    report_.notes.push_back(std::string("building the replays failed: ") + e.what());
  }
  sceneRuns_.clear();
  particleTrajectories_.clear();
  transcript_ = Transcript{};
}

// 6. Score, 7. report.
int Grading::finish() {
  try {
    score(report_, rubric_);
  } catch (const std::exception& e) {
    fail(std::string("scoring failed: ") + e.what());
  }
  report_.seconds = std::chrono::duration<double>(GradingClock::now() - start_).count();
  rusage self{};
  if (getrusage(RUSAGE_SELF, &self) == 0)
    report_.peakRssMiB = static_cast<double>(self.ru_maxrss) / 1024;
  int status = graderFailed_ ? 1 : 0;
  for (const std::string& e :
       {writeResultsJson(report_, results_), writeHtml(report_, out_ / "report.html")}) {
    if (e.empty()) continue;
    std::fprintf(stderr, "a6_grade: %s\n", e.c_str());
    status = 1;
  }
  std::error_code ec;
  if (!scratch_.empty()) fs::remove_all(scratch_, ec);
  std::fputs(terminalSummary(report_, options_.color).c_str(), stdout);
  std::printf("results: %s\nreport:  %s\n", results_.c_str(), (out_ / "report.html").c_str());
  std::fflush(stdout);
  return status;
}

}  // namespace

int grade(const GradeOptions& options, const Rubric& rubric) {
  return Grading(options, rubric).run();
}

}  // namespace a6::grader
