// The diagnosis (measure.h): every task's designed inputs, and each failing task's findings put
// in one sentence for the student.
#include <algorithm>
#include <optional>

#include "mistakes/library/measured/tasks.h"
#include "mistakes/measure.h"

namespace a6::grader {
namespace {

using measured::Finding;
using measured::Verdict;

// Task 7: springJacobians, then (where they are right: the step uses them) the implicit step.
std::vector<Finding> measureTask7(const Transcript& t) {
  std::vector<Finding> f = measured::measureJacobians(t);
  for (const Finding& x : f) {
    if (x.verdict != Verdict::Right) return f;
  }
  for (Finding& x : measured::measureImplicit(t)) f.push_back(std::move(x));
  return f;
}

// Each measured task and its parts' findings.
struct MeasuredTask {
  int task;
  std::vector<Finding> (*measure)(const Transcript&);
};

const std::vector<MeasuredTask>& measuredTasks() {
  static const std::vector<MeasuredTask> tasks = {
      {1, measured::measureSpringForce},
      {2, measured::measureForces},
      {3, measured::measureStepping},
      {4, measured::measureCloth},
      {5, measured::measureParticles},
      {6, measured::measureJoints},
      {7, measureTask7},
  };
  return tasks;
}

// The sentence of a part that differs: "Your <part> <how> (measured at N inputs; at ...)".
std::string namedSentence(const Finding& f, std::size_t samples) {
  const std::size_t cut = f.measured.find("; at ");
  return "Your " + f.part + " " + f.how + " (measured on " + std::to_string(samples) +
         " designed inputs" + (f.measured.empty() ? "" : "; " + f.measured.substr(0, cut)) + ")";
}

// One task's findings, if any part differs, as the student's mistake.
std::optional<NamedMistake> mistakeOf(const MeasuredTask& task, const std::vector<Finding>& f,
                                      std::size_t samples) {
  std::vector<const Finding*> differ, unexplained;
  bool stub = true;
  for (const Finding& x : f) {
    if (x.verdict == Verdict::Differs) differ.push_back(&x);
    if (x.verdict == Verdict::Unexplained) unexplained.push_back(&x);
    stub = stub && (x.verdict == Verdict::Unmeasured || x.zero);
  }
  // Nothing differs, or every answer is zero (a starter's stub, which its checks' words fit).
  if ((differ.empty() && unexplained.empty()) || stub) return std::nullopt;
  NamedMistake m{"t" + std::to_string(task.task), task.task, "", 0,
                 unexplained.size() > 0 && differ.empty()};
  for (const Finding* x : differ) {
    m.id += "_" + x->tag;
    m.text += (m.text.empty() ? "" : " ") + namedSentence(*x, samples) + ".";
  }
  if (m.measuredOnly) m.id += "_measured";
  for (const Finding* x : unexplained) {
    m.text += std::string(m.text.empty() ? "" : " ") + "Your " + x->part +
              " differs from the physics' " + "in a way no single change explains: measured " +
              x->measured + ".";
  }
  m.evidence = static_cast<int>(samples);
  return m;
}

}  // namespace

const std::vector<Designed>& designedInputs() {
  static const std::vector<Designed> all = [] {
    std::vector<Designed> out;
    measured::designSpring(out);
    measured::designForces(out);
    measured::designStepping(out);
    measured::designCloth(out);
    measured::designParticles(out);
    measured::designJoints(out);
    measured::designImplicit(out);
    return out;
  }();
  return all;
}

std::vector<NamedMistake> diagnose(const Transcript& answers, const std::set<int>& failingTasks) {
  std::vector<NamedMistake> out;
  for (const MeasuredTask& task : measuredTasks()) {
    if (failingTasks.count(task.task) == 0) continue;
    const std::string prefix = "t" + std::to_string(task.task) + ".";
    const std::size_t samples = static_cast<std::size_t>(
        std::count_if(answers.exchanges.begin(), answers.exchanges.end(),
                      [&prefix](const Exchange& x) { return x.check.rfind(prefix, 0) == 0; }));
    if (std::optional<NamedMistake> m = mistakeOf(task, task.measure(answers), samples))
      out.push_back(std::move(*m));
  }
  return out;
}

}  // namespace a6::grader
