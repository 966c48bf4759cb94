// Task 7 (extra credit) — implicit Euler
// Slides: "Instability" ("a more robust integration scheme"); Baraff and Witkin, "Large steps in
// cloth simulation" (SIGGRAPH 1998). The handout's "Task 7" derives all of this in a page.
//
// Explicit steps (task 3) blow up once sqrt(k/m) dt > 2. Backward Euler evaluates the forces at
// the END of the step instead:
//     v1 = v0 + dt M⁻¹ f(x1, v1),   x1 = x0 + dt v1.
// Linearise f about (x0, v0) (one Newton step), write Δv = v1 - v0, and you get one linear
// system for every particle's Δv at once:
//
//     (M - dt ∂f/∂v - dt² ∂f/∂x) Δv = dt (f + dt ∂f/∂x v)
//
// 1. springJacobians(s): the derivatives of the spring force on p2 (task 1's f2). With
//    d = x2 - x1, l = |d|, e = d / l, I the 2x2 identity (Mat2::Identity()):
//        dfdx = ∂f2/∂x2 = -ks ( e eᵀ + (1 - l0 / l) (I - e eᵀ) )       (e eᵀ: e * e.transpose())
//        dfdv = ∂f2/∂v2 = -kd e eᵀ
//    Coincident particles (l < 1e-12): return zero Jacobians. (The damping term's derivative by
//    position is left out, as Baraff and Witkin do: the matrix stays symmetric.)
//
// 2. MassSpringSystem::stepImplicit(dt):
//    a. the forces, exactly as in step(): p.f = externalForce(p), then every springForce(s)
//       added to p2 and subtracted from p1;
//    b. the system to solve: implicitSystem() (a6/implicit.h), empty. For every particle i:
//           addBlock(i, i, m_i I)          addToB(i, dt f_i)
//       For every spring, with i, j its p1 and p2 (springEnds()[k]) and
//       K = dt dfdv + dt² dfdx  (f2 depends on x2 - x1, so ∂f2/∂x1 = -dfdx, ∂f1/∂x1 = +dfdx):
//           addBlock(i, i, -K)  addBlock(j, j, -K)  addBlock(i, j, K)  addBlock(j, i, K)
//           addToB(j, dt² dfdx (v_j - v_i))      addToB(i, -dt² dfdx (v_j - v_i))
//    c. fix(i) for every pinned particle (its Δv is zero);
//    d. dv = solve(); for every particle that is not pinned: v += dv[i] (Δv is the CHANGE of
//       velocity), then x += v dt with the new v.
//
// Done when: `ctest -R Task7` passes (tests named Task7Implicit.*): the Jacobians against hand-
// computed values and finite differences of your task 1 force, one step against the closed form
// of backward Euler, energy that never grows, pinning, and the stiff cloth that stays together in
// one step per frame.
#include "a6/implicit.h"

#include "a6/mass_spring_system.h"

namespace a6 {

SpringJacobians springJacobians(const Spring& s) {
  // TODO(task 7): dfdx = -ks (e eᵀ + (1 - l0/l) (I - e eᵀ)), dfdv = -kd e eᵀ.
  return {};
}

void MassSpringSystem::stepImplicit(double dt) {
  // TODO(task 7): parts a to d above.
}

}  // namespace a6
