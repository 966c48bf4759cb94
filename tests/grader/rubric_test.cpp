// The rubric: its format, every kind of error with its message and line, the first-match rule,
// and the default rubric's coverage of the suite the grader runs.
#include "rubric/rubric.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace a6::grader {
namespace {

const char* const kGood = R"(title = "A6"
total = 20
time_limit = 7

[[item]]
name = "Task 1: spring"
task = 1
tests = "Task1Spring.*"
points = 10

[[item]]
name = "Task 4 extra"
task = 4
tests = ["Task4Cloth.Bending*", "Task4Cloth.Extra?"]
points = 2.5
extra_credit = true
visibility = "after_due_date"
all_or_nothing = true
time_limit = 30

[[item]]
name = "Task 4: cloth"
task = 4
tests = "Task4Cloth.*"
points = 10
visibility = "hidden"
)";

// The rubric's error, or a failure when it parsed.
std::string errorOf(const std::string& text) {
  const Rubric r = parseRubric(text, "r.toml");
  EXPECT_FALSE(r.ok()) << "this rubric should have been refused:\n" << text;
  return r.error;
}

// Runs a command and returns its standard output.
std::string run(const std::string& command, int* status) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return output;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int raw = pclose(pipe);
  *status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return output;
}

TEST(Glob, MatchesStarsAndQuestionMarksOverTheWholeName) {
  EXPECT_TRUE(globMatch("Task1Spring.*", "Task1Spring.AtRest"));
  EXPECT_TRUE(globMatch("*", ""));
  EXPECT_TRUE(globMatch("Task?Cloth.*Bend*", "Task4Cloth.ShearAndBendingFlags"));
  EXPECT_TRUE(globMatch("a*b*c", "aXXbYYbZc"));
  EXPECT_FALSE(globMatch("Task1Spring.*", "Task1SpringX.AtRest"));
  EXPECT_FALSE(globMatch("Task4Cloth.Bending*", "Task4Cloth.ShearAndBendingFlags"));
  EXPECT_FALSE(globMatch("Task1Spring", "Task1Spring.AtRest"));  // whole name, not a prefix
  EXPECT_FALSE(globMatch("?", ""));
}

TEST(Rubric, ReadsEveryFieldOfAGoodFile) {
  const Rubric r = parseRubric(kGood, "good.toml");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.title, "A6");
  EXPECT_EQ(r.totalPoints, 20);
  ASSERT_EQ(r.items.size(), 3u);
  const RubricItem& first = r.items[0];
  EXPECT_EQ(first.name, "Task 1: spring");
  EXPECT_EQ(first.task, 1);
  EXPECT_EQ(first.tests, std::vector<std::string>{"Task1Spring.*"});
  EXPECT_EQ(first.points, 10);
  EXPECT_FALSE(first.allOrNothing);
  EXPECT_FALSE(first.extraCredit);
  EXPECT_EQ(first.visibility, Visibility::Visible);
  EXPECT_EQ(first.timeLimitSeconds, 7) << "the top-level time_limit is every item's default";
  EXPECT_EQ(first.line, 5);
  const RubricItem& extra = r.items[1];
  EXPECT_EQ(extra.tests.size(), 2u);
  EXPECT_EQ(extra.points, 2.5);
  EXPECT_TRUE(extra.extraCredit);
  EXPECT_TRUE(extra.allOrNothing);
  EXPECT_EQ(extra.visibility, Visibility::AfterDueDate);
  EXPECT_EQ(extra.timeLimitSeconds, 30);
  EXPECT_EQ(r.items[2].visibility, Visibility::Hidden);
}

TEST(Rubric, ATestCountsForTheFirstItemThatMatchesIt) {
  const Rubric r = parseRubric(kGood, "good.toml");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.itemFor("Task4Cloth.BendingSpringsSkipOneParticle"), 1);
  EXPECT_EQ(r.itemFor("Task4Cloth.ExtraA"), 1);
  EXPECT_EQ(r.itemFor("Task4Cloth.ParticleCount"), 2);
  EXPECT_EQ(r.itemFor("Task1Spring.AtRest"), 0);
  EXPECT_EQ(r.itemFor("Task2Forces.Gravity"), -1);
  EXPECT_TRUE(r.items[2].matches("Task4Cloth.BendingSpringsSkipOneParticle"))
      << "the broad item matches too: only the first counts";
}

