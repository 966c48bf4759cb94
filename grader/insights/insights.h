// The class's picture after a batch (insights.html): the results.json files of a6_batch's output
// folder or of a Gradescope export, summed over the submissions. Any of them may be missing,
// broken or hostile (a submission's own text is in its messages). The page is page.h's.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/tasks.h"

namespace a6::grader::insights {

/// One rubric item of one submission, as results.json's "tests" entry gives it.
struct ItemResult {
  std::string name;    ///< the rubric item's name, without a6_grade's " (k/n checks)"
  std::string number;  ///< "4.3": the task, then the item's place in it
  int task = 0;        ///< from the "task<N>" tag; 0 when none
  bool extraCredit = false;
  bool passed = false;              ///< every check of it passed
  double score = 0, max = 0;        ///< max 0 for extra credit and for items without points
  std::optional<double> worth;      ///< what the item is worth (extra_data.points), when given
  std::string mistake;              ///< the named mistake behind its failures (an id), or ""
  std::string mistakeText;          ///< what the report told the student about it
  std::vector<std::string> checks;  ///< its checks (extra_data.checks; none in older results),
                                    ///< at most kMostChecksOfAnItem
};

/// Counts of what went wrong while the code ran (results.json's extra_data.incidents).
struct Incidents {
  int crashes = 0, timeouts = 0, startFailures = 0;
};

struct MistakeStats {
  std::string id, example;  ///< example: the message one student got
  int task = 0;
  std::vector<std::string> who;  ///< the submissions it was named for
};

/// One submission: its results, or why there are none.
struct SubmissionResult {
  std::string key;     ///< its name in the batch (a6_batch's folder) or Gradescope's submitters
  std::string rubric;  ///< the rubric's title (extra_data.rubric), or ""
  std::string report;  ///< the path of its report.html relative to the page, or ""
  std::optional<double> total;  ///< extra credit included; none when it has no grade
  double max = 0, extraCredit = 0;
  std::string problem;  ///< why it has no grade ("no results.json", a grader error), or ""
  std::string build;    ///< the task files that did not compile ("" when all did)
  std::vector<ItemResult> items;
  std::map<std::string, bool> checks;  ///< each check the grading ran: passed?
  /// The diagnosis by measurement of each failing task (extra_data.diagnoses): its id (the
  /// task and the parts, "t1_elastic"), its task and its sentence.
  std::vector<MistakeStats> diagnoses;
  Incidents incidents;
};

/// The results.json text of one submission, read: anything unreadable becomes `problem`.
SubmissionResult readResults(const std::string& key, const std::string& resultsJson);

/// Every submission of a6_batch's output (results.json, or batch.json when the grading failed)
/// or of a Gradescope export (one without results.json has that problem); `notes`: what was
/// left out and why.
std::vector<SubmissionResult> readFolder(const std::filesystem::path& folder,
                                         std::vector<std::string>& notes);

/// A Gradescope export's submitted folders, each with its key as readFolder names it; empty
/// for any other folder (a6_batch's output holds no submitted files).
std::vector<std::pair<std::string, std::filesystem::path>> exportedSubmissions(
    const std::filesystem::path& folder);

struct ItemStats {
  std::string name, number;
  int task = 0;
  bool extraCredit = false;
  double points = 0;  ///< what the item is worth (its extra credit for an extra-credit item)
  int graded = 0;     ///< submissions graded on it
  int full = 0;       ///< ... that got all its points (for a 0-point item: that passed it)
  double lost = 0;    ///< points the class lost on it, summed (extra credit not earned, too)
  double mean = 0;    ///< mean points
};

struct CheckStats {
  std::string name;
  int task = 0;  ///< its suite's task (harness/tasks.h); 0 when none
  int ran = 0, passed = 0;
  /// Points the class lost on it: each grading's points lost on an item, shared among the item's
  /// checks it failed. Known (costed) only when every grading that ran it named them (a
  /// results.json written before the checks were named did not).
  double lost = 0;
  int costedRuns = 0;
  bool costed() const { return ran > 0 && costedRuns == ran; }
  double passRate() const { return ran == 0 ? 0 : double(passed) / ran; }
};

/// A check to look at: nearly everyone fails it (is it broken, or the lesson missing?) or
/// nobody does (does it catch anything?).
struct Flag {
  std::string check;
  bool nearlyAllFail = false;
};

struct ClassInsights {
  std::vector<SubmissionResult> submissions;  ///< sorted by key
  std::vector<ItemStats> items;               ///< by number
  std::vector<CheckStats> checks;             ///< by name
  std::vector<MistakeStats> mistakes;         ///< most often named first
  std::vector<MistakeStats> parts;            ///< the diagnosed parts, most often first
  std::vector<Flag> flags;
  int graded = 0;  ///< submissions with a grade
};

/// An item's list of checks longer than this is cut (a results.json is untrusted).
inline constexpr std::size_t kMostChecksOfAnItem = 10000;

/// Checks are flagged only in a class of at least this many graded submissions.
inline constexpr int kFlagMinimum = 5;
/// "Nearly everyone fails": a pass rate at or below this.
inline constexpr double kNearlyAllFail = 0.10;

ClassInsights summarize(std::vector<SubmissionResult> submissions);

/// The task a check belongs to, by its suite in `tasks` (harness/tasks.h); 0 for none.
int taskOfCheck(const std::string& check, const TaskTable& tasks = courseTasks());

}  // namespace a6::grader::insights
