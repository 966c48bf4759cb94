// Scoring arithmetic and the three reports: results.json in Gradescope's format (written
// atomically), the HTML report (self-contained, student text escaped), the terminal summary.
#include "report/report.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "report/replay_html.h"

namespace a6::grader {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const char* const kRubric = R"(title = "Test rubric"
total = 30

[[item]]
name = "Task 1: spring"
task = 1
tests = "Task1Spring.*"
points = 15

[[item]]
name = "Task 4 extra: bending"
task = 4
tests = "Task4Cloth.Bending*"
points = 3
extra_credit = true

[[item]]
name = "Task 4: cloth"
task = 4
tests = "Task4Cloth.*"
points = 9
visibility = "after_due_date"

[[item]]
name = "Task 6: mouse"
task = 6
tests = "Task6Joints.Mouse*"
points = 6
all_or_nothing = true
visibility = "hidden"
)";

Rubric rubric() {
  Rubric r = parseRubric(kRubric, "test.toml");
  EXPECT_TRUE(r.ok()) << r.error;
  return r;
}

TestOutcome outcome(const std::string& name, bool passed, const std::string& message = "") {
  TestOutcome t;
  t.name = name;
  t.passed = passed;
  t.message = message;
  t.seconds = 0.25;
  return t;
}

// A run: task 1 two of three, cloth one of two plus bending, mouse one of two.
GradeReport sampleReport() {
  GradeReport report;
  report.submission = "alice.zip";
  report.seed = 4242;
  report.tests = {outcome("Task1Spring.A", true),
                  outcome("Task1Spring.B", true),
                  outcome("Task1Spring.C", false, "expected (0, 1)\n  hint: check the sign"),
                  outcome("Task4Cloth.BendingSprings", true),
                  outcome("Task4Cloth.Count", true),
                  outcome("Task4Cloth.Rest", false, "rest length wrong"),
                  outcome("Task6Joints.MouseA", true),
                  outcome("Task6Joints.MouseB", false, "no")};
  report.intake.files["spring.cpp"] = "/work/src/spring.cpp";
  report.build.tasks.push_back(TaskBuild{"spring.cpp", TaskBuild::Status::Compiled, "", 0.1, {}});
  report.build.tasks.push_back(
      TaskBuild{"cloth.cpp", TaskBuild::Status::CompileError, "cloth.cpp:3: error: oops", 0.1, {}});
  report.seconds = 12.3;
  score(report, rubric());
  return report;
}

