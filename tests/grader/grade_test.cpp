// a6_grade end to end: the command line, a bad rubric, and whole submissions (the solution gets
// full marks, the starter nothing, a broken task costs that task only), graded twice the same.
//
// Each case is its own ctest entry (--gtest_filter), so they run in parallel.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "rubric/rubric.h"
#include "run_command.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using Outcome = a6::test::CommandRun;

Outcome run(const std::string& command) { return a6::test::runCommand(command); }

// A fresh output folder for one case, inside the build tree (ctest's working directory).
fs::path outDir(const std::string& name) {
  const fs::path dir = fs::absolute("grade_test_out") / name;
  fs::remove_all(dir);
  return dir;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

json results(const fs::path& out) {
  const std::string text = readAll(out / "results.json");
  EXPECT_FALSE(text.empty()) << "no results.json in " << out;
  return json::parse(text, nullptr, false);
}

Outcome grade(const fs::path& submission, const fs::path& out, const std::string& extra = "") {
  return run(std::string(A6_GRADE_COMMAND) + " '" + submission.string() + "' --out '" +
             out.string() + "' --quiet --seed 7 " + extra);
}

const json* item(const json& r, const std::string& prefix) {
  for (const json& t : r["tests"]) {
    if (t["name"].get<std::string>().rfind(prefix, 0) == 0) return &t;
  }
  ADD_FAILURE() << "no item named " << prefix << "... in " << r.dump(2);
  return nullptr;
}

TEST(GradeCommand, ABadCommandLineExitsWith2) {
  EXPECT_EQ(run(A6_GRADE_COMMAND).status, 2);
  EXPECT_EQ(run(std::string(A6_GRADE_COMMAND) + " --no-such-option").status, 2);
  const Outcome help = run(std::string(A6_GRADE_COMMAND) + " --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--rubric"), std::string::npos) << help.output;
}

