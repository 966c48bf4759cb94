// The task table (framework/harness/tasks.h) is the one description of the tasks: every stage
// finds a task by looking a suite, a tag or a file up in it, whole. Here a table of eight, the
// course's seven and a rope task, goes through the lookups, the rubric, the gradebook and the
// insights' checks, with no other edit.
#include "harness/tasks.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "batch/batch.h"
#include "insights/insights.h"
#include "rubric/rubric.h"

namespace a6::test::tasks_table {
namespace {

// The course's tasks and an eighth.
TaskTable eightTasks() {
  std::vector<Task> tasks = courseTasks().all();
  tasks.push_back({0, "rope.cpp", "Rope", {"buildRope"}});
  return TaskTable(tasks);
}

TEST(TaskTable, NumbersItsRowsInOrder) {
  const TaskTable eight = eightTasks();
  ASSERT_EQ(eight.count(), 8);
  EXPECT_EQ(eight.file(8), "rope.cpp");
  EXPECT_EQ(eight.ofFile("rope.cpp"), 8);
  EXPECT_EQ(eight.files().back(), "rope.cpp");
  EXPECT_EQ(courseTasks().ofFile("rope.cpp"), 0);
  EXPECT_EQ(eight.file(9), "");
  EXPECT_EQ(eight.file(0), "");
}

TEST(TaskTable, FindsEachSuiteOfTheEighthTaskWhole) {
  const TaskTable eight = eightTasks();
  EXPECT_EQ(eight.suite(8, SuiteKind::Public), "Task8Rope");
  for (SuiteKind kind : kSuiteKinds) {
    const SuiteOwner owner = eight.ofSuite(eight.suite(8, kind));
    EXPECT_EQ(owner.task, 8) << eight.suite(8, kind);
    EXPECT_EQ(owner.kind, kind) << eight.suite(8, kind);
    EXPECT_EQ(courseTasks().ofSuite(eight.suite(8, kind)).task, 0) << "the course has no task 8";
  }
  EXPECT_EQ(eight.ofCheck("Task8Rope.HangsStraight"), 8);
  EXPECT_EQ(eight.ofCheck("GoldenTask8Hidden.rope_swing"), 8);
  EXPECT_TRUE(isHidden(eight.ofSuite("GoldenTask8Hidden").kind));
  EXPECT_FALSE(isHidden(eight.ofSuite("GoldenTask8").kind));
}

TEST(TaskTable, ReadsNoTaskFromANamesCharacters) {
  // The old readings took the character after "Task": "Task10..." was task 1.
  EXPECT_EQ(courseTasks().ofCheck("Task10Rope.X"), 0);
  EXPECT_EQ(courseTasks().ofCheck("Task1SpringX.Y"), 0);
  EXPECT_EQ(courseTasks().ofCheck("Task1Spring.AtRestGivesZeroForce"), 1);
  EXPECT_EQ(courseTasks().ofCheck("Task"), 0);
  EXPECT_EQ(courseTasks().ofTag("task10"), 0);
  EXPECT_EQ(courseTasks().ofTag("task7"), 7);
  EXPECT_EQ(eightTasks().ofTag("task8"), 8);
  EXPECT_EQ(eightTasks().tag(8), "task8");
  EXPECT_EQ(courseTasks().tag(8), "");
}

TEST(TaskTable, TheRubricTakesTheEighthTaskThroughTheTable) {
  const std::string rubric =
      "title = \"A\"\ntotal = 5\n[[item]]\nname = \"rope\"\ntask = 8\n"
      "tests = \"Task8Rope.*\"\npoints = 5\n";
  EXPECT_EQ(grader::parseRubric(rubric, "eight.toml", eightTasks()).error, "");
  const std::string refused = grader::parseRubric(rubric, "eight.toml").error;
  EXPECT_NE(refused.find("must be 1..7, or 0 for none"), std::string::npos) << refused;
}

TEST(TaskTable, TheGradebookHasAColumnPerTaskOfTheTable) {
  grader::batch::Submission s;
  s.key = "rope";
  s.people = {{"Rope, Ann", "", "8"}};
  grader::batch::Outcome o;
  o.status = grader::batch::kGraded;
  o.tasks.resize(8);
  o.tasks[7] = 12.5;
  const std::string csv = grader::batch::gradebookCsv({{&s, &o}}, eightTasks());
  const std::string header = csv.substr(0, csv.find('\r'));
  EXPECT_NE(header.find(",task7,task8,extra_credit,"), std::string::npos) << header;
  EXPECT_NE(csv.find(",12.5,"), std::string::npos) << csv;
  const std::string seven = grader::batch::gradebookCsv({{&s, &o}});
  EXPECT_EQ(seven.find("task8"), std::string::npos) << seven;
}

// The table's functions are the ones the starter asks for and the solution writes, in its file.
TEST(TaskTable, EachFunctionIsInItsTasksFile) {
  for (const Task& t : courseTasks().all()) {
    for (const char* tree : {"starter", "solution"}) {
      std::ifstream in(std::string(A6_SOURCE_DIR) + "/" + tree + "/" + t.file);
      const std::string text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      ASSERT_FALSE(text.empty()) << tree << "/" << t.file;
      for (const std::string& f : t.functions) {
        EXPECT_NE(text.find(" " + f + "("), std::string::npos)
            << f << " in " << tree << "/" << t.file;
      }
    }
  }
}

TEST(TaskTable, InsightsFindTheEighthTasksChecks) {
  EXPECT_EQ(grader::insights::taskOfCheck("GoldenTask8.rope_swing", eightTasks()), 8);
  EXPECT_EQ(grader::insights::taskOfCheck("GoldenTask8.rope_swing"), 0);
}

}  // namespace
}  // namespace a6::test::tasks_table