TEST(Rubric, VisibilityNamesAreGradescopes) {
  EXPECT_STREQ(toString(Visibility::Visible), "visible");
  EXPECT_STREQ(toString(Visibility::Hidden), "hidden");
  EXPECT_STREQ(toString(Visibility::AfterDueDate), "after_due_date");
  EXPECT_STREQ(toString(Visibility::AfterPublished), "after_published");
}

TEST(RubricErrors, AMisspeltKeyIsCaughtWithItsLineAndASuggestion) {
  const std::string e =
      errorOf("total = 5\n\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoint = 5\npoints = 5\n");
  EXPECT_NE(e.find("r.toml:6:"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key 'point'"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'points'?"), std::string::npos) << e;
}

TEST(RubricErrors, AMisspeltTopLevelKeyIsCaught) {
  const std::string e =
      errorOf("totl = 5\ntotal = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 5\n");
  EXPECT_NE(e.find("r.toml:1: unknown top-level key 'totl' (did you mean 'total'?)"),
            std::string::npos)
      << e;
}

TEST(RubricErrors, AWrongTypeNamesTheKeyTheItemAndTheLine) {
  const std::string e =
      errorOf("total = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = \"five\"\n");
  EXPECT_NE(e.find("r.toml:5: 'points' of [[item]] 1 must be a number, not a string"),
            std::string::npos)
      << e;
  EXPECT_NE(errorOf("total = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 5\n"
                    "extra_credit = \"yes\"\n")
                .find("r.toml:6: 'extra_credit' of [[item]] 1 must be true or false"),
            std::string::npos);
  EXPECT_NE(errorOf("total = 5\n[[item]]\nname = \"a\"\ntests = 3\npoints = 5\n")
                .find("r.toml:4: 'tests' of [[item]] 1 must be a glob string or a list"),
            std::string::npos);
  EXPECT_NE(errorOf("total = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 5\n"
                    "task = 1.5\n")
                .find("'task' of [[item]] 1 must be an integer, not a number"),
            std::string::npos);
}

TEST(RubricErrors, NegativePointsAreRefused) {
  const std::string e =
      errorOf("total = -2\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = -2\n");
  EXPECT_NE(e.find("r.toml:5: 'points' of [[item]] 1 is negative"), std::string::npos) << e;
}

TEST(RubricErrors, AnUnknownVisibilityListsTheValidOnes) {
  const std::string e = errorOf(
      "total = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 5\nvisibility = \"secret\"\n");
  EXPECT_NE(e.find("r.toml:6: 'visibility' of [[item]] 1 is 'secret': use one of visible, "
                   "hidden, after_due_date, after_published"),
            std::string::npos)
      << e;
}

TEST(RubricErrors, TheTotalMustBeTheSumOfTheRegularPoints) {
  const std::string e = errorOf(
      "total = 100\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 60\n"
      "[[item]]\nname = \"b\"\ntests = \"B.*\"\npoints = 30\n"
      "[[item]]\nname = \"c\"\ntests = \"C.*\"\npoints = 10\nextra_credit = true\n");
  EXPECT_NE(e.find("r.toml:1: total = 100 but the items' points add up to 90 (extra credit not "
                   "counted)"),
            std::string::npos)
      << e;
}

TEST(RubricErrors, RequiredKeysAreNamed) {
  const std::string e = errorOf("total = 0\n[[item]]\ntask = 1\n");
  EXPECT_NE(e.find("r.toml:2: [[item]] 1 has no 'name'"), std::string::npos) << e;
  EXPECT_NE(e.find("[[item]] 1 has no 'tests'"), std::string::npos) << e;
  EXPECT_NE(e.find("[[item]] 1 has no 'points'"), std::string::npos) << e;
  EXPECT_NE(errorOf("[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 1\n").find("no 'total'"),
            std::string::npos);
  EXPECT_NE(errorOf("total = 0\n").find("no [[item]]"), std::string::npos);
}

