// a6_batch's progress on stderr, and the words it shows an outcome in. Takes each finished
// grading's outcome; gives a bar redrawn in place on a terminal, or a line per grading (CI logs).
#pragma once

#include <chrono>
#include <string>

#include "batch/batch.h"

namespace a6::grader::batch {

/// An outcome's points: "87/100 +3", or "" without a total.
std::string points(const Outcome& o);
/// An outcome that stands (a re-run skips it): points, even 0 for a submission with nothing to
/// grade in it.
bool hasGrade(const Outcome& o);

class Progress {
 public:
  Progress(int total, int done, int toRun, int jobs, bool tty)
      : total_(total), done_(done), toRun_(toRun), jobs_(jobs), tty_(tty) {}

  void finished(const Submission& s, const Outcome& o);
  void tick();  ///< redraws the bar now and then
  void clear();

 private:
  int width() const { return static_cast<int>(std::to_string(total_).size()); }
  std::string counters() const;
  void draw();

  int total_, done_, toRun_, jobs_;
  int ranNow_ = 0, failed_ = 0;
  double secondsNow_ = 0;  // of the gradings of this run
  bool tty_;
  std::chrono::steady_clock::time_point lastDraw_{};
};

}  // namespace a6::grader::batch
