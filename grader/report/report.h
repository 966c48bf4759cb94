// What a grading run produced, and the three ways it is written: Gradescope's results.json, a
// self-contained HTML report, and a summary on the terminal.
//
// Scoring rules (score()):
//   - a test counts for the first rubric item whose globs match it (Rubric::itemFor);
//   - an item's points are split evenly among its tests: score = points * passed / tests, or,
//     when all_or_nothing, points only if every one of its tests passed;
//   - extra-credit items add to the score above the total (GradeReport::extraCredit);
//   - an item that matches no test scores 0 and a test that matches no item scores nothing;
//     both are listed in GradeReport::warnings (a rubric that needs fixing).
// The score depends only on the rubric and on which tests passed: never on anything the probe
// printed, never on timing. Scores are rounded to 1e-4 points.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "build/build.h"
#include "intake/intake.h"
#include "mistakes/named.h"
#include "replay/replay_view.h"
#include "scoring/rubric.h"

namespace a6::grader {

/// One test as run in the grader's process.
struct TestOutcome {
  std::string name;  ///< "Task1Spring.AtRestGivesZeroForce"
  bool passed = false;
  std::string message;  ///< the failure messages (input, expected, actual, hint)
  double seconds = 0;
  /// The largest relative difference of its exact comparisons (tests/support/comparisons.h)
  /// when it is beyond double rounding (about 1e-7 for float intermediates), else 0.
  double agreement = 0;
  /// For golden-image checks: paths of the images (student, reference, difference), if any.
  std::vector<std::filesystem::path> images;
  /// The machine may have ended it, not the code (a time limit, a probe killed or not started):
  /// a failed check so marked is run again (checks stage). Not in results.json.
  bool machineMayHaveEndedIt = false;
  /// It failed for the grader alone (a probe that could not start, a grader error): a repeat
  /// makes the grading the machine's failure, never the student's 0.
  bool graderFailedIt = false;
  bool ranAgain = false;  ///< this is the outcome of its second run
};

/// One rubric item, scored.
struct ScoredItem {
  RubricItem item;
  double score = 0;
  int passed = 0, failed = 0;
  std::vector<const TestOutcome*> tests;  ///< point into GradeReport::tests
  std::string number;  ///< "1.1", "1.2", ... (task, then the item's rank within its task)
};

struct GradeReport {
  std::string submission;  ///< what was graded (path as given)
  std::uint64_t seed = 0;  ///< the seed of the hidden checks, for a reproducible regrade
  std::string rubricTitle;
  std::filesystem::path rubricFile;
  Intake intake;
  Build build;
  /// The files were linked into the grading program (GradeOptions::linked, the tests' in-process
  /// gradings): no intake, no build, so the report says that instead of "not found".
  bool linked = false;
  std::vector<TestOutcome> tests;
  std::vector<ScoredItem> items;
  /// The known mistakes the answers of failing tasks matched (grader/mistakes/), in task order:
  /// each failed item of its task leads with the mistake's sentence.
  std::vector<NamedMistake> mistakes;
  /// Each imaged scene's run beside the reference's (grader/replay/): the report's players.
  std::vector<ReplayView> replays;
  double score = 0;        ///< regular points plus extra credit
  double maxScore = 0;     ///< the rubric's total (extra credit not included)
  double extraCredit = 0;  ///< the part of `score` earned by extra-credit items
  double seconds = 0;
  double peakRssMiB = 0;              ///< the grader's own peak memory (not its children's)
  std::string probeOutput;            ///< capped; shown to instructors only
  std::vector<std::string> warnings;  ///< rubric problems found while scoring
  std::vector<std::string> notes;     ///< for instructors: sandbox protections that could not
                                      ///< be applied (not root, ...), and the like
  std::vector<std::string> errors;    ///< grader-level problems (never crashes: they land here)
  /// Why nothing was graded (no such submission, no task file in it, a rubric that cannot be
  /// used): a6_grade stopped before any build and exits 2. Empty for a graded submission.
  std::string refused;
  /// What the student's code did that a TA may want to look at, though it was graded: probes
  /// that crashed, requests and checks stopped at a time limit (or not run when the time
  /// budget was spent), probes that did not start. results.json's extra_data.incidents.
  struct Incidents {
    int crashes = 0, timeouts = 0, startFailures = 0;
  } incidents;
};

/// The part of a score a student sees before the due date: the items whose visibility is
/// "visible" (the others are shown later, or never).
struct VisibleTotals {
  double score = 0, max = 0, extraCredit = 0;
  double laterPoints = 0;       ///< regular points of the items not visible yet
  double laterExtraCredit = 0;  ///< extra credit of the items not visible yet
  int laterItems = 0;
};
VisibleTotals visibleTotals(const GradeReport& report);

/// Scores `report.tests` with `rubric`: fills items, score, maxScore, extraCredit, warnings.
/// Deterministic: the same tests and rubric give the same numbers.
void score(GradeReport& report, const Rubric& rubric);

/// results.json as Gradescope reads it (see docs/instructor.md): one test per rubric item.
std::string resultsJson(const GradeReport& report);
/// Writes resultsJson() atomically (a temporary file in the same folder, then rename). Returns
/// an empty string, or what went wrong.
std::string writeResultsJson(const GradeReport& report, const std::filesystem::path& file);

/// One self-contained HTML page (inline CSS, images as data URIs); student-derived text escaped.
std::string htmlReport(const GradeReport& report);
std::string writeHtml(const GradeReport& report, const std::filesystem::path& file);

/// A table per item (task, points, tests passed and failed) for the terminal.
std::string terminalSummary(const GradeReport& report, bool color);

/// Helpers, public for the tests.
std::string htmlEscape(const std::string& text);
std::string base64(const std::string& bytes);
/// Writes `text` to `file` atomically; returns an empty string or the error.
std::string writeFileAtomically(const std::filesystem::path& file, const std::string& text);

}  // namespace a6::grader
