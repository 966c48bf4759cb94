// a6_batch's command line (see command_line.h).
#include "batch/command_line.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <system_error>

#include "common/command_line.h"
#include "common/read_all.h"

namespace a6::paths {
extern const char rubric[];   // the default rubric (cmake/A6FastBuild.cmake, a6_configured_path)
extern const char starter[];  // the starter files, which the similarity discounts
}  // namespace a6::paths

namespace a6::grader::batch {

namespace fs = std::filesystem;

namespace {

// `a6_grade --check-rubric --rubric FILE`: "" when the rubric can be used, else what a6_grade
// said (each problem with its line and fix).
std::string rubricProblems(const fs::path& grader, const fs::path& rubric) {
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) return std::string("pipe: ") + std::strerror(errno);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    dup2(out[1], STDERR_FILENO);
    execl(grader.c_str(), grader.c_str(), "--check-rubric", "--rubric", rubric.c_str(), nullptr);
    _exit(127);
  }
  ::close(out[1]);
  std::string said;
  char buffer[4096];
  for (ssize_t n; (n = read(out[0], buffer, sizeof buffer)) != 0;) {
    if (n > 0) said.append(buffer, static_cast<std::size_t>(n));
    if (n < 0 && errno != EINTR) break;
  }
  ::close(out[0]);
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) != pid) return "cannot run " + grader.string();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  return said.empty() ? grader.string() + " --check-rubric failed" : said;
}

}  // namespace

std::optional<int> parseCommandLine(int argc, char** argv, Options& options) {
  options.starter = a6::paths::starter;
  CLI::App app{
      "a6_batch: grades a folder of Assignment 6 submissions, one a6_grade each "
      "(docs/instructor.md, \"Batch grading\")"};
  app.add_option("input", options.input,
                 "the folder of submissions: one sub-folder or archive per student, or an "
                 "unzipped Gradescope or Canvas export")
      ->required();
  app.add_option("--out", options.out, "where the results and gradebook.csv go (created)")
      ->required();
  app.add_option("-j,--jobs", options.jobs, "submissions graded at once (default: one per core)")
      ->check(CLI::Range(1, 256));
  app.add_option("--timeout", options.timeout,
                 "seconds one submission may take before its a6_grade is killed (default " +
                     secondsText(kBatchTimeout) + ")")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_option("--layout", options.layout,
                 "plain, gradescope or canvas (default: recognised from the folder)")
      ->check(CLI::IsMember({"plain", "gradescope", "canvas"}));
  app.add_flag("--force", options.force, "grade everything again, even what is graded already");
  app.add_option("--grader", options.grader,
                 "the a6_grade to run (default: the one beside a6_batch)");
  app.add_option("--rubric", options.rubric, "passed to a6_grade");
  app.add_option("--kit", options.kit, "passed to a6_grade");
  app.add_option("--seed", options.seed, "passed to a6_grade (default: its own, per submission)");
  app.add_option("--time-budget", options.timeBudget, "passed to a6_grade")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_flag("--keep-work", options.keepWork,
               "keep each a6_grade's work folder (objects, probe; removed by default)");
  app.add_flag("--similarity", options.similarity,
               "compare the submissions' task files with sim_c++ (listed in insights.html)");
  app.add_option("--starter", options.starter, "the starter files the similarity discounts");
  return parseOrExit(app, argc, argv);
}

std::string checkPaths(const Options& options, fs::path& input, fs::path& out, fs::path& grader) {
  std::error_code ec;
  input = fs::absolute(options.input).lexically_normal();
  if (!fs::exists(input, ec)) return "no such folder: " + options.input;
  if (!fs::is_directory(input, ec)) {
    return options.input +
           " is not a folder (unzip an export first; a6_grade grades one archive on its own)";
  }
  out = fs::absolute(options.out).lexically_normal();
  if (fs::exists(out, ec) && fs::equivalent(out, input, ec)) {
    return "--out must not be the input folder itself";
  }
  fs::create_directories(out, ec);
  if (ec) return "cannot create " + out.string() + ": " + ec.message();
  grader = options.grader.empty() ? besideProgram("a6_grade") : fs::absolute(options.grader);
  if (access(grader.c_str(), X_OK) != 0) {
    return "cannot run the grader " + grader.string() +
           " (build a6_grade beside a6_batch, or give --grader)";
  }
  return "";
}

std::string checkRubric(const Options& options, const fs::path& grader) {
  if (options.rubric.empty()) return "";
  std::error_code ec;
  if (!fs::is_regular_file(options.rubric, ec)) return "no rubric file " + options.rubric;
  std::string problems = rubricProblems(grader, fs::absolute(options.rubric));
  if (problems.empty()) return "";
  while (!problems.empty() && problems.back() == '\n') problems.pop_back();
  return "the rubric " + options.rubric + " cannot be used:\n" + problems;
}

std::string lockOutput(const fs::path& out) {
  const fs::path lockFile = out / ".a6_batch.lock";
  const int lock = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock < 0 || flock(lock, LOCK_EX | LOCK_NB) != 0) {
    return "another a6_batch is writing to " + out.string() + " (" + lockFile.string() + ")";
  }
  return "";
}

std::string decidingOptions(const Options& options) {
  std::ostringstream decides;
  const fs::path rubric =
      options.rubric.empty() ? fs::path(a6::paths::rubric) : fs::path(options.rubric);
  decides << "rubric=" << (rubric.empty() ? std::string("default") : readAll(rubric)) << "\n"
          << "seed=" << (options.seed ? std::to_string(*options.seed) : "default") << "\n"
          << "time-budget="
          << (options.timeBudget ? std::to_string(*options.timeBudget) : "default") << "\n";
  return decides.str();
}

}  // namespace a6::grader::batch
