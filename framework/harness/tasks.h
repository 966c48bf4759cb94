// The assignment's tasks: the one table every stage asks for a task's number, file, functions
// and checks, and who sees them (the suite, the golden images, the grader's intake, build,
// checks, report, rubric, batch and insights; CMake reads its files, cmake/A6Student.cmake).
// No code reads a task from a name's characters: a suite, a tag or a file is looked up here,
// whole. An eighth task is one more row of courseTasks() (tests/grader/tasks_test.cpp runs the
// lookups on a table of eight). Points and extra credit are the rubric's (grader/rubric.toml).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace a6 {

/// The kinds of check suites a task has, and who sees them.
enum class SuiteKind {
  Public,       ///< "Task1Spring": in the student release, run by the students' own tests
  Hidden,       ///< "Task1Hidden": the grader's only
  Golden,       ///< "GoldenTask1": the reference images the release holds
  GoldenHidden  ///< "GoldenTask1Hidden": the grader's own images
};

/// One task of the handout.
struct Task {
  int number = 0;                      ///< 1-based, the handout's order
  std::string file;                    ///< the student's file (task 1's is spring.cpp)
  std::string topic;                   ///< the public suite's name after "Task<N>": "Spring"
  std::vector<std::string> functions;  ///< what the student writes in `file`
};

/// A suite name looked up: the task it belongs to (0: none) and its kind.
struct SuiteOwner {
  int task = 0;
  SuiteKind kind = SuiteKind::Public;
};

/// Every kind, in the order a task's suites are listed.
inline constexpr SuiteKind kSuiteKinds[] = {SuiteKind::Public, SuiteKind::Hidden, SuiteKind::Golden,
                                            SuiteKind::GoldenHidden};

/// Whether `kind`'s checks are physics checks (run on the student's functions), not images.
inline bool isPhysics(SuiteKind kind) {
  return kind == SuiteKind::Public || kind == SuiteKind::Hidden;
}

/// Whether `kind`'s checks are the grader's only (not in the student release).
inline bool isHidden(SuiteKind kind) {
  return kind == SuiteKind::Hidden || kind == SuiteKind::GoldenHidden;
}

/// The tasks, numbered 1 to count() in order.
class TaskTable {
 public:
  /// `tasks` in order; each one's number is its place (set here).
  explicit TaskTable(std::vector<Task> tasks);

  int count() const { return static_cast<int>(tasks_.size()); }
  const std::vector<Task>& all() const { return tasks_; }
  /// The task numbered `number`, or nullptr.
  const Task* find(int number) const;
  /// The task files, in task order.
  std::vector<std::string> files() const;
  /// The file of task `number`; "" for a number that is no task.
  std::string file(int number) const;
  /// The task whose file is `file`; 0 for none.
  int ofFile(std::string_view file) const;

  /// The name of task `number`'s suite of kind `kind` ("Task3TimeStepping", "GoldenTask3Hidden").
  std::string suite(int number, SuiteKind kind) const;
  /// Every task's suites, by name, in task order.
  const std::vector<std::pair<std::string, SuiteOwner>>& suites() const { return suites_; }
  /// Whose suite `suite` is, compared whole against every task's suites; task 0 for none.
  SuiteOwner ofSuite(std::string_view suite) const;
  /// Whose suite a check "Suite.Name" (or a rubric glob whose suite is whole) is in.
  SuiteOwner ownerOfCheck(std::string_view check) const;
  /// The task of a check; 0 for none.
  int ofCheck(std::string_view check) const { return ownerOfCheck(check).task; }
  /// Whether `check` is a physics check (public or hidden, not an image) of the task of `file`.
  bool isPhysicsCheckOf(std::string_view check, std::string_view file) const;

  /// The tag results.json gives task `number`'s items: "task3".
  std::string tag(int number) const;
  /// The task a results.json tag names; 0 for none.
  int ofTag(std::string_view tag) const;

 private:
  std::vector<Task> tasks_;
  std::vector<std::pair<std::string, SuiteOwner>> suites_;
};

