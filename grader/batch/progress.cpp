// The words of an outcome (see progress.h).
#include "batch/progress.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "common/fixed.h"
#include "sandbox/process.h"

namespace a6::grader::batch {

using Clock = std::chrono::steady_clock;
using process::secondsSince;

std::string points(const Outcome& o) {
  if (!o.total) return "";
  std::ostringstream out;
  const double ec = o.extraCredit.value_or(0);
  out << (*o.total - ec) << "/" << o.max.value_or(0);
  if (ec > 0) out << " +" << ec;
  return out.str();
}

bool hasGrade(const Outcome& o) {
  return o.status == kGraded || o.status == kBuildFailed || o.status == kNotGraded;
}

void Progress::finished(const Submission& s, const Outcome& o) {
  ++done_;
  ++ranNow_;
  secondsNow_ += o.seconds;
  if (!hasGrade(o)) ++failed_;
  std::string line = s.key + ": " + o.status;
  if (o.total) line += ", " + points(o);
  line += " (" + fixed(o.seconds, 1) + " s)";
  if (!o.reason.empty() && o.status != kGraded) line += ": " + o.reason;
  if (tty_) {
    // Problems scroll above the bar; the rest only moves the bar.
    if (!hasGrade(o) || o.status == kBuildFailed) {
      std::fprintf(stderr, "\r\033[K%s\n", line.c_str());
    }
    draw();
  } else {
    std::fprintf(stderr, "[%*d/%d] %s; %s\n", width(), done_, total_, line.c_str(),
                 counters().c_str());
  }
}

void Progress::tick() {
  if (tty_ && secondsSince(lastDraw_) > 0.5) draw();
}

void Progress::clear() {
  if (tty_) std::fprintf(stderr, "\r\033[K");
}

std::string Progress::counters() const {
  std::string text = std::to_string(failed_) + " failed";
  const int left = toRun_ - ranNow_;
  if (left <= 0) return text;
  if (ranNow_ == 0) return text + ", estimating the time left";
  // The mean grading so far, for what is left, `jobs` at a time.
  const double mean = secondsNow_ / ranNow_;
  return text + ", ~" + duration(mean * left / std::min(jobs_, left)) + " left";
}

void Progress::draw() {
  constexpr int kBar = 24;
  const int filled = total_ > 0 ? done_ * kBar / total_ : kBar;
  std::fprintf(stderr, "\r\033[K[%s%s] %d/%d graded, %s", std::string(filled, '#').c_str(),
               std::string(kBar - filled, '.').c_str(), done_, total_, counters().c_str());
  std::fflush(stderr);
  lastDraw_ = Clock::now();
}

}  // namespace a6::grader::batch
