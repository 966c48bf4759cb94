// What a grading run produced, written three ways: Gradescope's results.json, a self-contained
// HTML report and a terminal summary. Its points come from scoring/score.h.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "build/build.h"
#include "checks/outcome.h"
#include "common/atomic_write.h"
#include "common/html_escape.h"
#include "intake/intake.h"
#include "mistakes/named.h"
#include "replay/replay_view.h"
#include "rubric/rubric.h"
#include "scoring/score.h"

namespace a6::grader {

struct GradeReport {
  std::string submission;  ///< what was graded (path as given)
  std::uint64_t seed = 0;  ///< the seed of the hidden checks, for a reproducible regrade
  std::string rubricTitle;
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
  /// What the designed inputs measured of each failing task (mistakes/measure.h), whether or not
  /// the catalogue named a mistake there: for instructors (results.json's extra_data).
  std::vector<NamedMistake> diagnoses;
  /// The failed stepping checks' first divergences (checks/divergence.h): each failed item of
  /// their task shows its checks'.
  std::vector<Divergence> divergences;
  /// Each imaged scene's run beside the reference's (grader/replay/): the report's players.
  std::vector<ReplayView> replays;
  double score = 0;          ///< regular points plus extra credit
  double maxScore = 0;       ///< the rubric's total (extra credit not included)
  double extraCredit = 0;    ///< the part of `score` earned by extra-credit items
  double seconds = 0;        ///< the whole grading's wall time
  double buildSeconds = 0;   ///< the build stage's (its budget, the links and start-up checks)
  double checksSeconds = 0;  ///< the checks stage's (within --time-budget and what ends a check)
  double peakRssMiB = 0;     ///< the grader's own peak memory (not its children's)
  std::string probeOutput;   ///< capped; shown to instructors only
  std::vector<std::string> warnings;  ///< rubric problems found while scoring
  std::vector<std::string> notes;     ///< for instructors: sandbox protections that could not
                                      ///< be applied (not root, ...), and the like
  std::vector<std::string> errors;    ///< grader-level problems (never crashes: they land here)
  /// Why nothing was graded (no such submission, no task file in it, a rubric that cannot be
  /// used): a6_grade stopped before any build and exits 2. Empty for a graded submission.
  std::string refused;
  Incidents incidents;  ///< checks/outcome.h
};

/// Scores `report.tests` with `rubric` (scoring/score.h): its items, score, maxScore,
/// extraCredit and rubricTitle, and the scoring's warnings added to its own.
void score(GradeReport& report, const Rubric& rubric);
/// The part of the report's score a student sees before the due date.
inline VisibleTotals visibleTotals(const GradeReport& report) {
  return visibleTotals(report.items);
}

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
std::string base64(const std::string& bytes);

}  // namespace a6::grader
