// Task 3, time stepping: the reference's symplectic Euler step (reference/steppers.h, with the
// reference forces, which the checks of task 3 ask the probe for too: referenceForces), and its
// mistakes part by part: the step's parts (resetting the forces, a spring's two ends, the mass, the
// order of v and x, the pins, the substeps' length) each in the physics' form or a wrong one, with
// one or two parts wrong. Requests run on the student's own forces or with the implicit step cannot
// be modelled: they are skipped.
#include "mistakes/library/models.h"
#include "mistakes/library/step_parts.h"
#include "reference/steppers.h"

namespace a6::grader::mistakes {

using reference::simulate;
using reference::StepForm;

// Every step with one or two parts in a wrong form, named part by part (MistakeModel::partByPart).
std::vector<MistakeModel> task3Mistakes() {
  const std::vector<WrongPart<StepForm>> parts = {
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
  return stepModels(3, "step", simulate, parts);
}

}  // namespace a6::grader::mistakes
