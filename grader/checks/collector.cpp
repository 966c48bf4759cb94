#include "checks/collector.h"

#include <cstdio>

#include "checks/budgeted_student.h"
#include "comparisons.h"
#include "suite.h"

namespace a6::grader {

void Collector::OnTestStart(const ::testing::TestInfo& info) {
  current_ = TestOutcome{};
  current_.name = std::string(info.test_suite_name()) + "." + info.name();
  skipMessage_.clear();
  const int item = rubric_.itemFor(current_.name);
  const double limit = item >= 0 ? rubric_.items[static_cast<std::size_t>(item)].timeLimitSeconds
                                 : kDefaultTimeLimit;
  if (startCheck_) startCheck_(limit);
}

void Collector::OnTestPartResult(const ::testing::TestPartResult& part) {
  if (part.skipped()) {
    skipMessage_ += part.message();
    return;
  }
  if (!part.failed()) return;
  if (!current_.message.empty()) current_.message += "\n";
  current_.message += a6::test::messageOf(part);
}

std::vector<std::filesystem::path> Collector::imagesOf(const ::testing::TestResult& result) {
  std::string images[3];
  for (int k = 0; k < result.test_property_count(); ++k) {
    const ::testing::TestProperty& p = result.GetTestProperty(k);
    const std::string key = p.key();
    if (key == "student_image" || key == "actual_image") images[0] = p.value();
    if (key == "reference_image" || key == "expected_image") images[1] = p.value();
    if (key == "difference_image" || key == "diff_image") images[2] = p.value();
  }
  std::vector<std::filesystem::path> named;
  if (images[0].empty()) return named;
  for (const std::string& image : images) {
    if (!image.empty()) named.push_back(image);
  }
  return named;
}

void Collector::OnTestEnd(const ::testing::TestInfo& info) {
  const ::testing::TestResult& result = *info.result();
  current_.seconds = static_cast<double>(result.elapsed_time()) / 1000.0;
  if (result.Skipped()) {
    // A skipped check is the grader's environment failing (no GL for the images, say): it
    // earns nothing, and the run reports a grader error.
    ++skipped_;
    current_.passed = false;
    current_.message = "not run: " + (skipMessage_.empty() ? "skipped" : skipMessage_) +
                       (current_.message.empty() ? "" : "\n" + current_.message);
  } else {
    current_.passed = result.Passed();
  }
  // Kept only beyond double rounding: the report's float note reads it (comparisons.h).
  const double agreement = a6::test::comparisonsOf(info).agreement;
  current_.agreement = agreement > a6::test::kBeyondDoubleRounding ? agreement : 0;
  current_.images = imagesOf(result);
  if (endCheck_) endCheck_(current_);
  if (progress_) {
    std::fprintf(stderr, "  %-6s %s (%.2f s)\n", current_.passed ? "ok" : "FAILED",
                 current_.name.c_str(), current_.seconds);
  }
  out_.push_back(std::move(current_));
}

}  // namespace a6::grader
