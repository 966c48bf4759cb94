// a6_grade: grades one submission (grader/DESIGN.md; its options: a6_grade --help). This file
// only reads the command line; the stages (grading/grading.cpp) write DIR/results.json
// (Gradescope), DIR/report.html and a summary on stdout. Student code never runs in this process:
// the suite's a6::test::student() is the probe.
//
// Exit status: 0 when grading completed, whatever the score (a submission that does not build
// gets its zero with the reasons in the report); 1 when the grader itself failed (missing kit,
// an environment that cannot run the checks, a report that could not be written): results.json
// is still written, with score 0 and the error; 2, before any build, when there is nothing to
// grade (a bad command line, no such submission, no task file in it, an archive that cannot be
// read) or the rubric cannot be used (invalid, or not matching the checks).
#include <sys/prctl.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "checks/checks.h"
#include "common/command_line.h"
#include "common/limits.h"
#include "grading/grading.h"
#include "rubric/rubric.h"
#include "sandbox/sandbox.h"

namespace fs = std::filesystem;
namespace a6::paths {
extern const char rubric[];  // the default rubric (cmake/A6FastBuild.cmake, a6_configured_path)
}  // namespace a6::paths
using namespace a6::grader;

namespace {

struct Options {
  GradeOptions grading;
  std::string rubric;
  bool listTests = false;
  bool checkRubric = false;
  bool listItems = false;
  bool listLimits = false;
  std::string publicRubric;
};

fs::path defaultRubric() {
  if (fs::exists(a6::paths::rubric)) return a6::paths::rubric;
  return besideProgram("rubric.toml");
}

// What is graded, and with what (in --help's order).
void addInputOptions(CLI::App& app, Options& all) {
  GradeOptions& options = all.grading;
  app.add_option("submission", options.submission,
                 "the submission: a folder, or an archive (zip, tar, tar.gz or tgz, tar.bz2, "
                 "tar.xz; recognised by content), or one task file");
  app.add_option("--out", options.out, "where results.json and report.html go (created)");
  app.add_option("--rubric", all.rubric, "the rubric (default: grader/rubric.toml)");
  app.add_option("--seed", options.seed,
                 "the seed of the randomised checks (default: derived from the submission's "
                 "files); the report records it for a regrade");
  app.add_option("--kit", options.kit, "the kit description (default: BUILD/grader/kit.json)");
  app.add_option("--hide", options.hide,
                 "hide this folder or file from the compiler and the probe too, except this "
                 "run's own work folder (a6_batch hides the other submissions and results); "
                 "repeatable")
      ->allow_extra_args(false);  // one path per --hide: never the submission after it
}

// How the grading runs.
void addRunOptions(CLI::App& app, GradeOptions& options) {
  app.add_option("--sandbox-uid", options.sandboxUid,
                 "as root, run the compiler and the probe as this user id (default: a uid drawn "
                 "at random that has no account and no process, claimed for this grading by a "
                 "lock in /run/lock). A uid that some process runs as is refused; each "
                 "sandboxed command runs in a pid namespace of its own, which ends what it "
                 "started (where the kernel refuses one, the uid's processes are ended after "
                 "the grading)")
      ->check(CLI::Range(1u, 4294967294u));
  app.add_option("--jobs", options.jobs,
                 "how many of the seven files are compiled at once (default 2; a6_batch gives 1, "
                 "since it grades several submissions at once)")
      ->check(CLI::Range(1, 64));
  app.add_option("--time-budget", options.timeBudget,
                 "seconds the student's code may take over all checks together (default " +
                     secondsText(kDefaultTimeBudget) +
                     "); checks after that fail unrun, so that a submission that loops in many "
                     "places still gets its results within Gradescope's limit")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_option("--tests", options.filter,
                 "only the checks matching this GoogleTest filter (debugging: the score is then "
                 "partial)");
}

// The commands that grade nothing, and the output's form.
void addCommandOptions(CLI::App& app, Options& options) {
  app.add_flag("--list-tests", options.listTests,
               "print every check and the rubric item it counts for, then exit");
  app.add_flag("--list-items", options.listItems,
               "print each rubric item (name, points, checks, extra or regular, visibility) "
               "and a last line: total, points, checks, extra credit; then exit");
  app.add_flag("--list-limits", options.listLimits,
               "print every time and memory limit of a grading (key, value, unit, what: "
               "grader/common/limits.h), then exit");
  app.add_flag("--check-rubric", options.checkRubric,
               "check the rubric (--rubric, or the default) against every check, then exit: 0 "
               "when it can be used, 2 and each problem with its line and fix when not");
  app.add_option("--public-rubric", options.publicRubric,
                 "write the rubric without its items on hidden checks (for a student release) "
                 "to this file, then exit");
  app.add_flag("--quiet,-q", options.grading.quiet, "no progress on stderr");
  app.add_flag("--color", options.grading.color, "colour the summary");
}

Rubric readRubric(const std::string& file) {
  Rubric rubric;
  try {
    rubric = loadRubric(file.empty() ? defaultRubric() : fs::path(file));
  } catch (const std::exception& e) {
    rubric.error = std::string("cannot load the rubric: ") + e.what();
  }
  return rubric;
}

// --public-rubric FILE: the rubric without its hidden items.
int writePublicRubric(const Rubric& rubric, const std::string& file) {
  if (!rubric.ok()) {
    std::fprintf(stderr, "a6_grade: %s\n", rubric.error.c_str());
    return 1;
  }
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << publicRubricToml(rubric);
  if (!out.flush()) {
    std::fprintf(stderr, "a6_grade: cannot write %s\n", file.c_str());
    return 1;
  }
  return 0;
}

// What the command line asks for, once it is read.
int dispatch(const Options& options) {
  if (options.listLimits) {
    std::fputs(listedLimits().c_str(), stdout);
    return 0;
  }
  const Rubric rubric = readRubric(options.rubric);
  if (!options.publicRubric.empty()) return writePublicRubric(rubric, options.publicRubric);
  if (options.listTests || options.checkRubric || options.listItems) {
    registerChecks(1, options.grading.filter, fs::temp_directory_path() / "a6_grade_list", false);
    if (options.listItems) return listItems(rubric);
    return options.listTests ? listChecks(rubric) : checkRubricAgainstChecks(rubric);
  }
  if (options.grading.submission.empty() || options.grading.out.empty()) {
    std::fprintf(stderr, "a6_grade: give a SUBMISSION and --out DIR (a6_grade --help)\n");
    return 2;
  }
  return grade(options.grading, rubric);
}

}  // namespace

int main(int argc, char** argv) {
  // What a probe leaves running is reparented here, to be ended (process::endStrayChildren).
  prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
  Options options;
  CLI::App app{"a6_grade: grades one Assignment 6 submission (docs/instructor.md)"};
  addInputOptions(app, options);
  addRunOptions(app, options.grading);
  addCommandOptions(app, options);
  if (const std::optional<int> status = parseOrExit(app, argc, argv)) return *status;
  try {
    return dispatch(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "a6_grade: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "a6_grade: internal error\n");
  }
  return 1;
}
