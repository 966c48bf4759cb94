// Task 7, the implicit step, part by part: the reference's step (steppers.h: one linearised
// backward Euler step with the reference forces and the physics' Jacobians, solved densely) with
// its parts (the off-diagonal blocks' sign, the power of h before dfdx, the term h² dfdx v of b,
// how Δv is applied, the pins' fix(), the order of v and x) each in the physics' form or a wrong
// one, with one or two parts wrong. The checks' small systems are modelled (a dense solve per
// step); the stiff cloth, and requests run on the student's own forces, are skipped. A wrong
// Jacobian makes every one of these differ: it is named by its own models (parts.cpp).
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"
#include "mistakes/library/steppers.h"

namespace a6::grader::mistakes {
namespace {

using harness::SimulateRequest;
using harness::SimulateResult;

// One wrong form of one part of the step: its key (the model's id; a one-part form's is the
// wrong version's it was first written from, tests/wrong/t7_<key>), what it does, and the form.
struct WrongPart {
  const char* key;
  const char* does;
  void (*apply)(ImplicitForm&);
};

const std::vector<WrongPart>& wrongParts() {
  static const std::vector<WrongPart> parts = {
      {"off_diagonal_sign",
       "adds -K on the off-diagonal blocks (i, j) and (j, i): they take +K, the diagonal ones -K",
       [](ImplicitForm& f) { f.offDiagonalNegative = true; }},
      {"h_instead_of_h_squared",
       "puts h dfdx in A where the physics has h² dfdx: A = M - h dfdv - h² dfdx",
       [](ImplicitForm& f) { f.hBeforeDfdx = true; }},
      {"rhs_without_dfdx_v",
       "leaves h² dfdx (v_j - v_i) out of b: b = h (f + h dfdx v), spring by spring",
       [](ImplicitForm& f) { f.rhsWithoutDfdxV = true; }},
      {"delta_v_as_velocity", "uses the solve's Δv as the new velocity: it is the change, v += Δv",
       [](ImplicitForm& f) { f.deltaVAsVelocity = true; }},
      {"pinned_rows_not_fixed",
       "never fix()es the pinned particles, so the others are solved as if the pins could move",
       [](ImplicitForm& f) { f.pinsNotFixed = true; }},
      {"position_before_velocity",
       "moves x with the old velocity (x += h v before v += Δv): apply Δv first",
       [](ImplicitForm& f) { f.positionFirst = true; }},
  };
  return parts;
}

MistakeModel model(const std::vector<const WrongPart*>& wrong) {
  ImplicitForm form;
  std::string key, text = "Your stepImplicit ";
  for (const WrongPart* part : wrong) {
    part->apply(form);
    key += (key.empty() ? "" : "_and_") + std::string(part->key);
    text += (part == wrong.front() ? "" : "; it ") + std::string(part->does);
  }
  auto judge = [form](const Transcript& t) {
    return judgeEach(
        t.of<harness::SimulateRequest>(),
        [](const SimulateRequest& r) { return simulateImplicit(r, ImplicitForm{}); },
        [form](const SimulateRequest& r) { return simulateImplicit(r, form); }, sameRun);
  };
  MistakeModel m{"t7_" + key, 7, text + ".", judge};
  m.partByPart = true;
  return m;
}

}  // namespace

// Every step with one or two parts in a wrong form (MistakeModel::partByPart).
std::vector<MistakeModel> task7Mistakes() {
  std::vector<MistakeModel> models;
  const std::vector<WrongPart>& parts = wrongParts();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    models.push_back(model({&parts[i]}));
    for (std::size_t j = i + 1; j < parts.size(); ++j)
      models.push_back(model({&parts[i], &parts[j]}));
  }
  return models;
}

}  // namespace a6::grader::mistakes
