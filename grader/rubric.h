// The instructor's rubric (TOML): points per test or group of tests, visibility, extra credit,
// per-test time limits. Scores come from here and from pass/fail decided in the grader's process,
// never from anything the probe prints.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace a6::grader {

enum class Visibility { Visible, Hidden, AfterDueDate, AfterPublished };
const char* toString(Visibility v);  ///< Gradescope's names: visible, hidden, after_due_date, ...

/// One rubric item: the tests whose full name (Suite.Test) matches `tests` (a glob with * and ?)
/// share `points`, split evenly, or all-or-nothing when `allOrNothing`.
struct RubricItem {
  std::string name;          ///< shown in reports, e.g. "Task 1: spring force"
  int task = 0;              ///< 1..6, or 0 for none
  std::string tests;         ///< glob over "Suite.Test"
  double points = 0;
  bool allOrNothing = false;
  bool extraCredit = false;  ///< counts above the total (max_score 0 in the total)
  Visibility visibility = Visibility::Visible;
  double timeLimitSeconds = 10;  ///< per request of each matching test
};

struct Rubric {
  std::string title;
  double totalPoints = 100;  ///< the sum of non-extra-credit points (checked on load)
  std::vector<RubricItem> items;
  std::string error;         ///< a clear message with file and line when the file is invalid
  bool ok() const { return error.empty(); }
};

Rubric loadRubric(const std::filesystem::path& file);

}  // namespace a6::grader
