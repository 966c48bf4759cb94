// The scores a6_grade gives known submissions, against the default rubric:
//   - the solution: every item's points, extra credit included;
//   - the starter: nothing;
//   - every wrong version under tests/wrong/ (the solution with the files of its folder in place
//     of the solution's): it loses points in exactly the tasks its EXPECT file names ("fail: 3"),
//     and keeps every point of every other task. Golden images whose scene runs the wrong task's
//     code (the manifest's "tasks": the cloth images run the spring, the forces and the stepper)
//     may fail (kImagesMayCrossTasks): the default rubric makes them feedback without points. No
//     physics check of another task may fail: the suite checks each task with the reference
//     models of the others;
//   - the same submission graded twice: the same results.json, timing fields aside.
//
// Each wrong version and each alternative is graded once, by its own ctest entry (wrong_<name>,
// alternative_<name>, tests/grader/CMakeLists.txt), with its files linked into the grader's
// stages (linked_grade_main.cpp: no sandbox, no build; the solution, the starter and the hostile
// submissions prove the sandbox): that one grading gives the physics checks' verdict with its
// margins (each wrong task misses by ten times its tolerance), the images' and the scores'.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "rubric/rubric.h"
#include "run_command.h"
#include "staging.h"

namespace {

namespace fs = std::filesystem;
using a6::grader::Rubric;
using a6::grader::RubricItem;
using nlohmann::json;

using a6::test::staging::kSource;

// A golden image (GoldenTask<n>.<image>) runs the code of every task in its manifest entry's
// "tasks", so a mistake in one of them can fail it, and its points are charged to the image's
// own task. The issue asks for a mistake to cost its own task only: false makes the test hold
// the grader to that (it fails while images charge across tasks).
constexpr bool kImagesMayCrossTasks = true;

using a6::test::staging::readAll;

struct Graded {
  int status = -1;
  std::string output;
  json results;
};

// A grading command's exit status, what it printed and its results.json.
Graded graded(const std::string& command, const fs::path& out) {
  const a6::test::CommandRun run = a6::test::runCommand(command);
  Graded g;
  g.status = run.status;
  g.output = run.output;
  g.results = json::parse(readAll(out / "results.json"), nullptr, false);
  return g;
}

Graded grade(const fs::path& submission, const fs::path& out, const std::string& extra = "") {
  return graded(std::string(A6_GRADE_COMMAND) + " '" + submission.string() + "' --out '" +
                    out.string() + "' --quiet " + extra,
                out);
}

// The ctest entry's linked grader (a6_graded_<set>, linked_grade_main.cpp): the set's one
// grading, with the suite's summary per task and its margins on stdout.
Graded gradeLinked(const fs::path& out) {
  const char* program = std::getenv("A6_LINKED_GRADER");
  if (program == nullptr) {
    ADD_FAILURE() << "A6_LINKED_GRADER is not set: run this case through its ctest entry";
    return {};
  }
  return graded(std::string(program) + " --out '" + out.string() + "'", out);
}

// "<key> 1:<a>:<b> 2:..." from the linked grader's output: task -> its fields after the task.
std::map<int, std::vector<std::string>> taskLine(const std::string& output,
                                                 const std::string& key) {
  std::map<int, std::vector<std::string>> fields;
  const std::size_t at = output.find("\n" + key + " ");
  if (at == std::string::npos) return fields;
  std::istringstream line(output.substr(at + key.size() + 2, output.find('\n', at + 1) - at));
  for (std::string word; line >> word;) {
    std::istringstream parts(word);
    std::string part;
    std::getline(parts, part, ':');
    const int task = std::atoi(part.c_str());
    while (std::getline(parts, part, ':')) fields[task].push_back(part);
  }
  return fields;
}

fs::path outDir(const std::string& name) {
  const fs::path dir = fs::absolute("scores_out") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const Rubric& rubric() {
  static const Rubric r = a6::grader::loadRubric(A6_DEFAULT_RUBRIC);
  return r;
}

// Score per task (items of task 0 under 0), and the rubric's points per task.
std::map<int, double> perTask(const json& results, bool points) {
  std::map<std::string, const RubricItem*> byName;
  for (const RubricItem& item : rubric().items) byName[item.name] = &item;
  std::map<int, double> sum;
  for (const RubricItem& item : rubric().items) sum[item.task] += points ? item.points : 0;
  if (points) return sum;
  for (const json& t : results["tests"]) {
    std::string name = t.value("name", "");
    name.resize(std::min(name.size(), name.rfind(" (")));
    const auto found = byName.find(name);
    EXPECT_NE(found, byName.end()) << "results.json has an item the rubric lacks: " << name;
    if (found != byName.end()) sum[found->second->task] += t["score"].get<double>();
  }
  return sum;
}

// Each golden image's check name -> the tasks whose code its scene runs.
const std::map<std::string, std::set<int>>& imageTasks() {
  static const std::map<std::string, std::set<int>> tasks = [] {
    std::map<std::string, std::set<int>> out;
    const json manifest =
        json::parse(readAll(kSource / "tests" / "golden" / "manifest.json"), nullptr, false);
    if (manifest.is_discarded() || !manifest.contains("images")) return out;
    for (const json& image : manifest["images"]) {
      const std::string check = "GoldenTask" + std::to_string(image.value("task", 0)) + "." +
                                image.value("name", std::string());
      for (const json& t : image.value("tasks", json::array())) out[check].insert(t.get<int>());
    }
    return out;
  }();
  return tasks;
}

// The task a check's points go to: its rubric item's (the stiff cloth image, GoldenTask3, counts
// for task 4), 0 if it counts for none.
int taskOfCheck(const std::string& check) {
  const int item = rubric().itemFor(check);
  return item < 0 ? 0 : rubric().items[static_cast<std::size_t>(item)].task;
}

std::string summary(const Graded& g) {
  std::ostringstream out;
  out << "a6_grade exited with " << g.status << ":\n" << g.output.substr(0, 6000);
  return out.str();
}

// The ids of the mistakes results.json names (extra_data.mistakes), not counting the plain
// measurements (measured_only: no part singled out, nothing named).
std::set<std::string> mistakesNamed(const json& results) {
  std::set<std::string> ids;
  for (const json& m : results["extra_data"].value("mistakes", json::array())) {
    if (!m.value("measured_only", false)) ids.insert(m.value("mistake", std::string()));
  }
  return ids;
}

// The ids of the diagnoses by measurement (extra_data.diagnoses), whatever the catalogue named.
std::set<std::string> diagnoses(const json& results) {
  std::set<std::string> ids;
  for (const json& m : results["extra_data"].value("diagnoses", json::array())) {
    ids.insert(m.value("diagnosis", std::string()));
  }
  return ids;
}

// The diagnosis by measurement of a wrong version is its EXPECT's "diagnosis:" (none without one):
// a change of the designed inputs or the fits that renames a part, or blames another, fails here.
void expectDiagnosis(const Graded& g, const std::string& name) {
  const std::string id = a6::test::staging::expectedDiagnosis(name);
  const std::set<std::string> found = diagnoses(g.results);
  std::printf("[ diagnosis] %s: expected %s, measured %s\n", name.c_str(),
              id.empty() ? "none" : id.c_str(), json(found).dump().c_str());
  EXPECT_EQ(found, id.empty() ? std::set<std::string>{} : std::set<std::string>{id})
      << name << ": if the new diagnosis is right, write 'diagnosis: <id>' in tests/wrong/" << name
      << "/EXPECT";
}

// A correct solution is never told it made a known mistake: none in extra_data, none on an item.
void expectNoMistakeNamed(const Graded& g) {
  EXPECT_EQ(mistakesNamed(g.results), std::set<std::string>{}) << g.results.dump(2).substr(0, 4000);
  for (const json& t : g.results["tests"]) {
    EXPECT_FALSE(t.value("extra_data", json::object()).contains("mistake")) << t.dump(2);
  }
}

// The report's replays (grader/replay/): one per imaged scene, and a correct solution's follow
// the reference in every frame (none marked where it parts). Returns the report.
std::string expectReplays(const fs::path& out, bool correct) {
  const std::string html = readAll(out / "report.html");
  std::size_t scenes = 0, parted = 0;
  for (std::size_t at = html.find("class=\"replay-box\""); at != std::string::npos;
       at = html.find("class=\"replay-box\"", at + 1)) {
    ++scenes;
  }
  for (std::size_t at = html.find("{\"parted\": "); at != std::string::npos;
       at = html.find("{\"parted\": ", at + 1)) {
    parted += html.compare(at + 11, 2, "-1") != 0;
  }
  std::size_t energyPlots = 0;
  for (std::size_t at = html.find(">kinetic + potential energy<"); at != std::string::npos;
       at = html.find(">kinetic + potential energy<", at + 1)) {
    ++energyPlots;
  }
  EXPECT_GE(scenes, 14u) << "a replay per imaged scene";
  EXPECT_EQ(energyPlots, scenes) << "an energy plot beside every replay, Box2D's bodies too";
  EXPECT_EQ(html.find("No replay:"), std::string::npos) << "every scene has its replay";
  EXPECT_LT(html.size(), 3u << 20) << "the report stays small";
  if (correct) {
    EXPECT_EQ(parted, 0u) << "a correct solution's replays never part";
  }
  return html;
}

// A wrong version whose EXPECT names a mistake is named, first in every failed item of its task
// (Gradescope's output leads with it, extra_data carries it); no other mistake is named, and one
// whose EXPECT names none is named nothing: a wrong name is never given.
void expectMistakeNamed(const Graded& g, const std::string& name, const std::set<int>& failing) {
  const std::string id = a6::test::staging::expectedMistake(name);
  const std::set<std::string> named = mistakesNamed(g.results);
  std::printf("[ mistakes ] %s: expected %s, named %s\n", name.c_str(),
              id.empty() ? "none" : id.c_str(), json(named).dump().c_str());
  if (id.empty()) {
    EXPECT_EQ(named, std::set<std::string>{})
        << name << ": its EXPECT names no mistake, so none may be named (if the name is right, "
        << "add 'mistake: <id>' to tests/wrong/" << name << "/EXPECT)";
    return;
  }
  EXPECT_EQ(named, std::set<std::string>{id}) << name << ": the report must name its mistake";
  for (const json& t : g.results["tests"]) {
    const bool ofTask = std::any_of(failing.begin(), failing.end(), [&](int task) {
      const json tags = t.value("tags", json::array());
      return std::find(tags.begin(), tags.end(), "task" + std::to_string(task)) != tags.end();
    });
    if (!ofTask || t.value("status", "") != "failed") continue;
    ASSERT_TRUE(t.contains("extra_data")) << t.dump(2);
    EXPECT_EQ(t["extra_data"].value("mistake", ""), id) << t.dump(2);
    const std::string text = t["extra_data"].value("mistake_text", "");
    EXPECT_FALSE(text.empty());
    EXPECT_EQ(t.value("output", "").rfind(text, 0), 0u) << "the output leads with the mistake:\n"
                                                        << t.value("output", "").substr(0, 600);
  }
}

void expectCompleted(const Graded& g) {
  ASSERT_TRUE(rubric().ok()) << rubric().error;
  EXPECT_EQ(g.status, 0) << summary(g);
  ASSERT_TRUE(g.results.is_object() && g.results.contains("tests")) << summary(g);
  EXPECT_EQ(g.results["extra_data"]["errors"], json::array()) << summary(g);
}

// What a student reads (each item's output, the overall output) names no folder of the grading
// machine: not its scratch folder, not the source tree, not the output folder.
void expectNoGradingPaths(const Graded& g, const fs::path& dir) {
  std::vector<std::string> texts = {g.results.value("output", "")};
  for (const json& t : g.results["tests"]) texts.push_back(t.value("output", ""));
  for (const std::string& text : texts) {
    for (const std::string& path :
         {fs::temp_directory_path().string() + "/", kSource.string(), dir.string()}) {
      EXPECT_EQ(text.find(path), std::string::npos)
          << "a student-visible output names " << path << ":\n"
          << text.substr(0, 3000);
    }
  }
}

using a6::test::staging::failingTasks;
using a6::test::staging::wrongVersions;

TEST(Scores, TheSolutionGetsEveryPoint) {
  const fs::path dir = outDir("solution");
  const Graded g = grade(kSource / "solution", dir / "out");
  expectCompleted(g);
  if (HasFatalFailure()) return;
  double all = 0;
  for (const RubricItem& item : rubric().items) all += item.points;
  EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), all) << summary(g);
  const auto got = perTask(g.results, false), full = perTask(g.results, true);
  for (const auto& [task, points] : full) EXPECT_DOUBLE_EQ(got.at(task), points) << "task " << task;
  expectNoMistakeNamed(g);
  expectReplays(dir / "out", true);
}