TEST(RubricErrors, OutOfRangeValuesAreRefused) {
  const std::string base = "total = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 5\n";
  EXPECT_NE(errorOf(base + "task = 8\n").find("'task' of [[item]] 1 must be 1..7, or 0"),
            std::string::npos);
  EXPECT_NE(errorOf(base + "time_limit = 0\n")
                .find("'time_limit' of [[item]] 1 must be more "
                      "than 0"),
            std::string::npos);
  EXPECT_NE(errorOf("total = 5\n[[item]]\nname = \"a\"\ntests = []\npoints = 5\n")
                .find("[[item]] 1 has an empty 'tests' list"),
            std::string::npos);
}

TEST(RubricErrors, DuplicateItemNamesAreRefused) {
  const std::string e = errorOf(
      "total = 2\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoints = 1\n"
      "[[item]]\nname = \"a\"\ntests = \"B.*\"\npoints = 1\n");
  EXPECT_NE(e.find("r.toml:6: two items are named 'a'"), std::string::npos) << e;
}

TEST(RubricErrors, InvalidTomlGivesTheParsersLine) {
  const std::string e = errorOf("total = 5\n\n[[item]\nname = \"a\"\n");
  EXPECT_NE(e.find("r.toml:3: not valid TOML"), std::string::npos) << e;
}

TEST(RubricErrors, EveryProblemIsReportedAtOnce) {
  const std::string e = errorOf(
      "total = 5\n[[item]]\nname = \"a\"\ntests = \"A.*\"\npoint = 5\nvisibility = \"x\"\n");
  EXPECT_NE(e.find("unknown key 'point'"), std::string::npos) << e;
  EXPECT_NE(e.find("'visibility' of [[item]] 1 is 'x'"), std::string::npos) << e;
  EXPECT_NE(e.find("has no 'points'"), std::string::npos) << e;
}

TEST(RubricErrors, AMissingFileSaysSo) {
  const Rubric r = loadRubric("/nonexistent/rubric.toml");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("/nonexistent/rubric.toml: cannot read the rubric file"),
            std::string::npos)
      << r.error;
}

// The default rubric against the checks the grader really runs (a6_grade --list-tests) -----------

// Its numbers are the instructor's to change (docs/instructor.md, "Adapting the assignment"):
// the tests read them from the rubric, never pin them.
TEST(DefaultRubric, LoadsAndTotalsItsItems) {
  const Rubric r = loadRubric(A6_DEFAULT_RUBRIC);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_GT(r.totalPoints, 0);
  double regular = 0, extra = 0;
  std::set<int> tasks;
  for (const RubricItem& item : r.items) {
    (item.extraCredit ? extra : regular) += item.points;
    tasks.insert(item.task);
  }
  EXPECT_EQ(regular, r.totalPoints);
  EXPECT_EQ(tasks, (std::set<int>{1, 2, 3, 4, 5, 6, 7}));
  bool delayed = false;
  for (const RubricItem& item : r.items)
    delayed = delayed || item.visibility != Visibility::Visible;
  EXPECT_TRUE(delayed) << "the default rubric shows delayed visibility";
}

