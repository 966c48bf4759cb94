// Staging the submissions' task files for the comparison. See similarity.h.
#include <system_error>

#include "insights/similarity.h"
#include "intake/intake.h"

namespace a6::grader::insights {

std::vector<SubmissionFiles> stageSubmissions(
    const std::vector<std::pair<std::string, std::filesystem::path>>& keyAndPath,
    const std::filesystem::path& work, std::vector<std::string>& notes) {
  std::error_code ec;
  std::filesystem::remove_all(work, ec);
  std::vector<SubmissionFiles> staged;
  for (std::size_t i = 0; i < keyAndPath.size(); ++i) {
    const auto& [key, path] = keyAndPath[i];
    const std::filesystem::path dest = work / std::to_string(i);
    const Intake intake = takeSubmission(path, dest);
    if (!intake.ok()) {
      notes.push_back(key + ": not compared: " + intake.error);
      continue;
    }
    if (!intake.files.empty()) staged.push_back({key, dest});
  }
  return staged;
}

}  // namespace a6::grader::insights
