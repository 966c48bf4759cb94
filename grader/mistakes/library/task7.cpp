// Task 7, the implicit step, part by part: the reference's step (reference/steppers.h: one
// linearised backward Euler step with the reference forces and the physics' Jacobians, solved
// densely) with its parts (the off-diagonal blocks' sign, the power of h before dfdx, the term h²
// dfdx v of b, how Δv is applied, the pins' fix(), the order of v and x) each in the physics' form
// or a wrong one, with one or two parts wrong. The checks' small systems are modelled (a dense
// solve per step); the stiff cloth, and requests run on the student's own forces, are skipped. A
// wrong Jacobian makes every one of these differ: it is named by its own models (parts.cpp).
#include "mistakes/library/models.h"
#include "mistakes/library/step_parts.h"
#include "reference/steppers.h"

namespace a6::grader::mistakes {

using reference::ImplicitForm;
using reference::simulateImplicit;

// Every step with one or two parts in a wrong form (MistakeModel::partByPart); each part has its
// own number: none excludes another.
std::vector<MistakeModel> task7Mistakes() {
  const std::vector<WrongPart<ImplicitForm>> parts = {
      {0, "off_diagonal_sign",
       "adds -K on the off-diagonal blocks (i, j) and (j, i): they take +K, the diagonal ones -K",
       [](ImplicitForm& f) { f.offDiagonalNegative = true; }},
      {1, "h_instead_of_h_squared",
       "puts h dfdx in A where the physics has h² dfdx: A = M - h dfdv - h² dfdx",
       [](ImplicitForm& f) { f.hBeforeDfdx = true; }},
      {2, "rhs_without_dfdx_v",
       "leaves h² dfdx (v_j - v_i) out of b: b = h (f + h dfdx v), spring by spring",
       [](ImplicitForm& f) { f.rhsWithoutDfdxV = true; }},
      {3, "delta_v_as_velocity",
       "uses the solve's Δv as the new velocity: it is the change, v += Δv",
       [](ImplicitForm& f) { f.deltaVAsVelocity = true; }},
      {4, "pinned_rows_not_fixed",
       "never fix()es the pinned particles, so the others are solved as if the pins could move",
       [](ImplicitForm& f) { f.pinsNotFixed = true; }},
      {5, "position_before_velocity",
       "moves x with the old velocity (x += h v before v += Δv): apply Δv first",
       [](ImplicitForm& f) { f.positionFirst = true; }},
  };
  return stepModels(7, "stepImplicit", simulateImplicit, parts);
}

}  // namespace a6::grader::mistakes
