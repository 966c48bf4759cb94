// The points a grading gives (the scoring stage), from the rubric and the checks' outcomes.
//
// Scoring rules (score()):
//   - a test counts for the first rubric item whose globs match it (Rubric::itemFor);
//   - an item's points are split evenly among its tests: score = points * passed / tests, or,
//     when all_or_nothing, points only if every one of its tests passed;
//   - extra-credit items add to the score above the total (Scores::extraCredit);
//   - an item that matches no test scores 0 and a test that matches no item scores nothing;
//     both are listed in Scores::warnings (a rubric that needs fixing).
// The score depends only on the rubric and on which tests passed: never on anything the probe
// printed, never on timing. Scores are rounded to 1e-4 points.
#pragma once

#include <string>
#include <vector>

#include "checks/outcome.h"
#include "rubric/rubric.h"

namespace a6::grader {

struct ScoredItem {
  RubricItem item;
  double score = 0;
  int passed = 0, failed = 0;
  std::vector<const TestOutcome*> tests;  ///< point into the outcomes scored
  std::string number;  ///< "1.1", "1.2", ... (task, then the item's rank within its task)
};

/// The part of a score a student sees before the due date: the items whose visibility is
/// "visible" (the others are shown later, or never).
struct VisibleTotals {
  double score = 0, max = 0, extraCredit = 0;
  double laterPoints = 0;       ///< regular points of the items not visible yet
  double laterExtraCredit = 0;  ///< extra credit of the items not visible yet
  int laterItems = 0;
};
VisibleTotals visibleTotals(const std::vector<ScoredItem>& items);

/// What the scoring stage gives: the rubric's items with their points, and the totals.
struct Scores {
  std::vector<ScoredItem> items;
  double score = 0;        ///< regular points plus extra credit
  double maxScore = 0;     ///< the rubric's total (extra credit not included)
  double extraCredit = 0;  ///< the part of `score` earned by extra-credit items
  std::string rubricTitle;
  std::vector<std::string> warnings;  ///< items that match no test, tests that match no item
};

/// Scores `tests` with `rubric` (the items' tests point into `tests`, which must outlive them).
/// Deterministic: the same tests and rubric give the same numbers.
Scores scoreTests(const std::vector<TestOutcome>& tests, const Rubric& rubric);
Scores scoreTests(std::vector<TestOutcome>&& tests, const Rubric& rubric) = delete;  // dangling

/// Points rounded as every score is: to 1e-4.
double roundPoints(double points);
/// Points as the report writes them: rounded, no trailing zeros ("12", "7.5", "0.3333").
std::string formatPoints(double points);

}  // namespace a6::grader