TEST(GradeCommand, ABadRubricStopsBeforeAnyBuildWithExit2AndTheLine) {
  const fs::path out = outDir("bad_rubric");
  fs::create_directories(out);
  std::ofstream(out / "bad.toml")
      << "total = 10\n[[item]]\nname = \"a\"\ntests = \"*\"\npoint = 10\n";
  const Outcome r =
      grade(A6_SOURCE_DIR "/solution", out, "--rubric '" + (out / "bad.toml").string() + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("bad.toml:5: unknown key 'point'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out / "work" / "build")) << "nothing was built";
  const json j = results(out);  // still there for Gradescope, with the error
  EXPECT_EQ(j["score"], 0);
  const std::string output = j["output"];
  EXPECT_NE(output.find("rubric cannot be used (a grader problem, not yours"), std::string::npos)
      << output;
  EXPECT_NE(j["extra_data"]["errors"].dump().find("the rubric is invalid"), std::string::npos)
      << "the details, for instructors";
}

// A rubric whose item matches no check (its points could never be earned) is refused as early,
// and --check-rubric says so without grading anything.
TEST(GradeCommand, ARubricItemThatMatchesNoCheckIsRefusedWithItsLine) {
  const fs::path out = outDir("rubric_no_match");
  fs::create_directories(out);
  std::string rubric = readAll(A6_SOURCE_DIR "/grader/rubric.toml");
  const std::size_t at = rubric.find("\"Task1Spring.*\"");
  ASSERT_NE(at, std::string::npos);
  rubric.replace(at + 1, 11, "Task1Sprung");
  std::ofstream(out / "typo.toml") << rubric;
  const std::string file = (out / "typo.toml").string();
  const Outcome checked =
      run(std::string(A6_GRADE_COMMAND) + " --check-rubric --rubric '" + file + "'");
  EXPECT_EQ(checked.status, 2) << checked.output;
  EXPECT_NE(checked.output.find("item 'Task 1: spring force' matches no check"), std::string::npos)
      << checked.output;
  EXPECT_NE(checked.output.find(file + ":"), std::string::npos) << "names the line";
  const Outcome r = grade(A6_SOURCE_DIR "/solution", out, "--rubric '" + file + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_FALSE(fs::exists(out / "work" / "build")) << "nothing was built";
  // The student reads that the grader has a problem, never the checks' names (some hidden).
  const std::string shown = results(out)["output"];
  EXPECT_NE(shown.find("rubric cannot be used (a grader problem, not yours"), std::string::npos)
      << shown;
  EXPECT_EQ(shown.find("Task1Spring."), std::string::npos) << shown;
  EXPECT_EQ(results(out)["extra_data"]["errors"].size(), 1u) << "the details, for instructors";

  const Outcome good = run(std::string(A6_GRADE_COMMAND) + " --check-rubric");
  EXPECT_EQ(good.status, 0) << good.output;
  EXPECT_NE(good.output.find("valid"), std::string::npos) << good.output;
}

// A path that does not exist, an empty folder, an archive that is no archive: one line naming
// the problem, exit status 2, nothing built; results.json (for Gradescope) says why, score 0.
TEST(GradeCommand, NoSubmissionToGradeStopsEarlyWithExit2) {
  const fs::path base = outDir("bad_input");
  fs::create_directories(base / "empty");
  fs::create_directories(base / "misnamed");
  std::ofstream(base / "misnamed" / "Spring.cpp") << "// a near miss\n";
  std::ofstream(base / "junk.zip") << "PK\x03\x04 not really a zip";
  const struct {
    std::string submission, says;
  } cases[] = {{"/nonexistent/submission.zip", "does not exist"},
               {(base / "empty").string(), "none of the task files (spring.cpp"},
               // The intake's notes come along: here, why Spring.cpp was not taken.
               {(base / "misnamed").string(), "ignored: the name must be exactly"},
               {(base / "junk.zip").string(), "cannot read"}};
  int n = 0;
  for (const auto& c : cases) {
    const fs::path out = base / ("out" + std::to_string(++n));
    const Outcome r = grade(c.submission, out);
    EXPECT_EQ(r.status, 2) << c.submission << "\n" << r.output;
    EXPECT_NE(r.output.find("a6_grade: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("graded with the starter code"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "work" / "build")) << "nothing was built for " << c.submission;
    const json j = results(out);
    EXPECT_EQ(j["score"], 0);
    EXPECT_EQ(j["tests"].size(), 0u) << "no item was graded";
    EXPECT_NE(j["output"].get<std::string>().find("Not graded: "), std::string::npos) << j;
    EXPECT_NE(j["output"].get<std::string>().find(c.says), std::string::npos) << j["output"];
  }
}

TEST(GradeSubmission, TheSolutionGetsFullMarksAndTheExtraCredit) {
  const fs::path out = outDir("solution");
  const Outcome r = grade(A6_SOURCE_DIR "/solution", out);
  EXPECT_EQ(r.status, 0) << r.output;
  const json j = results(out);
  // The rubric's own numbers (an instructor's rubric has its own: read, never pinned).
  const a6::grader::Rubric rubric = a6::grader::loadRubric(A6_DEFAULT_RUBRIC);
  ASSERT_TRUE(rubric.ok()) << rubric.error;
  double extra = 0;
  for (const auto& item : rubric.items) extra += item.extraCredit ? item.points : 0;
  EXPECT_EQ(j["extra_data"]["max_score"].get<double>(), rubric.totalPoints);
  EXPECT_EQ(j["extra_data"]["extra_credit"].get<double>(), extra);
  EXPECT_EQ(j["score"].get<double>(), rubric.totalPoints + extra) << r.output;
  for (const json& t : j["tests"]) EXPECT_EQ(t["status"], "passed") << t;
  EXPECT_EQ(j["extra_data"]["seed"], "7");
  EXPECT_NE(r.output.find("total"), std::string::npos) << "the summary on stdout";
  EXPECT_TRUE(fs::exists(out / "report.html"));
}

TEST(GradeSubmission, TheStarterGetsNothing) {
  const fs::path out = outDir("starter");
  const Outcome r = grade(A6_SOURCE_DIR "/starter", out);
  EXPECT_EQ(r.status, 0) << r.output;
  const json j = results(out);
  EXPECT_EQ(j["score"], 0) << r.output;
  for (const json& t : j["tests"]) {
    // Items worth points fail; the 0-point sanity items hold what a stub passes.
    if (t["max_score"] > 0) {
      EXPECT_EQ(t["status"], "failed") << t;
    }
    EXPECT_EQ(t["score"], 0) << t;
  }
}

TEST(GradeSubmission, ABrokenTaskCostsThatTaskOnlyAndItsMessagesAreEscaped) {
  const fs::path out = outDir("broken_cloth");
  const fs::path submission = out.parent_path() / "broken_cloth_submission";
  fs::remove_all(submission);
  fs::create_directories(submission);
  for (const char* file :
       {"spring.cpp", "forces.cpp", "time_stepping.cpp", "particle_system.cpp", "joints.cpp"}) {
    fs::copy_file(fs::path(A6_SOURCE_DIR "/solution") / file, submission / file);
  }
  std::ofstream(submission / "cloth.cpp") << "#include \"a6/cloth.h\"\n"
                                             "#error <script>alert(1)</script>\n";
  const Outcome r = grade(submission, out);
  EXPECT_EQ(r.status, 0) << r.output;
  const json j = results(out);
  const json* cloth = item(j, "Task 4: cloth");
  ASSERT_NE(cloth, nullptr);
  EXPECT_EQ((*cloth)["score"], 0);
  const std::string output = (*cloth)["output"];
  EXPECT_NE(output.find("cloth.cpp did not compile: graded with the starter code"),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("alert(1)"), std::string::npos) << "the compiler's message is shown";
  for (const char* other : {"Task 1:", "Task 2:", "Task 5:", "Task 6: joints"}) {
    const json* t = item(j, other);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ((*t)["score"], (*t)["max_score"]) << other << " must not pay for task 4";
  }
  const std::string html = readAll(out / "report.html");
  EXPECT_EQ(html.find("<script>alert(1)"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
}

}  // namespace
