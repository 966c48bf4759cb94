// Code similarity between a batch's submissions, task file by task file, with Debian's
// similarity-tester (sim_c++, run on this machine: no code leaves it).
//
// Why sim_c++: it compares C++ token by token, blind to layout, comments and identifiers, and
// gives the shared runs' lines, shown side by side. Dolos does the same but needs Node.js.
//
// Discounted: the starter's lines (blanked first), and runs that more than kCommonShare of the
// class share (the formulas every solution writes alike). A pair is listed when the rare runs
// cover at least `threshold` percent of either file's own code.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace a6::grader::insights {

/// One run two files share: where it lies in each, and its text in each.
struct SharedPassage {
  int firstA = 0, lastA = 0, firstB = 0, lastB = 0;  ///< lines, from 1
  int tokens = 0;
  std::string textA, textB;
};

struct SimilarPair {
  std::string a, b;      ///< submission keys, a < b
  std::string taskFile;  ///< "spring.cpp"
  int percent = 0;       ///< of one file's own code that the rare runs cover (the larger)
  std::vector<SharedPassage> passages;
};

struct SimilarityReport {
  std::string tool;                ///< the program and its version, or "" when it is missing
  int threshold = 0;               ///< percent
  int minimumRun = 0;              ///< tokens
  int compared = 0;                ///< files compared, over all task files
  std::vector<SimilarPair> pairs;  ///< highest percent first
  std::vector<std::string> notes;  ///< what could not be compared, and why
  bool stopped = false;            ///< asked to stop before the last task file was compared
};

/// A submission's key and the folder holding its task files.
struct SubmissionFiles {
  std::string key;
  std::filesystem::path folder;
};

/// The task files of each submission (a folder or an archive, read by the grader's intake with
/// its limits) copied into work/<n>/; one that cannot be read is a note.
std::vector<SubmissionFiles> stageSubmissions(
    const std::vector<std::pair<std::string, std::filesystem::path>>& keyAndPath,
    const std::filesystem::path& work, std::vector<std::string>& notes);

/// A share of the class (the pair left out) above which a shared line is common, not evidence.
inline constexpr double kCommonShare = 0.34;

/// Asked often while the comparison runs: true to stop it (a6_batch's Ctrl-C).
using StopAsked = std::function<bool()>;

/// Compares every pair of submissions task file by task file. `work`: a scratch folder
/// (emptied); `stop` (may be empty) ends it early, with a note of what was not compared. Never
/// throws: a missing tool or an unreadable file is a note.
SimilarityReport compareSubmissions(const std::vector<SubmissionFiles>& submissions,
                                    const std::filesystem::path& starter,
                                    const std::filesystem::path& work, const StopAsked& stop = {},
                                    int threshold = 60, int minimumRun = 20);

}  // namespace a6::grader::insights
