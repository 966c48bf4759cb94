#include "mistakes/mistakes.h"

#include <map>

#include "mistakes/measure.h"

namespace a6::grader {
namespace {

struct Tally {
  int mistake = 0, reference = 0, neither = 0;
  /// Like the mistake somewhere, and wherever it differs from the reference (never like the
  /// reference there, nor like neither).
  bool fits() const { return mistake > 0 && reference == 0 && neither == 0; }
};

Tally tally(const std::vector<Likeness>& verdicts) {
  Tally t;
  for (const Likeness v : verdicts) {
    if (v == Likeness::Mistake) ++t.mistake;
    if (v == Likeness::Reference) ++t.reference;
    if (v == Likeness::Neither) ++t.neither;
  }
  return t;
}

}  // namespace

std::vector<NamedMistake> nameMistakes(const Transcript& transcript,
                                       const std::vector<MistakeModel>& library,
                                       const std::set<int>& failingTasks) {
  std::map<int, NamedMistake> best;                  // per task: the model with the most evidence
  std::map<int, std::vector<NamedMistake>> fitting;  // per task: the part-by-part models that fit
  for (const MistakeModel& model : library) {
    if (failingTasks.count(model.task) == 0 || !model.judge) continue;
    const Tally t = tally(model.judge(transcript));
    if (model.partByPart) {
      if (t.fits()) fitting[model.task].push_back({model.id, model.task, model.text, t.mistake});
      continue;
    }
    if (!t.fits()) continue;
    const auto found = best.find(model.task);
    if (found != best.end() && found->second.evidence >= t.mistake) continue;
    best[model.task] = NamedMistake{model.id, model.task, model.text, t.mistake};
  }
  // One part-by-part model alone fits: the evidence singles out the parts and how they are wrong.
  for (auto& [task, fits] : fitting) {
    if (fits.size() == 1) best[task] = std::move(fits.front());
  }
  std::vector<NamedMistake> named;
  for (auto& [task, mistake] : best) named.push_back(std::move(mistake));
  return named;
}

std::vector<NamedMistake> combine(const std::vector<NamedMistake>& catalogue,
                                  const std::vector<NamedMistake>& diagnosed) {
  std::map<int, NamedMistake> byTask;
  for (const NamedMistake& m : diagnosed) byTask[m.task] = m;
  for (const NamedMistake& m : catalogue) byTask[m.task] = m;
  std::vector<NamedMistake> out;
  for (auto& [task, m] : byTask) out.push_back(std::move(m));
  return out;
}

}  // namespace a6::grader
