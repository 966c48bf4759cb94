// The checks stage: the physics suite (tests/task*_test.cpp, linked into a6_grade) and the
// golden-image checks, registered in this process and run against the student's code in the
// sandboxed probe. Student code never runs here: the suite's a6::test::student() is the probe.
//
// Takes: the seed and filter the checks are registered with; the built probes and what the
// probe may see; the time budget. Gives: each check's outcome (TestOutcome), what the probes
// did (crashes, time-outs, their output) for the report, and the public checks' requests with
// the student's answers (the transcript) for the mistakes stage, and the scenes' runs for the
// report's replays.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "checks/divergence.h"
#include "checks/outcome.h"
#include "checks/scene_run.h"
#include "checks/transcript.h"
#include "common/limits.h"
#include "harness/student_code.h"
#include "rubric/rubric.h"

namespace a6::grader {

/// Registers every check with GoogleTest, its flags pinned (nothing from the environment, such
/// as GTEST_FILTER, changes what runs): `seed` draws the random inputs, `filter` (a GoogleTest
/// filter, "" for all) chooses the checks. The golden-image checks write their images into
/// `imagesDir`; with `inReportOnly` their messages do not name those paths (a grading: only the
/// report shows the images).
void registerChecks(std::uint64_t seed, const std::string& filter,
                    const std::filesystem::path& imagesDir, bool inReportOnly);

/// The names of every registered check, in run order.
std::vector<std::string> registeredChecks();

/// What makes a valid rubric unusable with the registered checks: an item that matches no
/// check (its points could never be earned) and a check that matches no item (it would score
/// nothing). One line each, with the place and the fix; empty when every check counts.
std::vector<std::string> coverageProblems(const Rubric& rubric);

/// --list-tests: every check and the item it counts for; 1 when some check or item is unmatched.
int listChecks(const Rubric& rubric);
/// --check-rubric: 0 and a one-line summary when the rubric can be used; 2 and each problem
/// (place and fix) when not.
int checkRubricAgainstChecks(const Rubric& rubric);
/// `a6_grade --list-items`: one line per rubric item, tab-separated: name, points, how many of
/// the registered checks count for it, "extra" or "regular", its visibility; then a line
/// "total", the rubric's total, the number of checks, the extra credit's points. For scripts
/// and tests that must read the rubric's numbers rather than pin them. 0, or 1 when the rubric
/// is invalid.
int listItems(const Rubric& rubric);

/// The probes the checks run against, and what they may see.
struct ChecksInput {
  std::filesystem::path probe;        ///< serves every request
  std::filesystem::path modelsProbe;  ///< serves the requests that ask for the reference forces
  std::filesystem::path work;         ///< the run folders go under it
  std::vector<std::filesystem::path> secrets;  ///< what the probe must not see
  uid_t uid = 0;
  gid_t gid = 0;
  /// Non-empty when there is no probe to run (the build failed): every request fails with it.
  std::string unavailable;
  double timeBudget = kDefaultTimeBudget;
  std::string filter;  ///< the checks registered to run ("": all), restored after a re-run
  bool progress = false;
  bool replays = true;  ///< run each imaged scene once more for the report's replays
  /// The student's code linked into this program (tests only, GradeOptions::linked), asked in
  /// place of the probes; null: the probes.
  harness::StudentCode* linked = nullptr;
  /// Asked after every check has been collected (so they change no score), for the diagnosis.
  std::vector<Designed> designed;
  /// The reference steppers the failed stepping checks restart from (checks/divergence.h;
  /// empty: no divergence is looked for).
  ReferenceSteppers reference;
};

struct ChecksRun {
  std::vector<TestOutcome> tests;
  std::vector<std::string> errors;  ///< the grader's own failures
  std::vector<std::string> notes;   ///< for instructors (sandbox protections, restarts)
  std::string probeOutput;          ///< what the probes printed, capped
  Incidents incidents;
  Transcript transcript;  ///< what the public checks asked and the student's code answered
  Transcript measured;    ///< the designed inputs' answers (labels as `check`)
  std::vector<Divergence> divergences;  ///< the failed stepping checks' first divergences
  std::vector<SceneRun> replays;  ///< the imaged scenes run again at replay frames, for the report
  std::filesystem::path replayFolder;  ///< the reference replays (render/replay.h) beside them
  /// Failed particle checks' runs asked again at many step counts, for the report.
  std::vector<ParticleTrajectory> particleTrajectories;
};

/// The names of the checks that failed, in run order.
std::vector<std::string> failedChecks(const std::vector<TestOutcome>& tests);

/// Runs every registered check against the probes of `input` (registerChecks first).
ChecksRun runChecks(const ChecksInput& input, const Rubric& rubric);

}  // namespace a6::grader
