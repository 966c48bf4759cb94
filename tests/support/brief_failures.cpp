#include "brief_failures.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include "suite.h"

namespace a6::test {

namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

BriefFailures::BriefFailures(std::string logPath) : logPath_(std::move(logPath)) {}

void BriefFailures::OnTestEnd(const ::testing::TestInfo& info) {
  const ::testing::TestResult& result = *info.result();
  if (!result.Failed()) return;
  Failed f;
  f.name = std::string(info.test_suite_name()) + "." + info.name();
  log_ += "[  FAILED  ] " + f.name + "\n";
  for (int k = 0; k < result.total_part_count(); ++k) {
    const ::testing::TestPartResult& part = result.GetTestPartResult(k);
    if (!part.failed()) continue;
    const std::string where = std::string(part.file_name() ? part.file_name() : "?") + ":" +
                              std::to_string(part.line_number());
    log_ += where + ": Failure\n" + part.message() + "\n";
    if (f.first.empty()) {
      f.first = messageOf(part);
    } else {
      ++f.more;
    }
  }
  failed_.push_back(std::move(f));
}

void BriefFailures::OnTestProgramEnd(const ::testing::UnitTest&) {
  if (failed_.empty()) return;
  std::ofstream(logPath_) << log_;
  std::printf("\n%zu failed check%s, each with its first message:\n", failed_.size(),
              failed_.size() == 1 ? "" : "s");
  int lines = 0;
  std::size_t shown = 0;
  for (; shown < failed_.size(); ++shown) {
    const Failed& f = failed_[shown];
    const std::vector<std::string> message = linesOf(f.first);
    const int needed = 1 + static_cast<int>(message.size()) + (f.more > 0 ? 1 : 0);
    if (shown > 0 && lines + needed > kMaxLines) break;
    std::printf("\nFAILED %s\n", f.name.c_str());
    for (const std::string& line : message) std::printf("  %s\n", line.c_str());
    if (f.more > 0)
      std::printf("  (and %d more failure%s in this check)\n", f.more, f.more == 1 ? "" : "s");
    lines += needed + 1;
  }
  if (shown < failed_.size()) {
    std::printf("\n... and %zu more failed checks.\n", failed_.size() - shown);
  }
  std::printf("\nEvery message in full: %s\n", logPath_.c_str());
  std::fflush(stdout);
}

}  // namespace a6::test