// The hidden checks draw other inputs at another seed: still every point, and no mistake named.
TEST(Scores, TheSolutionAtAnotherSeedIsNamedNoMistake) {
  const fs::path dir = outDir("solution_seed");
  const Graded g = grade(kSource / "solution", dir / "out", "--seed 424242");
  expectCompleted(g);
  if (HasFatalFailure()) return;
  double all = 0;
  for (const RubricItem& item : rubric().items) all += item.points;
  EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), all) << summary(g);
  expectNoMistakeNamed(g);
}

TEST(Scores, TheStarterGetsNothing) {
  const fs::path dir = outDir("starter");
  const Graded g = grade(kSource / "starter", dir / "out");
  expectCompleted(g);
  if (HasFatalFailure()) return;
  EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), 0) << summary(g);
  // Its stubs answer nothing like any known mistake (an emitter that puts every particle at the
  // centre is not one that draws the radius uniformly; a drag that made no joint cannot have
  // forgotten to destroy it): no mistake may be named, however wrong it is.
  EXPECT_EQ(mistakesNamed(g.results), std::set<std::string>{});
}

// As root, the compiler and the probe run as nobody: an output folder nobody may enter (a home
// folder of mode 0700) must not turn every file into "did not compile".
TEST(Scores, AnOutputFolderTheSandboxCannotEnter) {
  if (geteuid() != 0) GTEST_SKIP() << "only root drops privileges";
  const fs::path dir = outDir("private");
  fs::permissions(dir, fs::perms::owner_all);
  auto scratchFolders = [] {
    std::set<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path(), ec)) {
      if (e.path().filename().string().rfind("a6_grade.", 0) == 0) names.insert(e.path());
    }
    return names;
  };
  const auto before = scratchFolders();
  const Graded g = grade(kSource / "solution", dir / "out");
  expectCompleted(g);
  if (HasFatalFailure()) return;
  double all = 0;
  for (const RubricItem& item : rubric().items) all += item.points;
  EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), all) << summary(g);
  const std::string notes = g.results["extra_data"]["notes"].dump();
  EXPECT_NE(notes.find("cannot be entered"), std::string::npos) << notes;
  // The note names the scratch folder; it is gone. (Only ours: other gradings on the machine
  // make and remove folders of their own meanwhile.)
  const std::size_t from = notes.find("went to ");
  ASSERT_NE(from, std::string::npos) << notes;
  const std::string scratch = notes.substr(from + 8, notes.find(" (removed", from) - (from + 8));
  EXPECT_NE(scratch.find("/a6_grade."), std::string::npos) << scratch;
  EXPECT_FALSE(fs::exists(scratch)) << scratch << ": the scratch folder was not removed";
}