// The student release's rubric: the default one without the items on hidden checks, every other
// item as it was, and a title that says the grader checks more.
TEST(PublicRubric, LeavesOutTheHiddenItemsAndKeepsTheOthersAsTheyWere) {
  const Rubric full = loadRubric(A6_DEFAULT_RUBRIC);
  ASSERT_TRUE(full.ok()) << full.error;
  const Rubric pub = parseRubric(publicRubricToml(full), "public.toml");
  ASSERT_TRUE(pub.ok()) << pub.error << "\n" << publicRubricToml(full);

  double hiddenPoints = 0;
  std::vector<const RubricItem*> kept;
  for (const RubricItem& item : full.items) {
    if (item.onHiddenChecks()) {
      EXPECT_TRUE(item.extraCredit || item.visibility != Visibility::Visible)
          << item.name << ": a hidden check's result is shown only after the due date";
      if (!item.extraCredit) hiddenPoints += item.points;
    } else {
      kept.push_back(&item);
    }
  }
  EXPECT_GT(hiddenPoints, 0) << "the default rubric has hidden checks";
  EXPECT_EQ(pub.totalPoints, full.totalPoints - hiddenPoints);
  ASSERT_EQ(pub.items.size(), kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const RubricItem& a = *kept[k];
    const RubricItem& b = pub.items[k];
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.task, a.task);
    EXPECT_EQ(b.tests, a.tests);
    EXPECT_EQ(b.points, a.points);
    EXPECT_EQ(b.allOrNothing, a.allOrNothing);
    EXPECT_EQ(b.extraCredit, a.extraCredit);
    EXPECT_EQ(b.visibility, a.visibility);
    EXPECT_EQ(b.timeLimitSeconds, a.timeLimitSeconds);
    EXPECT_FALSE(b.onHiddenChecks());
  }
  std::ostringstream says;  // the hidden items' points, as the rubric has them
  says << "hidden checks add " << hiddenPoints << " points";
  EXPECT_NE(pub.title.find(says.str()), std::string::npos) << pub.title;
}

TEST(PublicRubric, AnItemIsOnHiddenChecksOnlyWhenAllItsSuitesAre) {
  RubricItem item;
  item.tests = {"Task1Hidden.*"};
  EXPECT_TRUE(item.onHiddenChecks());
  item.tests = {"GoldenTask6Hidden.car_f90", "Task2Hidden.X"};
  EXPECT_TRUE(item.onHiddenChecks());
  item.tests = {"Task1Hidden.*", "Task1Spring.*"};
  EXPECT_FALSE(item.onHiddenChecks());
  item.tests = {"GoldenTask6.*"};
  EXPECT_FALSE(item.onHiddenChecks());
  item.tests = {"Task*Hidden.*", "GoldenTask?Hidden.*"};
  EXPECT_TRUE(item.onHiddenChecks()) << "a wildcard suite that matches hidden suites only";
  item.tests = {"Task1*.*"};
  EXPECT_FALSE(item.onHiddenChecks()) << "Task1Spring and Task1Hidden";
  item.tests = {"NoSuchSuite*.*"};
  EXPECT_FALSE(item.onHiddenChecks());
  item.tests = {};
  EXPECT_FALSE(item.onHiddenChecks());
}

#if defined(A6_GRADE_COMMAND) && defined(A6_TESTS_COMMAND)
// The physics suite's test names, from a6_tests --gtest_list_tests ("Suite.\n  Test\n").
std::vector<std::string> physicsTests() {
  int status = 0;
  const std::string text = run(std::string(A6_TESTS_COMMAND) + " --gtest_list_tests", &status);
  EXPECT_EQ(status, 0);
  std::vector<std::string> names;
  std::string suite, line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] != ' ') {
      suite = line.substr(0, line.find('.') + 1);
    } else {
      const std::size_t begin = line.find_first_not_of(' ');
      names.push_back(suite + line.substr(begin, line.find_first_of(" #", begin) - begin));
    }
  }
  return names;
}