const ScoredItem& item(const GradeReport& report, const std::string& name) {
  for (const ScoredItem& s : report.items) {
    if (s.item.name == name) return s;
  }
  ADD_FAILURE() << "no item " << name;
  static ScoredItem none;
  return none;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("a6_report_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Scoring -----------------------------------------------------------------------------------------

TEST(Score, PointsAreSplitEvenlyAmongAnItemsTests) {
  const GradeReport report = sampleReport();
  const ScoredItem& spring = item(report, "Task 1: spring");
  EXPECT_EQ(spring.passed, 2);
  EXPECT_EQ(spring.failed, 1);
  EXPECT_DOUBLE_EQ(spring.score, 10);                          // 15 * 2 / 3
  EXPECT_DOUBLE_EQ(item(report, "Task 4: cloth").score, 4.5);  // 9 * 1 / 2
}

TEST(Score, FullMarksAreExactlyThePointsHoweverTheyDivide) {
  GradeReport report;
  for (int k = 0; k < 7; ++k)
    report.tests.push_back(outcome("Task1Spring.T" + std::to_string(k), true));
  score(report, rubric());
  EXPECT_EQ(item(report, "Task 1: spring").score, 15);  // not 7 * (15/7)
  report.tests.back().passed = false;
  score(report, rubric());
  EXPECT_DOUBLE_EQ(item(report, "Task 1: spring").score, 12.8571);  // 15*6/7 to 1e-4
}

TEST(Score, AllOrNothingGivesNothingUnlessEveryTestPasses) {
  GradeReport report = sampleReport();
  EXPECT_EQ(item(report, "Task 6: mouse").score, 0);
  report.tests.back().passed = true;
  score(report, rubric());
  EXPECT_EQ(item(report, "Task 6: mouse").score, 6);
}

TEST(Score, ExtraCreditCountsAboveTheTotal) {
  const GradeReport report = sampleReport();
  EXPECT_EQ(report.maxScore, 30);
  EXPECT_EQ(report.extraCredit, 3);
  EXPECT_DOUBLE_EQ(report.score, 10 + 4.5 + 0 + 3);
}

TEST(Score, ATestCountsOnlyForTheFirstItemThatMatchesIt) {
  const GradeReport report = sampleReport();
  EXPECT_EQ(item(report, "Task 4 extra: bending").tests.size(), 1u);
  EXPECT_EQ(item(report, "Task 4: cloth").tests.size(), 2u)
      << "the bending test must not count for the cloth item too";
}

TEST(Score, UnmatchedTestsAndEmptyItemsAreWarnings) {
  GradeReport report;
  report.tests = {outcome("Task1Spring.A", true), outcome("Task9Other.X", true)};
  score(report, rubric());
  EXPECT_EQ(report.score, 15) << "an unmatched test earns nothing";
  std::string all;
  for (const std::string& w : report.warnings) all += w + "\n";
  EXPECT_NE(all.find("test Task9Other.X matches no rubric item"), std::string::npos) << all;
  EXPECT_NE(all.find("rubric item 'Task 6: mouse' (test.toml:"), std::string::npos) << all;
  EXPECT_NE(all.find("matches no test: its 6 points cannot be earned"), std::string::npos) << all;
}

TEST(Score, NumbersFollowTasks) {
  const GradeReport report = sampleReport();
  EXPECT_EQ(item(report, "Task 1: spring").number, "1.1");
  EXPECT_EQ(item(report, "Task 4 extra: bending").number, "4.1");
  EXPECT_EQ(item(report, "Task 4: cloth").number, "4.2");
  EXPECT_EQ(item(report, "Task 6: mouse").number, "6.1");
}

// results.json --------------------------------------------------------------------------------

// Checks `r` against Gradescope's documented format (docs/instructor.md).
void expectGradescopeFormat(const json& r) {
  const std::set<std::string> visibilities = {"visible", "hidden", "after_due_date",
                                              "after_published"};
  const std::set<std::string> formats = {"text", "html", "simple_format", "md", "ansi"};
  const std::set<std::string> known = {"score",         "execution_time",     "output",
                                       "output_format", "test_output_format", "test_name_format",
                                       "visibility",    "stdout_visibility",  "extra_data",
                                       "tests",         "leaderboard"};
  ASSERT_TRUE(r.is_object());
  for (const auto& [key, value] : r.items())
    EXPECT_EQ(known.count(key), 1u) << "unknown key " << key;
  ASSERT_TRUE(r.contains("score") && r["score"].is_number());
  ASSERT_TRUE(r.contains("execution_time") && r["execution_time"].is_number());
  ASSERT_TRUE(r.contains("output") && r["output"].is_string());
  EXPECT_EQ(formats.count(r["output_format"].get<std::string>()), 1u);
  EXPECT_EQ(formats.count(r["test_output_format"].get<std::string>()), 1u);
  EXPECT_EQ(visibilities.count(r["visibility"].get<std::string>()), 1u);
  EXPECT_EQ(r["stdout_visibility"], "hidden");
  ASSERT_TRUE(r["extra_data"].is_object());
  ASSERT_TRUE(r.contains("tests") && r["tests"].is_array());
  double sum = 0;
  for (const json& t : r["tests"]) {
    ASSERT_TRUE(t.is_object());
    ASSERT_TRUE(t["name"].is_string());
    ASSERT_TRUE(t["score"].is_number());
    ASSERT_TRUE(t["max_score"].is_number());
    EXPECT_TRUE(t["status"] == "passed" || t["status"] == "failed") << t;
    ASSERT_TRUE(t["output"].is_string());
    EXPECT_EQ(visibilities.count(t["visibility"].get<std::string>()), 1u) << t;
    ASSERT_TRUE(t["number"].is_string());
    ASSERT_TRUE(t["tags"].is_array());
    for (const json& tag : t["tags"]) EXPECT_TRUE(tag.is_string());
    sum += t["score"].get<double>();
  }
  // The top-level score is the sum of the tests (extra credit included): no hidden override.
  EXPECT_NEAR(r["score"].get<double>(), sum, 1e-9);
}

TEST(ResultsJson, FollowsGradescopesFormat) {
  const json r = json::parse(resultsJson(sampleReport()));
  expectGradescopeFormat(r);
  EXPECT_EQ(r["score"], 17.5);
  EXPECT_EQ(r["execution_time"], 13);
  EXPECT_EQ(r["tests"].size(), 4u) << "one entry per rubric item";
  EXPECT_EQ(r["extra_data"]["seed"], "4242");
  EXPECT_EQ(r["extra_data"]["tests"]["Task1Spring.C"], "failed");
}

TEST(ResultsJson, OneEntryPerItemWithItsChecksAndFailures) {
  const json r = json::parse(resultsJson(sampleReport()));
  const json& spring = r["tests"][0];
  EXPECT_EQ(spring["name"], "Task 1: spring (2/3 checks)");
  EXPECT_EQ(spring["number"], "1.1");
  EXPECT_EQ(spring["score"], 10);
  EXPECT_EQ(spring["max_score"], 15);
  EXPECT_EQ(spring["status"], "failed");
  EXPECT_EQ(spring["tags"], json::array({"task1"}));
  const std::string output = spring["output"];
  EXPECT_NE(output.find("FAILED Task1Spring.C\nexpected (0, 1)\n  hint: check the sign"),
            std::string::npos)
      << output;
  EXPECT_EQ(output.find("Task1Spring.A"), std::string::npos) << "passing checks are not listed";
}

TEST(ResultsJson, ExtraCreditCarriesItsPointsOverAMaxScoreOfZero) {
  const json r = json::parse(resultsJson(sampleReport()));
  const json& extra = r["tests"][1];
  EXPECT_EQ(extra["max_score"], 0);
  EXPECT_EQ(extra["score"], 3);
  EXPECT_EQ(extra["status"], "passed");
  EXPECT_EQ(extra["tags"], json::array({"task4", "extra_credit"}));
}

TEST(ResultsJson, VisibilityComesFromTheRubric) {
  const json r = json::parse(resultsJson(sampleReport()));
  EXPECT_EQ(r["tests"][0]["visibility"], "visible");
  EXPECT_EQ(r["tests"][2]["visibility"], "after_due_date");
  EXPECT_EQ(r["tests"][3]["visibility"], "hidden");
  EXPECT_EQ(r["tests"][3]["tags"], json::array({"task6", "all_or_nothing"}));
}

// What a student sees before the due date (the top-level output, the visible items) is the same
// whatever the items shown later scored: the total counts the visible items only, and says so.
TEST(ResultsJson, TheVisibleOutputDoesNotRevealLaterItems) {
  const GradeReport failing = sampleReport();
  GradeReport passing = failing;
  for (TestOutcome& t : passing.tests) t.passed = t.passed || t.name.rfind("Task1", 0) != 0;
  score(passing, rubric());
  ASSERT_NE(passing.score, failing.score);
  const json a = json::parse(resultsJson(failing)), b = json::parse(resultsJson(passing));
  EXPECT_EQ(a["output"], b["output"]);
  for (std::size_t i = 0; i < a["tests"].size(); ++i) {
    if (a["tests"][i]["visibility"] == "visible") {
      EXPECT_EQ(a["tests"][i], b["tests"][i]) << i;
    }
  }
  const std::string output = a["output"];
  EXPECT_NE(output.find("Score on the items shown now: 10 / 15 (+3 extra credit)"),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("Not counted here: 2 items worth 15 points, shown to you later"),
            std::string::npos)
      << output;
  EXPECT_EQ(output.find("14.5"), std::string::npos) << "the whole total leaks: " << output;
  // The instructors' figures stay whole.
  EXPECT_EQ(a["score"], 17.5);
}

TEST(ResultsJson, ATaskOnTheStarterShowsTheCompilerMessages) {
  const json r = json::parse(resultsJson(sampleReport()));
  const std::string cloth = r["tests"][2]["output"];
  EXPECT_NE(cloth.find("cloth.cpp did not compile: graded with the starter code"),
            std::string::npos)
      << cloth;
  EXPECT_NE(cloth.find("cloth.cpp:3: error: oops"), std::string::npos) << cloth;
  const std::string overall = r["output"];
  EXPECT_NE(overall.find("Task 4 cloth.cpp: did not compile"), std::string::npos) << overall;
  EXPECT_NE(overall.find("Seed of the randomised checks: 4242"), std::string::npos) << overall;
  EXPECT_NE(overall.find("Not found (the starter code was used): forces.cpp"), std::string::npos)
      << overall;
}

TEST(ResultsJson, TheOverallOutputIsEscapedForSimpleFormat) {
  GradeReport report = sampleReport();
  report.intake.notes.push_back("skipped <img src=x onerror=alert(1)>.cpp");
  const json r = json::parse(resultsJson(report));
  EXPECT_EQ(r["output_format"], "simple_format");
  const std::string overall = r["output"];
  EXPECT_EQ(overall.find("<img"), std::string::npos) << overall;
  EXPECT_NE(overall.find("&lt;img src=x"), std::string::npos) << overall;
}

TEST(ResultsJson, InvalidUtf8FromStudentsIsReplacedNotFatal) {
  GradeReport report = sampleReport();
  report.tests[2].message = std::string("bad \xff\xfe bytes");
  report.build.tasks[1].messages = std::string("\xc3(");
  score(report, rubric());
  std::string text;
  ASSERT_NO_THROW(text = resultsJson(report));
  const json r = json::parse(text);  // valid JSON, valid UTF-8
  EXPECT_NE(r["tests"][0]["output"].get<std::string>().find("bad \xef\xbf\xbd"), std::string::npos);
}

TEST(ResultsJson, AGraderErrorIsReportedWithScoreZero) {
  GradeReport report;
  report.errors.push_back("the rubric is invalid: r.toml:3: oops");
  const json r = json::parse(resultsJson(report));
  expectGradescopeFormat(r);
  EXPECT_EQ(r["score"], 0);
  EXPECT_NE(r["output"].get<std::string>().find("Grader error: the rubric is invalid: r.toml:3"),
            std::string::npos);
}

TEST(ResultsJson, ScoringTwiceGivesTheSameJsonApartFromTime) {
  GradeReport a = sampleReport(), b = sampleReport();
  b.seconds = 99;
  score(b, rubric());
  json ja = json::parse(resultsJson(a)), jb = json::parse(resultsJson(b));
  EXPECT_NE(ja["execution_time"], jb["execution_time"]);
  for (json* j : {&ja, &jb}) {
    j->erase("execution_time");
    (*j)["extra_data"].erase("seconds");
  }
  EXPECT_EQ(ja.dump(), jb.dump());
}

TEST(ResultsJson, IsWrittenAtomicallyByRename) {
  const fs::path dir = freshDir("atomic");
  const fs::path file = dir / "results.json";
  std::ofstream(file) << "old";
  struct stat before {};
  ASSERT_EQ(::stat(file.c_str(), &before), 0);

  const GradeReport report = sampleReport();
  EXPECT_EQ(writeResultsJson(report, file), "");
  EXPECT_EQ(readAll(file), resultsJson(report));
  struct stat after {};
  ASSERT_EQ(::stat(file.c_str(), &after), 0);
  EXPECT_NE(before.st_ino, after.st_ino) << "replaced by a rename, not rewritten in place";
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(entries, 1) << "no temporary file is left behind";
  fs::remove_all(dir);
}

TEST(ResultsJson, AnUnwritablePlaceGivesAnErrorNotACrash) {
  const fs::path dir = freshDir("unwritable");
  std::ofstream(dir / "file") << "x";
  const std::string error = writeResultsJson(sampleReport(), dir / "file" / "results.json");
  EXPECT_NE(error.find("cannot"), std::string::npos) << error;
  fs::remove_all(dir);
}

// HTML ----------------------------------------------------------------------------------------

TEST(Html, Base64MatchesRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(Html, StudentTextIsEscapedEverywhere) {
  GradeReport report = sampleReport();
  const std::string evil = "<script>alert('x')</script>";
  report.submission = evil + ".zip";
  report.build.tasks[1].messages = "cloth.cpp:1: error: " + evil;
  report.tests[2].message = "expected " + evil;
  report.intake.notes.push_back("ignored " + evil + ".cpp");
  report.intake.files["forces.cpp"] = "/x/" + evil + "/forces.cpp";
  report.probeOutput = evil;
  report.errors.push_back(evil);
  score(report, rubric());
  const std::string html = htmlReport(report);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "unescaped student text in the report";
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;"), std::string::npos);
  EXPECT_EQ(htmlEscape("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&#39;");
}

TEST(Html, IsSelfContainedWithTheImagesEmbedded) {
  const fs::path dir = freshDir("html");
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + "pixels";
  for (const char* name : {"student.png", "reference.png", "difference.png"}) {
    std::ofstream(dir / name, std::ios::binary) << png;
  }
  GradeReport report = sampleReport();
  report.tests[5].images = {dir / "student.png", dir / "reference.png", dir / "difference.png"};
  score(report, rubric());
  const fs::path file = dir / "report.html";
  ASSERT_EQ(writeHtml(report, file), "");
  const std::string html = readAll(file);
  std::size_t count = 0;
  for (std::size_t at = html.find("data:image/png;base64," + base64(png)); at != std::string::npos;
       at = html.find("data:image/png;base64,", at + 1)) {
    ++count;
  }
  EXPECT_EQ(count, 3u) << "student, reference and difference side by side";
  for (const char* caption : {">student: ", ">reference: ", ">difference: "}) {
    EXPECT_NE(html.find(caption), std::string::npos) << caption;
  }
  EXPECT_EQ(html.find("src=\"http"), std::string::npos) << "nothing loaded from elsewhere";
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  EXPECT_NE(html.find("Task 1: spring"), std::string::npos);
  EXPECT_NE(html.find("rest length wrong"), std::string::npos);
  EXPECT_NE(html.find("cloth.cpp:3: error: oops"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Html, AMissingImageIsNamedNotFatal) {
  GradeReport report = sampleReport();
  report.tests[5].images = {"/nonexistent/student.png"};
  score(report, rubric());
  const std::string html = htmlReport(report);
  EXPECT_NE(html.find("cannot read /nonexistent/student.png"), std::string::npos);
}

// Terminal ------------------------------------------------------------------------------------

TEST(Terminal, SummaryListsEveryItemWithPointsAndCounts) {
  const std::string text = terminalSummary(sampleReport(), false);
  EXPECT_NE(text.find("Task 1: spring"), std::string::npos) << text;
  EXPECT_NE(text.find("10.00 / 15.00"), std::string::npos) << text;
  EXPECT_NE(text.find("2 passed, 1 failed"), std::string::npos) << text;
  EXPECT_NE(text.find("14.50 / 30.00"), std::string::npos) << text;
  EXPECT_NE(text.find("+3.00 extra credit"), std::string::npos) << text;
  EXPECT_NE(text.find("cloth.cpp: did not compile"), std::string::npos) << text;
  EXPECT_EQ(text.find("\033["), std::string::npos) << "no colour when not asked";
  EXPECT_NE(terminalSummary(sampleReport(), true).find("\033[31m"), std::string::npos);
}

// The known mistake named --------------------------------------------------------------------

TEST(Mistake, LeadsEveryFailedItemOfItsTaskAndGoesInExtraData) {
  GradeReport report = sampleReport();
  report.mistakes.push_back({"t1_wrong_sign", 1,
                             "Your spring force behaves exactly like one "
                             "whose spring term has the wrong sign.",
                             3});
  const json r = json::parse(resultsJson(report));
  int named = 0;
  for (const json& t : r["tests"]) {
    const bool taskOne = t["tags"].dump().find("\"task1\"") != std::string::npos;
    if (taskOne && t["status"] == "failed") {
      ++named;
      EXPECT_EQ(t["extra_data"]["mistake"], "t1_wrong_sign");
      EXPECT_EQ(t["output"].get<std::string>().rfind("Your spring force behaves", 0), 0u)
          << t["output"];
    } else {
      EXPECT_FALSE(t["extra_data"].contains("mistake")) << t.dump(2);
    }
  }
  EXPECT_EQ(named, 1);
  EXPECT_EQ(r["extra_data"]["mistakes"][0]["mistake"], "t1_wrong_sign");
  const std::string html = htmlReport(report);
  EXPECT_NE(html.find("class=\"mistake\""), std::string::npos);
  EXPECT_NE(terminalSummary(report, false).find("task 1: Your spring force"), std::string::npos);
}

TEST(Mistake, NoneNamedLeavesTheOutputAsItWas) {
  const json r = json::parse(resultsJson(sampleReport()));
  EXPECT_EQ(r["extra_data"]["mistakes"], json::array());
  for (const json& t : r["tests"]) EXPECT_FALSE(t["extra_data"].contains("mistake")) << t.dump(2);
}

// Each item names its checks (for a6_insights: what each check cost the class).
TEST(Results, EachItemNamesItsChecks) {
  const GradeReport report = sampleReport();
  const json r = json::parse(resultsJson(report));
  ASSERT_EQ(r["tests"].size(), report.items.size());
  for (std::size_t i = 0; i < report.items.size(); ++i) {
    std::vector<std::string> names;
    for (const TestOutcome* t : report.items[i].tests) names.push_back(t->name);
    EXPECT_EQ(r["tests"][i]["extra_data"]["checks"], json(names)) << r["tests"][i].dump(2);
  }
}

// Replays ----------------------------------------------------------------------------------------

// The largest committed reference replay as both runs (the size of a real one).
ReplayView largestReplay() {
  ReplayView v;
  std::uintmax_t most = 0;
  for (const auto& e : fs::directory_iterator(fs::path(A6_SOURCE_DIR) / "tests/golden/replays")) {
    if (e.file_size() <= most) continue;
    most = e.file_size();
    v.scene = e.path().stem().string();
    v.reference = v.student = readAll(e.path());
  }
  v.task = 4;
  const json packed = json::parse(v.reference);
  v.frames = packed["frames"].get<std::vector<int>>();
  for (const int f : v.frames) {
    v.times.push_back(f / 60.0);
    v.error.push_back(f > 30 ? 0.05 * f : 0.0);
    v.studentEnergy.push_back(10 + 0.1 * f);
    v.referenceEnergy.push_back(10.0);
  }
  v.errorMeasure = "RMS distance of the particles";
  v.threshold = 0.04;
  v.parted = 31;
  v.reading = "Your energy grows where the reference's does not.";
  return v;
}

TEST(Replay, APlayerWithItsPlotsAndDataAtMost300KBForTheLargestScene) {
  const GradeReport plain = sampleReport();
  GradeReport with = plain;
  with.replays.push_back(largestReplay());
  const std::string before = htmlReport(plain), after = htmlReport(with);
  const std::size_t added = after.size() - before.size();
  std::printf("[ replay   ] %s: the replay adds %zu bytes\n", with.replays[0].scene.c_str(), added);
  EXPECT_LE(added, 300u * 1024) << "a replay of the largest scene adds at most ~300 KB";
  EXPECT_NE(after.find("<canvas"), std::string::npos);
  EXPECT_NE(after.find("type=\"range\""), std::string::npos) << "a time scrubber";
  EXPECT_NE(after.find("go to where they part"), std::string::npos);
  EXPECT_NE(after.find("<svg class=\"plot\""), std::string::npos);
  EXPECT_NE(after.find("kinetic + potential energy"), std::string::npos);
  EXPECT_NE(after.find("Your energy grows"), std::string::npos);
  // Self-contained: no address to fetch anything from (the SVG's namespace is a name, not a
  // fetch).
  for (const char* fetch : {"src=\"http", "href=\"http", "url(", "@import", "<link"}) {
    EXPECT_EQ(after.find(fetch), std::string::npos) << fetch;
  }
}

TEST(Replay, ANoteInsteadWhenThereIsNone) {
  GradeReport report = sampleReport();
  ReplayView v;
  v.scene = "fire";
  v.missing = "your code failed while the scene ran again for this replay: boom </script>";
  report.replays.push_back(v);
  const std::string html = htmlReport(report);
  EXPECT_NE(html.find("No replay: your code failed"), std::string::npos);
  EXPECT_EQ(html.find("boom </script>"), std::string::npos) << "escaped";
}

TEST(Replay, PlotsAreDrawnWithinTheirRangeAndMarkWhereTheyPart) {
  const std::vector<double> times = {0, 1, 2}, ys = {0, 1e30, NAN};
  const std::string svg =
      svgPlot("energy", "J", times, {{"yours", "#e8710a", false, &ys}}, {0, 10}, 5, 1);
  // 0 J at the bottom edge (y 134), 1e30 J clamped to the top edge (y 32), NaN a gap.
  EXPECT_NE(svg.find("M64.0 134.0 L257.0 32.0\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("stroke=\"#b3261e\""), std::string::npos) << "the mark where they part";
  EXPECT_EQ(svg.find("nan"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("e+30"), std::string::npos) << "off the chart: drawn on its edge";
  EXPECT_EQ(withUnit(0.012345, "m"), "0.0123 m");
  EXPECT_EQ(withUnit(-4.5678, "J"), "-4.57 J");
  EXPECT_EQ(withUnit(NAN, "J"), "not a number");
}

}  // namespace
}  // namespace a6::grader
