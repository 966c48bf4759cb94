// The scoring stage: the rubric's points for the checks' outcomes (rules: score.h).
#include "scoring/score.h"

#include <cmath>
#include <map>
#include <sstream>

namespace a6::grader {

double roundPoints(double points) { return std::round(points * 1e4) / 1e4; }

std::string formatPoints(double points) {
  std::ostringstream out;
  out << roundPoints(points);
  return out.str();
}

VisibleTotals visibleTotals(const std::vector<ScoredItem>& items) {
  VisibleTotals v;
  for (const ScoredItem& s : items) {
    const bool now = s.item.visibility == Visibility::Visible;
    if (!now) {
      (s.item.extraCredit ? v.laterExtraCredit : v.laterPoints) += s.item.points;
      ++v.laterItems;
    } else if (s.item.extraCredit) {
      v.extraCredit += s.score;
    } else {
      v.score += s.score;
      v.max += s.item.points;
    }
  }
  v.score = roundPoints(v.score);
  v.extraCredit = roundPoints(v.extraCredit);
  return v;
}

Scores scoreTests(const std::vector<TestOutcome>& tests, const Rubric& rubric) {
  Scores scores;
  scores.maxScore = rubric.totalPoints;
  scores.rubricTitle = rubric.title;
  for (const RubricItem& item : rubric.items)
    scores.items.push_back(ScoredItem{item, 0, 0, 0, {}, {}});

  // Each test counts for the first item that matches it.
  for (const TestOutcome& t : tests) {
    const int index = rubric.itemFor(t.name);
    if (index < 0) {
      scores.warnings.push_back("test " + t.name + " matches no rubric item: it scores nothing");
      continue;
    }
    ScoredItem& s = scores.items[static_cast<std::size_t>(index)];
    s.tests.push_back(&t);
    (t.passed ? s.passed : s.failed)++;
  }

  std::map<int, int> rank;  // items seen so far per task, for "task.rank" numbers
  double regular = 0;
  for (ScoredItem& s : scores.items) {
    s.number = std::to_string(s.item.task) + "." + std::to_string(++rank[s.item.task]);
    const int n = s.passed + s.failed;
    if (n == 0) {
      std::string where = rubric.file.empty() ? ""
                                              : " (" + rubric.file.filename().string() + ":" +
                                                    std::to_string(s.item.line) + ")";
      scores.warnings.push_back("rubric item '" + s.item.name + "'" + where +
                                " matches no test: its " + formatPoints(s.item.points) +
                                " points cannot be earned");
      s.score = 0;
    } else if (s.item.allOrNothing) {
      s.score = s.failed == 0 ? s.item.points : 0;
    } else {
      // points * passed / n, not a sum of shares: full marks are exactly the points.
      s.score = roundPoints(s.item.points * s.passed / n);
    }
    (s.item.extraCredit ? scores.extraCredit : regular) += s.score;
  }
  scores.extraCredit = roundPoints(scores.extraCredit);
  scores.score = roundPoints(regular + scores.extraCredit);
  return scores;
}

}  // namespace a6::grader
