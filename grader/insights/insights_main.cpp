// a6_insights: the class's picture (insights.html) for a folder of gradings (grader/insights/).
//
//   a6_insights FOLDER [--out FILE] [--similarity] [--starter DIR] [--threshold P]
//
// FOLDER: a6_batch's output, or Gradescope's "Export Submissions", unzipped (only an export holds
// the submitted files that --similarity compares).
// Exit status: 0 page written; 1 it could not be written; 2 a bad command line or FOLDER.
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/command_line.h"
#include "insights/page.h"

namespace a6::paths {
extern const char starter[];  // the starter files (a6_configured_path)
}  // namespace a6::paths

namespace fs = std::filesystem;
using namespace a6::grader::insights;

int main(int argc, char** argv) {
  std::string folder, out, starter = a6::paths::starter;
  bool similarity = false;
  int threshold = 60;
  CLI::App app{"The class's picture (insights.html) for a folder of gradings"};
  app.add_option("folder", folder, "a6_batch's output folder, or a Gradescope export (unzipped)")
      ->required();
  app.add_option("--out", out, "the page (default: FOLDER/insights.html)");
  app.add_flag("--similarity", similarity, "compare the exported submissions' task files");
  app.add_option("--starter", starter, "the starter files, discounted by the comparison");
  app.add_option("--threshold", threshold, "percent of a file's own code shared to list a pair");
  if (const std::optional<int> status = a6::grader::parseOrExit(app, argc, argv)) return *status;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    std::fprintf(stderr, "a6_insights: %s is not a folder\n", folder.c_str());
    return 2;
  }
  if (out.empty()) out = (fs::path(folder) / "insights.html").string();
  PageInput input;
  SimilarityReport report;
  if (similarity) {
    const fs::path work = fs::path(out).parent_path() / ".a6_insights_similarity";
    std::vector<std::string> notes;
    const auto exported = exportedSubmissions(folder);
    if (exported.empty()) {
      notes.push_back(folder +
                      " is no Gradescope export: its submitted files are not in it "
                      "(a6_batch --similarity compares a batch's submissions)");
    }
    const auto staged = stageSubmissions(exported, work / "files", notes);
    report = compareSubmissions(staged, starter, work / "compare", {}, threshold);
    report.notes.insert(report.notes.begin(), notes.begin(), notes.end());
    fs::remove_all(work, ec);
    input.similarity = &report;
  }
  if (const std::string e = writeInsights(folder, out, input); !e.empty()) {
    std::fprintf(stderr, "a6_insights: %s\n", e.c_str());
    return 1;
  }
  std::printf("a6_insights: %s\n", out.c_str());
  return 0;
}
