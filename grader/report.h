// What a grading run produced, and the three ways it is written: Gradescope's results.json, a
// self-contained HTML report, and a summary on the terminal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "build.h"
#include "intake.h"
#include "rubric.h"

namespace a6::grader {

/// One test as run in the grader's process.
struct TestOutcome {
  std::string name;      ///< "Task1Spring.AtRestGivesZeroForce"
  bool passed = false;
  std::string message;   ///< the failure messages (input, expected, actual, hint)
  double seconds = 0;
  /// For golden-image checks: paths of the images (student, reference, difference), if any.
  std::vector<std::filesystem::path> images;
};

/// One rubric item, scored.
struct ScoredItem {
  RubricItem item;
  double score = 0;
  std::vector<const TestOutcome*> tests;
};

struct GradeReport {
  std::string submission;       ///< what was graded (path as given)
  std::uint64_t seed = 0;       ///< the seed of the hidden checks, for a reproducible regrade
  Intake intake;
  Build build;
  std::vector<TestOutcome> tests;
  std::vector<ScoredItem> items;
  double score = 0, maxScore = 0, extraCredit = 0;
  double seconds = 0;
  std::string probeOutput;      ///< capped; shown to instructors only
  std::vector<std::string> errors;  ///< grader-level problems (never crashes: they land here)
};

/// Scores `tests` with `rubric` (tests that match no item are reported with 0 points).
void score(GradeReport& report, const Rubric& rubric);

void writeResultsJson(const GradeReport& report, const std::filesystem::path& file);
void writeHtml(const GradeReport& report, const std::filesystem::path& file);
std::string terminalSummary(const GradeReport& report, bool color);

}  // namespace a6::grader