// The physics suite's verdict (tests/support/summary.h): every wrong task has a failed check,
// each of them missing by at least ten times the tolerance it crossed ("inf": it failed for a
// reason that is not a number, a count or a NaN), and no other task has one.
void expectMargins(const Graded& g, const std::string& name, const std::set<int>& failing) {
  const auto counts = taskLine(g.output, "A6-SUMMARY");
  const auto margins = taskLine(g.output, "A6-MARGIN");
  ASSERT_EQ(counts.size(), 7u) << "no summary per task:\n" << g.output.substr(0, 4000);
  for (const auto& [task, fields] : counts) {
    ASSERT_EQ(fields.size(), 2u);
    const int passed = std::atoi(fields[0].c_str()), failed = std::atoi(fields[1].c_str());
    EXPECT_GT(passed + failed, 0) << "task " << task << " ran no check";
    if (!failing.count(task)) {
      EXPECT_EQ(failed, 0) << name << ": task " << task << " must pass";
      continue;
    }
    ASSERT_GT(failed, 0) << name << ": task " << task << " must fail";
    const std::string margin = margins.count(task) ? margins.at(task).at(0) : "none";
    std::printf("[ margins  ] %s: task %d misses by %s times its tolerance at least\n",
                name.c_str(), task, margin.c_str());
    if (margin == "inf") continue;
    EXPECT_TRUE(margin != "none" && std::atof(margin.c_str()) >= 10)
        << name << ": task " << task << "'s margin is " << margin
        << ", under 10: a check misses by less than 10 times its tolerance";
  }
}

