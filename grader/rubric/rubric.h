// The instructor's rubric (TOML; the format: docs/instructor.md): points per test or group of
// tests, visibility, extra credit, per-test time limits. Scores come from here and from pass/fail
// decided in the grader's process, never from anything the probe prints. A test counts for the
// FIRST item (in file order) whose globs match it: narrow items (extra credit, hidden checks)
// go before the broad item of their task.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "harness/tasks.h"

namespace a6::grader {

enum class Visibility { Visible, Hidden, AfterDueDate, AfterPublished };
const char* toString(Visibility v);  ///< Gradescope's names: visible, hidden, after_due_date, ...

/// One rubric item: the tests whose full name (Suite.Test) matches one of `tests` (globs with *
/// and ?) and no earlier item share `points`, split evenly, or all-or-nothing when `allOrNothing`.
struct RubricItem {
  std::string name;                ///< shown in reports, e.g. "Task 1: spring force"
  int task = 0;                    ///< a task of harness/tasks.h, or 0 for none
  std::vector<std::string> tests;  ///< globs over "Suite.Test"; a test matching any of them
  double points = 0;
  bool allOrNothing = false;
  bool extraCredit = false;  ///< counts above the total (max_score 0 in results.json)
  Visibility visibility = Visibility::Visible;
  double timeLimitSeconds = 10;  ///< per request of each matching test, s
  /// How many checks the item counts, as the rubric says (`checks`, for an item with a glob: a
  /// check a TA adds then fails the ctest grader_rubric until an item is chosen for it); -1: not
  /// said.
  int checks = -1;
  int line = 0;  ///< where the item starts in the rubric file (for messages)

  /// True when `testName` matches one of the globs (regardless of earlier items).
  bool matches(const std::string& testName) const;
  /// True when every glob names a hidden suite (Task<N>Hidden, GoldenTask<N>Hidden): checks
  /// that only the graders have (tests/hidden, tests/golden/hidden), never a student release.
  bool onHiddenChecks() const;
};

struct Rubric {
  std::string title;
  double totalPoints = 100;  ///< the sum of non-extra-credit points (checked on load)
  std::vector<RubricItem> items;
  std::filesystem::path file;  ///< where it was loaded from
  std::string error;           ///< a clear message with file and line when the file is invalid
  bool ok() const { return error.empty(); }

  /// The index of the item a test counts for: the first whose globs match it; -1 when none.
  int itemFor(const std::string& testName) const;
};

/// Reads and validates a rubric file. Never throws: on any problem `error` says what and where
/// ("rubric.toml:12: unknown key 'point' in [[item]] 3 (did you mean 'points'?)"), with every
/// problem found, one per line.
Rubric loadRubric(const std::filesystem::path& file);
/// The same, from TOML text (`sourceName` names it in messages).
/// `tasks`: the tasks an item's `task` may name.
Rubric parseRubric(const std::string& text, const std::string& sourceName,
                   const TaskTable& tasks = courseTasks());

/// The rubric a student release carries: `rubric` without its items on hidden checks, its total
/// the sum of what is left, as TOML that loadRubric reads back (every value written out).
std::string publicRubricToml(const Rubric& rubric);

/// Glob matching over a whole string: `*` matches any run of characters, `?` any one.
bool globMatch(const std::string& pattern, const std::string& text);

}  // namespace a6::grader
