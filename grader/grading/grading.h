// One grading, stage by stage (grader/DESIGN.md): intake (submission -> files), the checks
// registered and matched with the rubric, build (files -> a probe that starts), checks (the
// suite and the images against the probe), scoring (rubric -> points), report (results.json,
// report.html, the terminal summary). grade() calls each stage once, in that order; a stage's
// failure becomes an error in the report, never a crash.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "checks/checks.h"
#include "common/limits.h"
#include "harness/student_code.h"
#include "rubric/rubric.h"

namespace a6::grader {

/// What a6_grade's command line says about one grading (grader/main.cpp).
struct GradeOptions {
  std::string submission;             ///< a folder, an archive or one task file
  std::string out;                    ///< where results.json and report.html go
  std::string kit;                    ///< the kit description ("": BUILD/grader/kit.json)
  std::vector<std::string> hide;      ///< more secrets: a batch's other submissions and results
  std::optional<uid_t> sandboxUid;    ///< who compiles and runs the probe, as root (default: a free
                                      ///< uid claimed for this grading, sandbox/process.h)
  std::optional<std::uint64_t> seed;  ///< default: a hash of the files taken
  int jobs = 2;                       ///< files compiled at once
  double timeBudget = kDefaultTimeBudget;
  std::string filter;  ///< only the checks matching this GoogleTest filter
  bool quiet = false;
  bool color = false;
  /// The student's code linked into this program (the tests' grading of a wrong version or a
  /// correct alternative, tests/grader/linked_grade_main.cpp), or null: a6_grade's own. With it,
  /// nothing is taken in, built or sandboxed: the checks ask it, and `seed` is required.
  harness::StudentCode* linked = nullptr;
};

/// Grades one submission. Exit status: 0 when grading completed, whatever the score; 1 when the
/// grader itself failed (results.json still says why, with score 0); 2, before any build, when
/// there is nothing to grade or the rubric cannot be used.
int grade(const GradeOptions& options, const Rubric& rubric);

}  // namespace a6::grader
