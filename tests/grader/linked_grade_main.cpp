// A grading of a file set linked into this program: a6_grade's stages after the build (the
// checks, the images, the mistakes, the replays, the rubric's scores, results.json and
// report.html) with the student's code asked in this process instead of in a sandboxed probe.
// One run of it gives every verdict the suite asks of a wrong version or a correct alternative
// (scores_test.cpp): besides the grading, it prints the physics suite's summary per task with
// the margins (tests/support/summary.h: A6-SUMMARY, A6-MARGIN, A6-CHECK-MARGIN).
//
//   a6_graded_<set> --out DIR [--seed N]     (the report names the program's file set)
//
// The sandbox's promises are proved on real gradings of the solution, the starter and the
// hostile submissions (hostile_test.cpp): the file sets graded here are ours, and never crash.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "grading/grading.h"
#include "harness/student_code.h"
#include "rubric/rubric.h"
#include "summary.h"

namespace {
#include A6_FORCE_MODELS  // the reference force models, as a6_grade answers the probe with them
}  // namespace

int main(int argc, char** argv) {
  a6::grader::GradeOptions options;
  options.submission = argc > 0 ? std::string(argv[0]) : "a6_graded";
  options.seed = 1;
  options.quiet = true;
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string arg = argv[k];
    if (arg == "--out") {
      options.out = argv[k + 1];
    } else if (arg == "--seed") {
      options.seed = std::strtoull(argv[k + 1], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: %s --out DIR [--seed N]\n", argv[0]);
      return 2;
    }
  }
  if (options.out.empty()) {
    std::fprintf(stderr, "usage: %s --out DIR [--seed N]\n", argv[0]);
    return 2;
  }
  const a6::grader::Rubric rubric = a6::grader::loadRubric(A6_DEFAULT_RUBRIC);
  const std::unique_ptr<a6::harness::StudentCode> code =
      a6::harness::makeInProcess(referenceForceModel());
  options.linked = code.get();
  setenv("A6_MARGINS", "1", 1);  // the summary's margin lines
  // Appended before the grading registers the checks: it prints when they have all run.
  ::testing::UnitTest::GetInstance()->listeners().Append(new a6::test::TaskSummary());
  return a6::grader::grade(options, rubric);
}