// The images' verdict: the images of scenes that run a wrong task do not all pass, except for
// the mistakes no scene shows (A6_IMAGES_UNSEEN=1, tests/grader/CMakeLists.txt says why): those
// pass every image.
void expectImagesSee(const Graded& g, const std::string& name, const std::set<int>& failing) {
  const char* unseenValue = std::getenv("A6_IMAGES_UNSEEN");
  const bool unseen = unseenValue != nullptr && std::string(unseenValue) == "1";
  int ran = 0, failed = 0;
  for (const auto& [check, outcome] : g.results["extra_data"]["tests"].items()) {
    const auto image = imageTasks().find(check);
    if (image == imageTasks().end()) continue;
    const bool runsWrongCode = std::any_of(failing.begin(), failing.end(),
                                           [&](int t) { return image->second.count(t) != 0; });
    if (!runsWrongCode) continue;
    ++ran;
    failed += outcome == "failed" ? 1 : 0;
  }
  std::printf("[ images   ] %s: %d of the %d images whose scene runs its code fail\n", name.c_str(),
              failed, ran);
  if (unseen) {
    EXPECT_EQ(failed, 0) << name << " is listed as unseen by the images, but " << failed
                         << " fail: a scene now shows it (move it out of A6_GOLDEN_UNSEEN)";
  } else {
    EXPECT_GT(ran, 0) << name << ": no image's scene runs its task";
    EXPECT_GT(failed, 0) << name << ": no image of a scene that runs its code fails";
  }
}

