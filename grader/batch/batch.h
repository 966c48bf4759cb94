// Grading a folder of submissions (a6_batch): finding them in the layouts TAs receive, reading
// what a6_grade wrote for each, the gradebook, the resume markers and the summary. The processes
// are batch_main.cpp's, the command line command_line.*'s, the progress bar progress.*'s.
//
// Layouts of the input folder:
//   plain       each sub-folder or archive (.zip .tar .tar.gz .tgz) is one student, named by
//               the folder or by the archive's name without its extension;
//   gradescope  Gradescope's "Export Submissions", unzipped: submission_metadata.yml and one
//               submission_<id>/ folder per submission (the YAML names the submitters);
//   canvas      Canvas's "Download Submissions", unzipped: a flat folder of
//               <login>_<userid>_<submissionid>_<name> files (<login>_LATE_... when late), staged
//               per student under their original names before grading.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/tasks.h"

namespace a6::grader::batch {

enum class Layout { Plain, Gradescope, Canvas };
const char* toString(Layout layout);
/// "plain", "gradescope", "canvas"; nullopt for anything else.
std::optional<Layout> layoutNamed(const std::string& name);

/// Someone a submission is graded for (a Gradescope group submission has several).
struct Person {
  std::string name;
  std::string email;  ///< empty when the layout does not say
  std::string sid;    ///< student id (Gradescope's :sid:, Canvas's user id), or empty
};

struct Submission {
  /// Its folder under the output folder: unique in the batch, a safe file name, stable from one
  /// run to the next (the resume finds its marker there).
  std::string key;
  /// What a6_grade grades: a folder or an archive. For Canvas, empty until staged (stage()).
  std::filesystem::path path;
  /// Canvas: the student's files, each with the name it had when uploaded.
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  std::vector<Person> people;      ///< never empty: one row of the gradebook each
  std::vector<std::string> notes;  ///< for the summary (a group, a missing metadata entry, ...)
};

struct Inventory {
  Layout layout = Layout::Plain;
  std::vector<Submission> submissions;  ///< sorted by key
  std::vector<std::string> notes;       ///< entries that are no submission, and why
  std::string error;                    ///< the folder could not be read at all
};

/// The layout a folder looks like: Gradescope when it (or its only sub-folder) holds
/// submission_metadata.yml; Canvas when most of its entries are files named the Canvas way and
/// none is a folder; plain otherwise. `exclude`: as for findSubmissions.
Layout detectLayout(const std::filesystem::path& input, const std::filesystem::path& exclude = {});

/// The folder of a Gradescope export: `input` itself, or its only sub-folder (hidden ones, links
/// and `exclude` aside) when it holds submission_metadata.yml (the export zip unzips to
/// assignment_<id>_export/); else empty.
std::filesystem::path gradescopeRoot(const std::filesystem::path& input,
                                     const std::filesystem::path& exclude = {});

/// Every submission in `input`, read as `layout`. `exclude` (the output folder, when it lies
/// inside the input) is never taken for a submission.
Inventory findSubmissions(const std::filesystem::path& input, Layout layout,
                          const std::filesystem::path& exclude = {});

/// submission_metadata.yml: "submission_<id>" -> its submitters (:name:, :email:, :sid:); empty
/// when it is not a YAML map.
std::map<std::string, std::vector<Person>> parseGradescopeMetadata(const std::string& yaml);

/// A file name as Canvas writes it into "Download Submissions".
struct CanvasName {
  std::string login;  ///< the student's login (Canvas: sortable name, lower case)
  std::string userId;
  std::string submissionId;  ///< Canvas's attachment id
  std::string original;      ///< the name as uploaded, Canvas's "-N" re-upload suffix removed
  int reupload = 0;          ///< N of that suffix (0: none): a higher N is a later upload
  bool late = false;
};
std::optional<CanvasName> parseCanvasName(const std::string& fileName);

/// Canvas: copies the submission's files into `dir` (emptied first) under their original names
/// and sets `path`: `dir`, or the one archive the student uploaded. Returns "" or what failed.
std::string stage(Submission& submission, const std::filesystem::path& dir);

/// A file name made from any text: letters, digits, '.', '-', '_' (no leading '.'), never empty.
std::string safeName(const std::string& text);

/// 16 hex digits over the submission's files (names, kinds, contents; links by their target) and
/// `options` (what else decides the grade: the rubric's text, the seed, ...).
std::string fingerprint(const Submission& submission, const std::string& options);

/// Statuses in the gradebook.
inline constexpr const char* kGraded = "graded";
inline constexpr const char* kBuildFailed = "build failed";  ///< a task file missing or broken
inline constexpr const char* kGraderError = "grader error";  ///< a6_grade exit 1, no results
inline constexpr const char* kTimedOut = "timed out";        ///< killed at --timeout
inline constexpr const char* kCrashed = "crashed";           ///< a6_grade died of a signal
/// a6_grade exit 2: no task file in it, or an archive that cannot be read (0 points).
inline constexpr const char* kNotGraded = "not graded";

/// One submission's outcome: a gradebook row without the people.
struct Outcome {
  std::string status = kGraderError;
  /// Present when graded (or with a failed build): the total (extra credit included), the
  /// rubric's maximum, each task's regular points, the extra credit.
  std::optional<double> total, max;
  std::vector<std::optional<double>> tasks =
      std::vector<std::optional<double>>(static_cast<std::size_t>(courseTasks().count()));
  std::optional<double> extraCredit;
  double seconds = 0;  ///< a6_grade's wall-clock time
  std::string reason;  ///< why it is not "graded" (for the summary)
  /// Graded, but for a TA to look at (extra_data.incidents): "the code crashed 3 times".
  std::vector<std::string> flags;
  /// The known mistakes the report named, by id (results.json's extra_data.mistakes).
  std::vector<std::string> mistakes;
  bool hasPoints() const { return total.has_value(); }
};

/// The outcome a6_grade's results.json gives: graded; build failed (extra_data.build); not
/// graded (extra_data.refused); or a grader error when it is missing, invalid or unfinished.
/// Per-task points: the tests summed by their "task<N>" tag, "extra_credit" apart.
Outcome outcomeOfResults(const std::string& resultsJson);

/// The marker written last into a graded submission's folder: its fingerprint and outcome.
std::string markerJson(const std::string& fingerprint, const Outcome& outcome);
/// The outcome a marker records, if it is valid and has this fingerprint.
std::optional<Outcome> outcomeOfMarker(const std::string& markerText,
                                       const std::string& fingerprint);

/// One CSV field: quoted when it holds a comma, a quote, a line break or leading or trailing
/// space (quotes doubled).
std::string csvField(const std::string& text);

/// gradebook.csv: `student,email,sid,total,max,task1..task<N>,extra_credit,status,seconds,mistakes`
/// (a column per task of `tasks`; the mistakes' ids, space-separated), a row per person of each
/// submission with an outcome, in key order. Points are blank for a submission without a grade
/// (grader error, timed out, crashed).
std::string gradebookCsv(const std::vector<std::pair<const Submission*, const Outcome*>>& graded,
                         const TaskTable& tasks = courseTasks());

/// How many submissions each known mistake was named for, most often first (ties by id), one
/// line each; "" when none was named.
std::string mistakeCounts(const std::vector<const Outcome*>& outcomes);

/// A text histogram of `totals` in 10-point bins (0-9, 10-19, ...), one line per bin up to the
/// highest total.
std::string histogram(const std::vector<double>& totals);

/// "3m10s", "42s", "1h02m".
std::string duration(double seconds);

}  // namespace a6::grader::batch
