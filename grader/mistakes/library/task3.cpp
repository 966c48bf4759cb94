// Task 3, time stepping: the reference's symplectic Euler step (steppers.h, with the reference
// forces, which the checks of task 3 ask the probe for too: referenceForces), and its mistakes
// part by part: the step's parts (resetting the forces, a spring's two ends, the mass, the order
// of v and x, the pins, the substeps' length) each in the physics' form or a wrong one, with one
// or two parts wrong. Requests run on the student's own forces or with the implicit step cannot
// be modelled: they are skipped.
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"
#include "mistakes/library/steppers.h"

namespace a6::grader::mistakes {
namespace {

using harness::SimulateRequest;
using harness::SimulateResult;

// One wrong form of one part of the step: its key (the model's id; a one-part form's is the
// wrong version's it was first written from, tests/wrong/t3_<key>), what it does, and the form.
struct WrongPart {
  int part;  // parts with the same number exclude each other
  const char* key;
  const char* does;
  void (*apply)(StepForm&);
};

const std::vector<WrongPart>& wrongParts() {
  static const std::vector<WrongPart> parts = {
      {0, "forces_not_reset",
       "never resets the forces (p.f += externalForce(p) adds to the last step's): start each "
       "step with p.f = externalForce(p)",
       [](StepForm& f) { f.forcesKept = true; }},
      {1, "spring_force_same_sign", "gives both ends of a spring +f: p1 must get -f",
       [](StepForm& f) { f.springEnds = 1; }},
      {1, "spring_ends_swapped",
       "gives p2 -f and p1 +f: the force springForce returns is p2's, p1 gets its opposite",
       [](StepForm& f) { f.springEnds = 2; }},
      {2, "force_not_divided_by_mass",
       "does not divide the force by the mass: the acceleration is f / m",
       [](StepForm& f) { f.noMassDivision = true; }},
      {3, "position_before_velocity",
       "moves x with the old velocity (x += v dt before v += f/m dt): update v first, then x "
       "with the new v",
       [](StepForm& f) { f.positionFirst = true; }},
      {4, "missing_pinning", "moves pinned particles too: skip them for both v and x",
       [](StepForm& f) { f.pins = 1; }},
      {4, "pinned_velocity_changes",
       "changes a pinned particle's velocity (only its x is kept): skip it for v too",
       [](StepForm& f) { f.pins = 2; }},
      {4, "pinned_position_moves",
       "moves a pinned particle's x with its velocity (only its v is kept): skip it for x too",
       [](StepForm& f) { f.pins = 3; }},
      {5, "substeps_reuse_frame_dt",
       "takes substeps of the whole frame time in advance: each must be frameDt / n long",
       [](StepForm& f) { f.substepFullDt = true; }},
  };
  return parts;
}

MistakeModel model(const std::vector<const WrongPart*>& wrong) {
  StepForm form;
  std::string key, text = "Your step ";
  for (const WrongPart* part : wrong) {
    part->apply(form);
    key += (key.empty() ? "" : "_and_") + std::string(part->key);
    text += (part == wrong.front() ? "" : "; it ") + std::string(part->does);
  }
  auto judge = [form](const Transcript& t) {
    return judgeEach(
        t.of<harness::SimulateRequest>(),
        [](const SimulateRequest& r) { return simulate(r, StepForm{}); },
        [form](const SimulateRequest& r) { return simulate(r, form); }, sameRun);
  };
  MistakeModel m{"t3_" + key, 3, text + ".", judge};
  m.partByPart = true;
  return m;
}

}  // namespace

// Every step with one or two parts in a wrong form, named part by part (MistakeModel::partByPart).
std::vector<MistakeModel> task3Mistakes() {
  std::vector<MistakeModel> models;
  const std::vector<WrongPart>& parts = wrongParts();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    models.push_back(model({&parts[i]}));
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      if (parts[j].part != parts[i].part) models.push_back(model({&parts[i], &parts[j]}));
    }
  }
  return models;
}

}  // namespace a6::grader::mistakes
