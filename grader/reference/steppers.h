// The reference steppers, built on the reference physics (physics.inc, included by steppers.cpp
// alone): task 3's symplectic Euler step (advance as n steps of T / n), task 5's update of
// particles already alive, task 7's linearised backward Euler step (solved densely). Each runs in
// a form whose default is the physics': the replays run that (referenceSimulation,
// referenceParticleRun: mistakes.h); the mistake library's models of tasks 3, 5 and 7 name the
// wrong forms of one or two parts and run them here. Takes a request the checks made; gives the
// answer of the form, or nothing for a request the stepper cannot model (the student's own
// forces, an emitter, a system too large for a dense solve). Graders' material, as physics.inc.
#pragma once

#include <optional>

#include "harness/student_code.h"

namespace a6::grader::reference {

// One form of the step, part by part; the default is the physics'.
struct StepForm {
  bool forcesKept = false;      ///< p.f += externalForce(p): the last step's forces never reset
  int springEnds = 0;           ///< 0: p2 +f, p1 -f; 1: both +f; 2: p2 -f, p1 +f
  bool noMassDivision = false;  ///< v += f dt
  bool positionFirst = false;   ///< x += v dt before v += f/m dt
  int pins = 0;                 ///< 0: skipped; 1: moved like the others; 2: only x kept; 3: only v
  bool substepFullDt = false;   ///< advance's substeps each take the whole frameDt
};

/// Task 3: a simulation with the reference forces, symplectic Euler in `form`.
std::optional<harness::SimulateResult> simulate(const harness::SimulateRequest& r,
                                                const StepForm& form);

/// Task 5: how an update differs from the physics' (None: it does not).
enum class ParticleFlaw { None, PositionFirst, CoolingWrongSign, NoRemoval, RemovalLate };

/// Task 5: a run of particles already alive (no emission) with the reference forces.
std::optional<harness::ParticlesResult> runParticles(const harness::ParticleRunRequest& r,
                                                     ParticleFlaw flaw);

// One form of the step, part by part; the default is the physics'.
struct ImplicitForm {
  bool offDiagonalNegative = false;  ///< -K on the blocks (i, j) and (j, i), where +K belongs
  bool hBeforeDfdx = false;          ///< K = h dfdv + h dfdx: h where h² belongs
  bool rhsWithoutDfdxV = false;      ///< b = h f
  bool deltaVAsVelocity = false;     ///< v = Δv
  bool pinsNotFixed = false;         ///< no fix(): pins solved as free, then skipped
  bool positionFirst = false;        ///< x += h v before v += Δv
};

/// Task 7: an implicit simulation of a small system (at most 12 particles) with the reference
/// forces and the physics' Jacobians, in `form`.
std::optional<harness::SimulateResult> simulateImplicit(const harness::SimulateRequest& r,
                                                        const ImplicitForm& form);

}  // namespace a6::grader::reference