TEST(DefaultRubric, CountsEveryCheckTheGraderRunsExactlyOnce) {
  int status = 0;
  const std::string text = run(std::string(A6_GRADE_COMMAND) + " --list-tests", &status);
  EXPECT_EQ(status, 0) << "a6_grade --list-tests says some check or item is unmatched:\n" << text;
  std::vector<std::string> graded;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) graded.push_back(line.substr(0, line.find('\t')));
  ASSERT_GT(graded.size(), 90u) << text;

  const Rubric r = loadRubric(A6_DEFAULT_RUBRIC);
  ASSERT_TRUE(r.ok()) << r.error;
  std::vector<int> perItem(r.items.size(), 0);
  std::set<std::string> seen;
  for (const std::string& name : graded) {
    EXPECT_TRUE(seen.insert(name).second) << name << " is listed twice";
    EXPECT_NE(courseTasks().ofCheck(name), 0)
        << name << ": its suite is no task's (framework/harness/tasks.h: Task<N><Topic>, "
        << "Task<N>Hidden, GoldenTask<N>, GoldenTask<N>Hidden)";
    const int item = r.itemFor(name);
    ASSERT_GE(item, 0) << name << " is matched by no rubric item";
    ++perItem[static_cast<std::size_t>(item)];
  }
  // A glob absorbs a new check of its suite: each glob item says how many it counts, so that a
  // check added without an item of its own (say, one meant to carry 2 points) is noticed.
  for (std::size_t i = 0; i < r.items.size(); ++i) {
    const RubricItem& item = r.items[i];
    EXPECT_GT(perItem[i], 0) << "rubric item '" << item.name << "' matches no check";
    const bool glob = std::any_of(item.tests.begin(), item.tests.end(), [](const std::string& g) {
      return g.find_first_of("*?") != std::string::npos;
    });
    if (!glob) continue;
    EXPECT_EQ(perItem[i], item.checks)
        << "rubric item '" << item.name << "' (grader/rubric.toml, line " << item.line
        << ") counts " << perItem[i] << " checks and says checks = " << item.checks
        << ": a check added to its suite counts for it (a6_grade --list-tests). If that is "
           "what you meant, say checks = "
        << perItem[i] << "; else give the check an item of its own before this one";
  }
  // Every check of the physics suite is among them.
  for (const std::string& name : physicsTests()) {
    EXPECT_EQ(seen.count(name), 1u) << name << " (a6_tests) is not run by a6_grade";
  }
}
#endif

#if defined(A6_TESTS_STARTER_COMMAND)
// Check -> passed, of the physics suite run on the starter (--gtest_output=json).
std::map<std::string, bool> starterOutcomes() {
  const std::string file = "starter_checks.json";
  int status = 0;
  run(std::string(A6_TESTS_STARTER_COMMAND) + " --gtest_output=json:" + file + " >/dev/null 2>&1",
      &status);
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  std::map<std::string, bool> passed;
  if (j.is_discarded()) return passed;
  for (const auto& suite : j.value("testsuites", nlohmann::json::array())) {
    for (const auto& t : suite.value("testsuite", nlohmann::json::array())) {
      const std::string name = suite.value("name", "") + "." + t.value("name", "");
      passed[name] = t.value("result", "") == "COMPLETED" && !t.contains("failures");
    }
  }
  return passed;
}

// The starter earns nothing: no check it passes carries points, unless its item gives them all
// or nothing and another of its checks fails on the starter. (A check a TA adds that the stubs
// pass would give every student its points for nothing.)
TEST(DefaultRubric, NoCheckTheStarterPassesCarriesPoints) {
  const Rubric r = loadRubric(A6_DEFAULT_RUBRIC);
  ASSERT_TRUE(r.ok()) << r.error;
  const std::map<std::string, bool> outcomes = starterOutcomes();
  ASSERT_GT(outcomes.size(), 90u) << "the starter's suite gave no results";
  std::map<int, bool> itemFails;  // item -> some check of it fails on the starter
  for (const auto& [name, passed] : outcomes) itemFails[r.itemFor(name)] |= !passed;
  for (const auto& [name, passed] : outcomes) {
    const int index = r.itemFor(name);
    if (!passed || index < 0) continue;
    const RubricItem& item = r.items[static_cast<std::size_t>(index)];
    const bool paid = item.points > 0 && !(item.allOrNothing && itemFails[index]);
    EXPECT_FALSE(paid) << name << " passes on the starter and earns points of '" << item.name
                       << "': make it fail on the stubs, or count it for an item of 0 points";
  }
}
#endif

}  // namespace
}  // namespace a6::grader
