// insights.html: the class's picture as one self-contained page (inline CSS, SVG plots and a
// few lines of script to sort the tables; no network). Every text from a submission or a
// results.json is escaped.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "insights/insights.h"
#include "insights/similarity.h"

namespace a6::grader::insights {

struct PageInput {
  std::string title;               ///< the rubric's title, or what the results were read from
  std::string source;              ///< the folder the results were read from
  std::vector<std::string> notes;  ///< what was left out, and why
  const SimilarityReport* similarity = nullptr;  ///< none: the section says how to ask for it
};

std::string insightsHtml(const ClassInsights& insights, const PageInput& input);

/// Reads `folder` (readFolder), sums it and writes the page to `page`; "" or what failed.
/// `input.title` empty: the rubric's title from the results.
std::string writeInsights(const std::filesystem::path& folder, const std::filesystem::path& page,
                          PageInput input);

}  // namespace a6::grader::insights
