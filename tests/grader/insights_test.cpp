// The class's picture (grader/insights/): results.json read whatever it holds, the class's
// numbers, the checks flagged, and a page that escapes what submissions wrote. End to end
// (a Gradescope export, similarity, Chromium): insights_test.sh.
#include "insights/insights.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "insights/page.h"

namespace a6::grader::insights {
namespace {

namespace fs = std::filesystem;

// A results.json as a6_grade writes it: two items of task 1 (one failed with a named mistake),
// extra credit in task 7, checks, incidents.
std::string results(double springScore, bool springPassed, const std::string& mistake = "",
                    int crashes = 0) {
  const std::string status = springPassed ? "passed" : "failed";
  return R"J({"score": )J" + std::to_string(springScore + 3) + R"J(, "tests": [
    {"name": "Task 1: spring force (7/8 checks)", "number": "1.2", "score": )J" +
         std::to_string(springScore) + R"J(, "max_score": 12, "status": ")J" + status +
         R"J(", "visibility": "visible", "tags": ["task1"], "extra_data": {"mistake": ")J" +
         mistake +
         R"J(", "mistake_text": "Your spring <b>pulls</b> the wrong way"}},
    {"name": "Task 7 extra credit: the implicit step (6/6 checks)", "number": "7.3", "score": 3,
     "max_score": 0, "status": "passed", "tags": ["task7", "extra_credit"]}],
  "extra_data": {"rubric": "A6", "max_score": 12, "tests": {"Task1Spring.A": ")J" +
         status + R"J(", "Task1Spring.B": "passed", "GoldenTask7.x": "passed"},
    "incidents": {"crashes": )J" +
         std::to_string(crashes) + R"J(, "timeouts": 0, "start_failures": 0},
    "build": {"spring.cpp": "compiled", "cloth.cpp": "compile error"}}})J";
}

TEST(Insights, AResultsJsonGivesItsItemsChecksMistakesAndIncidents) {
  const SubmissionResult s = readResults("ada", results(10.5, false, "t1_wrong_sign", 2));
  ASSERT_TRUE(s.total.has_value()) << s.problem;
  EXPECT_DOUBLE_EQ(*s.total, 13.5);
  EXPECT_EQ(s.rubric, "A6");
  ASSERT_EQ(s.items.size(), 2u);
  EXPECT_EQ(s.items[0].name, "Task 1: spring force") << "the check counts are not the item's name";
  EXPECT_EQ(s.items[0].task, 1);
  EXPECT_FALSE(s.items[0].passed);
  EXPECT_EQ(s.items[0].mistake, "t1_wrong_sign");
  EXPECT_TRUE(s.items[1].extraCredit);
  EXPECT_EQ(s.items[1].task, 7);
  EXPECT_DOUBLE_EQ(s.extraCredit, 3);
  EXPECT_EQ(s.checks.size(), 3u);
  EXPECT_FALSE(s.checks.at("Task1Spring.A"));
  EXPECT_EQ(s.incidents.crashes, 2);
  EXPECT_EQ(s.build, "cloth.cpp");
}

TEST(Insights, AnythingElseIsAProblemNotAGrade) {
  for (const std::string& text :
       {std::string(), std::string("{"), std::string("[1,2]"), std::string(R"({"tests": 3})"),
        std::string(R"({"tests": [], "extra_data": {"errors": ["a6_grade did not finish"]}})"),
        std::string(R"({"tests": [7, "x", {"name": 5, "tags": [1, null]}], "score": "high"})")}) {
    const SubmissionResult s = readResults("x", text);
    EXPECT_FALSE(s.total.has_value()) << text;
    EXPECT_FALSE(s.problem.empty()) << text;
  }
}

TEST(Insights, TheClassNumbersCountEachSubmissionOnce) {
  std::vector<SubmissionResult> all;
  all.push_back(readResults("a", results(12, true)));
  all.push_back(readResults("b", results(6, false, "t1_wrong_sign")));
  all.push_back(readResults("c", results(0, false, "t1_wrong_sign")));
  all.push_back(readResults("d", "not json"));
  const ClassInsights c = summarize(all);
  EXPECT_EQ(c.graded, 3);
  ASSERT_EQ(c.items.size(), 2u);
  EXPECT_EQ(c.items[0].name, "Task 1: spring force");
  EXPECT_EQ(c.items[0].full, 1);
  EXPECT_DOUBLE_EQ(c.items[0].lost, 36 - 18);
  EXPECT_DOUBLE_EQ(c.items[0].mean, 6);
  ASSERT_EQ(c.mistakes.size(), 1u);
  EXPECT_EQ(c.mistakes[0].who, (std::vector<std::string>{"b", "c"}));
  EXPECT_EQ(c.mistakes[0].example, "Your spring <b>pulls</b> the wrong way");
  EXPECT_TRUE(c.flags.empty()) << "3 graded submissions are too few to judge a check";
}