/// This course's tasks.
const TaskTable& courseTasks();

// The table's lookups, header-only so that every target that names a task can (the suite's
// support, the renderer, the grader's stages) without another library.

inline TaskTable::TaskTable(std::vector<Task> tasks) : tasks_(std::move(tasks)) {
  for (std::size_t i = 0; i < tasks_.size(); ++i) tasks_[i].number = static_cast<int>(i + 1);
  for (const Task& t : tasks_) {
    for (SuiteKind kind : kSuiteKinds) suites_.push_back({suite(t.number, kind), {t.number, kind}});
  }
}

inline const Task* TaskTable::find(int number) const {
  return number >= 1 && number <= count() ? &tasks_[static_cast<std::size_t>(number - 1)] : nullptr;
}

inline std::vector<std::string> TaskTable::files() const {
  std::vector<std::string> files;
  for (const Task& t : tasks_) files.push_back(t.file);
  return files;
}

inline std::string TaskTable::file(int number) const {
  const Task* t = find(number);
  return t != nullptr ? t->file : "";
}

inline int TaskTable::ofFile(std::string_view file) const {
  for (const Task& t : tasks_) {
    if (t.file == file) return t.number;
  }
  return 0;
}

inline std::string TaskTable::suite(int number, SuiteKind kind) const {
  const Task* t = find(number);
  if (t == nullptr) return "";
  const std::string task = "Task" + std::to_string(number);
  switch (kind) {
    case SuiteKind::Public:
      return task + t->topic;
    case SuiteKind::Hidden:
      return task + "Hidden";
    case SuiteKind::Golden:
      return "Golden" + task;
    case SuiteKind::GoldenHidden:
      return "Golden" + task + "Hidden";
  }
  return "";
}

inline SuiteOwner TaskTable::ofSuite(std::string_view suite) const {
  for (const auto& [name, owner] : suites_) {
    if (name == suite) return owner;
  }
  return {};
}

inline SuiteOwner TaskTable::ownerOfCheck(std::string_view check) const {
  return ofSuite(check.substr(0, check.find('.')));
}

inline bool TaskTable::isPhysicsCheckOf(std::string_view check, std::string_view file) const {
  const SuiteOwner owner = ownerOfCheck(check);
  return owner.task != 0 && owner.task == ofFile(file) && isPhysics(owner.kind);
}

inline std::string TaskTable::tag(int number) const {
  return find(number) != nullptr ? "task" + std::to_string(number) : "";
}

inline int TaskTable::ofTag(std::string_view tag) const {
  for (const Task& t : tasks_) {
    if (this->tag(t.number) == tag) return t.number;
  }
  return 0;
}

// The course: tasks 1 to 7 (the rubric counts task 7 as extra credit). Its files are the
// starter's and the solution's; the functions are those the handout asks for (each one is in its
// file: tests/grader/tasks_test.cpp).
inline const TaskTable& courseTasks() {
  static const TaskTable table({
      {0, "spring.cpp", "Spring", {"Spring::computeForce"}},
      {0,
       "forces.cpp",
       "Forces",
       {"gravityForce", "buoyancyForce", "dragForce", "repulsionForce", "externalForce"}},
      {0,
       "time_stepping.cpp",
       "TimeStepping",
       {"MassSpringSystem::step", "MassSpringSystem::advance"}},
      {0, "cloth.cpp", "Cloth", {"buildCloth"}},
      {0, "particle_system.cpp", "Particles", {"emitParticle", "ParticleSystem::update"}},
      {0,
       "joints.cpp",
       "Joints",
       {"createHinge", "createRope", "createPiston", "createWheel", "beginDrag", "moveDrag",
        "endDrag"}},
      {0, "implicit.cpp", "Implicit", {"springJacobians", "MassSpringSystem::stepImplicit"}},
  });
  return table;
}

/// The course's task files, in task order (courseTasks().files(), for the loops over them).
inline const std::vector<std::string> kTaskFiles = courseTasks().files();

}  // namespace a6