// The points per task a wrong version got, and the most it could.
struct TaskPoints {
  std::map<int, double> got, full;
};

// "score 85; per task 1:15/15 ...", with the tasks it is wrong in (`named`).
void printScores(const Graded& g, const std::string& name, const std::string& named,
                 const TaskPoints& points) {
  std::ostringstream table;
  for (const auto& [task, most] : points.full) {
    table << " " << task << ":" << points.got.at(task) << "/" << most;
  }
  std::printf("[ scores   ] %s (fail: %s): score %s; per task%s\n", name.c_str(), named.c_str(),
              g.results["score"].dump().c_str(), table.str().c_str());
}

// The report's replays of a wrong version.
void expectWrongReplays(const fs::path& out, const std::string& name,
                        const std::set<int>& failing) {
  const std::string html = expectReplays(out, false);
  std::printf("[ replays  ] %s: report.html %zu bytes\n", name.c_str(), html.size());
  // Linked, the files were never looked for: the report says so, not "not found".
  EXPECT_NE(html.find("compiled into the grading program"), std::string::npos);
  EXPECT_EQ(html.find("not found"), std::string::npos);
  // A wrong stepper's failed checks are replayed beside the reference stepper.
  if (failing.count(3) != 0) {
    EXPECT_NE(html.find("id=\"replay-Task3"), std::string::npos);
  }
  // So are a wrong particle system's, where the particles' positions or number differ (not
  // a temperature's or an emitter's mistake: those show in no position of an alive particle).
  if (name == "t5_position_before_velocity" || name == "t5_no_removal" ||
      name == "t5_removal_off_by_one") {
    EXPECT_NE(html.find("id=\"replay-Task5"), std::string::npos);
  }
}

// Which checks failed outside the wrong tasks, and whether an image may.
void expectNoFailureOutsideItsTasks(const Graded& g, const std::string& name,
                                    const std::set<int>& failing, const std::string& named) {
  for (const auto& [check, outcome] : g.results["extra_data"]["tests"].items()) {
    if (outcome != "failed") continue;
    const int task = taskOfCheck(check);
    if (failing.count(task)) continue;
    const auto image = imageTasks().find(check);
    const bool runsWrongCode = image != imageTasks().end() &&
                               std::any_of(failing.begin(), failing.end(),
                                           [&](int t) { return image->second.count(t) != 0; });
    if (kImagesMayCrossTasks && runsWrongCode) {
      // Allowed as feedback, but the task's points are still checked below: the default rubric
      // gives the images of tasks 1-5 no points, so the task must keep all of them.
      std::printf("[ scores   ]   %s fails the image %s of task %d, whose scene runs its code\n",
                  name.c_str(), check.c_str(), task);
      continue;
    }
    ADD_FAILURE() << name << " (wrong in task(s) " << named << ") fails " << check << " of task "
                  << task << "\n"
                  << g.results.dump(2).substr(0, 8000);
  }
}

// Points lost in the wrong tasks, every point kept in the others.
void expectPointsLostOnlyInItsTasks(const Graded& g, const std::string& name,
                                    const std::set<int>& failing, const std::string& named,
                                    const TaskPoints& points) {
  for (const auto& [task, most] : points.full) {
    if (task == 0) continue;
    if (failing.count(task)) {
      EXPECT_LT(points.got.at(task), most) << name << " must lose points in task " << task << "\n"
                                           << summary(g);
    } else {
      EXPECT_DOUBLE_EQ(points.got.at(task), most)
          << name << " must keep every point of task " << task << " (it is wrong in task(s) "
          << named << " only)\n"
          << g.results.dump(2).substr(0, 8000);
    }
  }
}

class WrongVersion : public ::testing::TestWithParam<std::string> {};