// The class by diagnosed part: each results.json's extra_data.diagnoses, counted once per
// submission, most often first, with one student's sentence; junk in the list is left out.
TEST(Insights, TheClassIsGroupedByDiagnosedPart) {
  const auto with = [](const std::string& diagnoses) {
    std::string text = results(6, false);
    text.insert(text.rfind("}}"), R"J(, "diagnoses": )J" + diagnoses);
    return text;
  };
  const std::string elastic =
      R"J({"task": 1, "diagnosis": "t1_elastic", "text": "Your elastic term is 2 times"})J";
  std::vector<SubmissionResult> all;
  all.push_back(readResults("a", with("[" + elastic + ", " + elastic + "]")));
  all.push_back(readResults("b", with("[" + elastic + R"J(, 7, {"diagnosis": 3},
      {"task": 7, "diagnosis": "t7_measured", "text": "Your dfdx differs"}])J")));
  all.push_back(readResults("c", with(R"J("not a list")J")));
  ASSERT_TRUE(all[1].total.has_value()) << all[1].problem;
  const ClassInsights c = summarize(all);
  ASSERT_EQ(c.parts.size(), 2u);
  EXPECT_EQ(c.parts[0].id, "t1_elastic");
  EXPECT_EQ(c.parts[0].task, 1);
  EXPECT_EQ(c.parts[0].who, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(c.parts[0].example, "Your elastic term is 2 times");
  EXPECT_EQ(c.parts[1].id, "t7_measured");
  const std::string page = insightsHtml(c, PageInput{"A6", "out", {}, nullptr});
  EXPECT_NE(page.find("<h2 id=\"parts\">Diagnosed parts</h2>"), std::string::npos);
  EXPECT_NE(page.find("<td><code>t1_elastic</code></td>"), std::string::npos);
}

// A grading of one item worth 12 that names its checks A and B, and which of them failed.
std::string costedResults(double score, bool aPassed, bool bPassed) {
  const auto status = [](bool passed) { return std::string(passed ? "passed" : "failed"); };
  return R"J({"score": )J" + std::to_string(score) + R"J(, "tests": [
    {"name": "Task 1: spring force", "number": "1.2", "score": )J" +
         std::to_string(score) + R"J(, "max_score": 12, "status": ")J" +
         status(aPassed && bPassed) +
         R"J(", "tags": ["task1"], "extra_data": {"points": 12,
       "checks": ["Task1Spring.A", "Task1Spring.B", "Task1Spring.A", 7]}}],
  "extra_data": {"tests": {"Task1Spring.A": ")J" +
         status(aPassed) + R"J(", "Task1Spring.B": ")J" + status(bPassed) +
         R"J(", "GoldenTask1.x": "passed"}}})J";
}

// The row of `check` in the page's checks table.
std::string checkRow(const std::string& page, const std::string& check) {
  const std::size_t at = page.find("<td><code>" + check + "</code></td>");
  return at == std::string::npos ? "" : page.substr(at, page.find("</tr>", at) - at);
}

TEST(Insights, EachCheckCostsItsShareOfThePointsItsItemLost) {
  std::vector<SubmissionResult> all;
  all.push_back(readResults("a", costedResults(6, false, false)));  // 3 each
  all.push_back(readResults("b", costedResults(9, false, true)));   // 3 on A
  all.push_back(readResults("c", costedResults(12, true, true)));
  ClassInsights c = summarize(all);
  std::map<std::string, CheckStats> by;
  for (const CheckStats& check : c.checks) by[check.name] = check;
  EXPECT_TRUE(by.at("Task1Spring.A").costed());
  EXPECT_DOUBLE_EQ(by.at("Task1Spring.A").lost, 6) << "A named twice is counted once";
  EXPECT_DOUBLE_EQ(by.at("Task1Spring.B").lost, 3);
  EXPECT_FALSE(by.at("GoldenTask1.x").costed()) << "no item names it";
  std::string page = insightsHtml(c, PageInput{"A6", "out", {}, nullptr});
  EXPECT_NE(page.find("<th>failed</th><th>points lost</th>"), std::string::npos);
  EXPECT_NE(checkRow(page, "Task1Spring.A").find("data-v=\"6\">6</td>"), std::string::npos)
      << checkRow(page, "Task1Spring.A");
  EXPECT_NE(checkRow(page, "GoldenTask1.x").find("data-v=\"-1\">–</td>"), std::string::npos)
      << "an unknown cost is no 0: " << checkRow(page, "GoldenTask1.x");

  // A results.json written before items named their checks: A's cost is unknown, not 6.
  all.push_back(readResults("d", results(6, false)));
  c = summarize(all);
  page = insightsHtml(c, PageInput{"A6", "out", {}, nullptr});
  EXPECT_NE(checkRow(page, "Task1Spring.A").find("data-v=\"-1\">–</td>"), std::string::npos)
      << checkRow(page, "Task1Spring.A");
}

TEST(Insights, ChecksNearlyEveryoneFailsOrNobodyFailsAreFlagged) {
  std::vector<SubmissionResult> all;
  for (int i = 0; i < 10; ++i) all.push_back(readResults(std::to_string(i), results(6, i == 0)));
  const ClassInsights c = summarize(all);
  std::vector<std::string> fail, pass;
  for (const Flag& f : c.flags) (f.nearlyAllFail ? fail : pass).push_back(f.check);
  EXPECT_EQ(fail, (std::vector<std::string>{"Task1Spring.A"})) << "1 of 10 pass it";
  EXPECT_EQ(pass, (std::vector<std::string>{"GoldenTask7.x", "Task1Spring.B"}));
}

