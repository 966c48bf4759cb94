// Steps named part by part (tasks 3 and 7): the wrong forms of a stepper's parts (steppers.h) and
// every step with one or two parts wrong as a model (MistakeModel::partByPart), judged on the
// simulations the checks asked for, the step in its form beside the physics' (Form{}).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mistakes/library/compare.h"

namespace a6::grader::mistakes {

/// One wrong form of one part of a step: its key (the model's id; a one-part form's is the wrong
/// version's it was first written from, tests/wrong/t<task>_<key>), what it does, and the form.
template <class Form>
struct WrongPart {
  int part;  ///< parts with the same number exclude each other
  const char* key;
  const char* does;
  void (*apply)(Form&);
};

/// A stepper (steppers.h: simulate, simulateImplicit): a simulation's answer in a form.
template <class Form>
using Stepper = std::optional<harness::SimulateResult> (*)(const harness::SimulateRequest&,
                                                           const Form&);

/// The model of task `task` whose `step` ("step", "stepImplicit") has the parts `wrong` wrong.
template <class Form>
MistakeModel stepModel(int task, const char* step, Stepper<Form> run,
                       const std::vector<const WrongPart<Form>*>& wrong) {
  Form form;
  std::string key, text = "Your " + std::string(step) + " ";
  for (const WrongPart<Form>* part : wrong) {
    part->apply(form);
    key += (key.empty() ? "" : "_and_") + std::string(part->key);
    text += (part == wrong.front() ? "" : "; it ") + std::string(part->does);
  }
  auto judge = [run, form](const Transcript& t) {
    return judgeEach(
        t.of<harness::SimulateRequest>(),
        [run](const harness::SimulateRequest& r) { return run(r, Form{}); },
        [run, form](const harness::SimulateRequest& r) { return run(r, form); }, sameRun);
  };
  MistakeModel m{"t" + std::to_string(task) + "_" + key, task, text + ".", judge};
  m.partByPart = true;
  return m;
}

/// Every `step` of task `task` with one of `parts` wrong or two (of different parts), in the
/// parts' order: each part alone, then with each later one.
template <class Form>
std::vector<MistakeModel> stepModels(int task, const char* step, Stepper<Form> run,
                                     const std::vector<WrongPart<Form>>& parts) {
  std::vector<MistakeModel> models;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    models.push_back(stepModel(task, step, run, {&parts[i]}));
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      if (parts[j].part != parts[i].part)
        models.push_back(stepModel(task, step, run, {&parts[i], &parts[j]}));
    }
  }
  return models;
}

}  // namespace a6::grader::mistakes