TEST_P(WrongVersion, LosesPointsOnlyInItsTasks) {
  const std::string name = GetParam();
  const std::set<int> failing = failingTasks(name);
  ASSERT_FALSE(failing.empty()) << "tests/wrong/" << name << "/EXPECT names no task";
  const fs::path dir = outDir("wrong_" + name);
  const Graded g = gradeLinked(dir / "out");
  expectCompleted(g);
  if (HasFatalFailure()) return;
  expectNoGradingPaths(g, dir);
  expectMargins(g, name, failing);
  expectImagesSee(g, name, failing);
  const TaskPoints points{perTask(g.results, false), perTask(g.results, true)};
  std::string named;
  for (const int t : failing) named += (named.empty() ? "" : " ") + std::to_string(t);
  printScores(g, name, named, points);
  expectMistakeNamed(g, name, failing);
  expectDiagnosis(g, name);
  expectWrongReplays(dir / "out", name, failing);
  expectNoFailureOutsideItsTasks(g, name, failing, named);
  expectPointsLostOnlyInItsTasks(g, name, failing, named, points);
}

INSTANTIATE_TEST_SUITE_P(Wrong, WrongVersion, ::testing::ValuesIn(wrongVersions()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// A correct solution written another way (tests/alternative/: float intermediates, other loop
// and summation orders, a 1 mm guard) gets every point; agreeing only to float precision adds a
// note that costs nothing.
class CorrectAlternative : public ::testing::TestWithParam<std::string> {};

TEST_P(CorrectAlternative, GetsEveryPoint) {
  const std::string name = GetParam();
  const fs::path dir = outDir("alternative_" + name);
  const Graded g = gradeLinked(dir / "out");
  expectCompleted(g);
  if (HasFatalFailure()) return;
  expectMargins(g, name, {});
  for (const auto& [check, outcome] : g.results["extra_data"]["tests"].items()) {
    EXPECT_EQ(outcome, "passed") << name << ": " << check;
  }
  double all = 0;
  for (const RubricItem& item : rubric().items) all += item.points;
  EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), all) << g.results.dump(2).substr(0, 8000);
  expectNoMistakeNamed(g);
  expectReplays(dir / "out", true);
  std::string notes;
  for (const json& t : g.results["tests"]) {
    const std::string output = t.value("output", "");
    if (output.find("float rounding") != std::string::npos) notes += t.value("name", "") + "\n";
  }
  std::printf("[ scores   ] %s: score %s; items with the float note:\n%s", name.c_str(),
              g.results["score"].dump().c_str(), notes.c_str());
  if (name.rfind("float", 0) == 0) {
    EXPECT_FALSE(notes.empty()) << "a float solution's items carry the float note";
  } else {
    EXPECT_TRUE(notes.empty()) << "a double solution's items carry no float note:\n" << notes;
  }
}

INSTANTIATE_TEST_SUITE_P(Alternative, CorrectAlternative,
                         ::testing::ValuesIn(a6::test::staging::alternatives()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// The seed is derived from the files (no --seed here), the messages hold computed values: still,
// twice the same submission gives the same results.json, timing aside. The submission: the
// solution with the starter's spring and particle system (failed checks with values in their
// messages, random inputs in task 5's).
TEST(Scores, GradingTwiceGivesTheSameResults) {
  const fs::path dir = outDir("twice");
  const fs::path sub = a6::test::staging::stage(dir / "submission", "", {1, 5});
  Graded a = grade(sub, dir / "a"), b = grade(sub, dir / "b");
  expectCompleted(a);
  expectCompleted(b);
  if (HasFatalFailure()) return;
  for (json* j : {&a.results, &b.results}) {
    j->erase("execution_time");
    (*j)["extra_data"].erase("seconds");
    (*j)["extra_data"].erase("seconds_by_stage");
    (*j)["extra_data"].erase("grader_peak_rss_mib");  // measured, like the time
    // Where the scratch files went (a checkout under a folder of mode 0700: each grading's own
    // /tmp folder) is a fact of the machine, like the time.
    json& notes = (*j)["extra_data"]["notes"];
    for (auto n = notes.begin(); n != notes.end();) {
      n = n->get<std::string>().find("scratch files went to") != std::string::npos ? notes.erase(n)
                                                                                   : n + 1;
    }
  }
  EXPECT_EQ(a.results.dump(2), b.results.dump(2));
  double all = 0;
  for (const RubricItem& item : rubric().items) all += item.points;
  EXPECT_LT(a.results["score"].get<double>(), all) << "a submission with failing checks";
}

}  // namespace