TEST(Insights, TheTaskOfACheckIsItsSuitesTask) {
  EXPECT_EQ(taskOfCheck("Task4Cloth.X"), 4);
  EXPECT_EQ(taskOfCheck("GoldenTask6.car_f90"), 6);
  EXPECT_EQ(taskOfCheck("Task2Hidden.Y"), 2);
  EXPECT_EQ(taskOfCheck("GoldenTask6Hidden.car_f90"), 6);
  EXPECT_EQ(taskOfCheck("Sanity.Z"), 0);
  EXPECT_EQ(taskOfCheck("Task"), 0);
  EXPECT_EQ(taskOfCheck("Task10Rope.X"), 0) << "task 1 read from the 1 of 10";
}

TEST(Insights, ThePageNamesEveryItemAndEscapesWhatSubmissionsWrote) {
  std::vector<SubmissionResult> all;
  all.push_back(readResults("<script>alert(1)</script>", results(6, false, "t1_wrong_sign")));
  all.push_back(readResults("bob", results(12, true)));
  all.back().report = "bob & co/report.html";
  const std::string page = insightsHtml(summarize(all), PageInput{"A6", "out", {}, nullptr});
  EXPECT_NE(page.find("Task 1: spring force"), std::string::npos);
  EXPECT_NE(page.find("Task 7 extra credit: the implicit step"), std::string::npos);
  EXPECT_EQ(page.find("<script>alert"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_EQ(page.find("<b>pulls</b>"), std::string::npos) << "a message is text, not markup";
  EXPECT_NE(page.find("href=\"bob%20%26%20co/report.html\""), std::string::npos);
  for (std::size_t at = page.find("http"); at != std::string::npos;
       at = page.find("http", at + 1)) {
    EXPECT_EQ(page.compare(at, 26, "http://www.w3.org/2000/svg"), 0)
        << "only the SVG namespace names a web address (the page needs no network): "
        << page.substr(at, 40);
  }
}

TEST(Insights, AGradescopeExportIsReadWithItsStudentsNames) {
  const fs::path dir = fs::current_path() / "insights_export";
  fs::remove_all(dir);
  fs::create_directories(dir / "export" / "submission_11");
  fs::create_directories(dir / "export" / "submission_12" / "a");
  fs::create_directories(dir / "export" / "submission_13");
  std::ofstream(dir / "export" / "submission_metadata.yml")
      << "submission_11:\n  :submitters:\n  - :name: Ada Lovelace\n    :sid: '1'\n"
      << "submission_12:\n  :submitters:\n  - :name: Ben Ng\n";
  std::ofstream(dir / "export" / "submission_11" / "results.json") << results(12, true);
  // Ben's own files: a results.json he submitted, and a link to Ada's: neither is his grade.
  std::ofstream(dir / "export" / "submission_12" / "a" / "results.json") << results(12, true);
  fs::create_symlink(dir / "export" / "submission_11" / "results.json",
                     dir / "export" / "submission_13" / "results.json");
  std::vector<std::string> notes;
  const std::vector<SubmissionResult> all = readFolder(dir, notes);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].key, "Ada Lovelace");
  EXPECT_TRUE(all[0].total.has_value());
  EXPECT_EQ(all[1].key, "Ben Ng");
  EXPECT_FALSE(all[1].total.has_value()) << "a results.json among the submitted files";
  EXPECT_EQ(all[2].key, "submission_13");
  EXPECT_FALSE(all[2].total.has_value()) << "a link is not the export's results.json";
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("2 of 3"), std::string::npos) << notes[0];
  EXPECT_EQ(exportedSubmissions(dir).size(), 3u);
}

TEST(Insights, NumbersNoFileShouldHoldAreNoGrade) {
  const SubmissionResult inf = readResults("x", R"({"score": 1e999, "tests": []})");
  EXPECT_FALSE(inf.total.has_value()) << "a number out of range: no results at all";
  const SubmissionResult big = readResults("y", R"J({"score": 3, "tests": [
      {"name": "Task 1: x (99999999999999999999999/1 checks)", "score": -1e308, "max_score": 1e308,
       "tags": ["task1"]}],
      "extra_data": {"incidents": {"crashes": 1e20, "timeouts": -5}}})J");
  ASSERT_TRUE(big.total.has_value());
  EXPECT_EQ(big.items.at(0).name, "Task 1: x");
  EXPECT_EQ(big.items.at(0).max, 1e308);
  EXPECT_EQ(big.incidents.crashes, 1000000000);
  EXPECT_EQ(big.incidents.timeouts, 0);
  const std::string page = insightsHtml(summarize({inf, big}), PageInput{"A6", "out", {}, nullptr});
  EXPECT_NE(page.find("</html>"), std::string::npos);
}

}  // namespace
}  // namespace a6::grader::insights
