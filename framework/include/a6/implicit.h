// Task 7 (extra credit): implicit Euler, the slides' "more robust integration scheme"
// (slide "Instability"; Baraff and Witkin, "Large steps in cloth simulation", 1998).
//
// One linearised backward Euler step (one Newton step) of a mass-spring system solves
//     (M - h ∂f/∂v - h² ∂f/∂x) Δv = h (f + h ∂f/∂x v)
// for the velocity change Δv of every particle, then v += Δv, x += h v. The student writes the
// spring's Jacobians (springJacobians, implicit.cpp) and the step (MassSpringSystem::stepImplicit,
// implicit.cpp); the framework gives the sparse matrix and its solver (ImplicitSystem, below).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "a6/spring.h"

namespace a6 {

using Mat2 = Eigen::Matrix2d;

/// The derivatives of a spring's force on p2, f2 = computeForce() (task 1), 2x2, world frame.
/// Since f1 = -f2 and f2 depends on x2 - x1 and v2 - v1 only:
///   ∂f2/∂x2 = dfdx, ∂f2/∂x1 = -dfdx, ∂f1/∂x1 = dfdx, ∂f1/∂x2 = -dfdx; the same for v.
struct SpringJacobians {
  Mat2 dfdx = Mat2::Zero();  ///< ∂f2/∂x2 of the elastic term -ks (l - l0) e, N/m
  Mat2 dfdv = Mat2::Zero();  ///< ∂f2/∂v2 of the damping term -kd ((v2 - v1)·e) e, N·s/m
};

/// TASK 7 (implicit.cpp). With d = x2 - x1, l = |d|, e = d / l and I the 2x2 identity:
///   dfdx = -ks ( e eᵀ + (1 - l0 / l) (I - e eᵀ) )
///   dfdv = -kd e eᵀ
/// dfdx leaves out the damping term's derivative by position (zero when v2 = v1), as Baraff and
/// Witkin do, so that the system stays symmetric. Coincident particles (l below 1e-12 m): zero.
SpringJacobians springJacobians(const Spring& s);

/// The linear system A Δv = b of one implicit step of n particles: A is 2n x 2n, made of 2x2
/// blocks, particle i owning rows and columns 2i and 2i+1; b and Δv are 2n long.
///
///   ImplicitSystem& sys = implicitSystem();   // MassSpringSystem's, empty, n = its particles
///   sys.addBlock(i, j, block);   // A's block (i, j) += block
///   sys.addToB(i, value);        // b's entries of particle i += value
///   sys.fix(i);                  // Δv of particle i is zero (a pinned particle)
///   std::vector<Vec2> dv = sys.solve();   // dv[i]: the velocity change of particle i, m/s
///
/// A must be symmetric (add block (i, j) and its transpose at (j, i)); the solve is a sparse
/// Cholesky factorisation, Eigen's SimplicialLDLT (which also takes the indefinite A that a
/// compressed spring can make), and a sparse LU where that fails. Blocks and fixes may come in
/// any order. A system keeps, from one solve to the next, what depends on its matrix's shape
/// only (the pattern and the ordering): built the same way at every step (the same springs, in
/// the same order), its solve is about three times cheaper, with the same answer. That is why
/// MassSpringSystem::implicitSystem() hands out the same system at every step, emptied; a system
/// of your own, ImplicitSystem sys(n), gives the same answers, only slower.
class ImplicitSystem {
 public:
  explicit ImplicitSystem(int particles = 0);
  ~ImplicitSystem();
  /// A copy has the same blocks, b and fixes; it learns its shape anew.
  ImplicitSystem(const ImplicitSystem& other);
  ImplicitSystem& operator=(const ImplicitSystem& other);
  int particles() const;
  /// Empties the system (no blocks, b zero, nothing fixed) for `particles` particles; what it
  /// learnt of the last shape is kept.
  void reset(int particles);
  /// A(i, j) += block (2x2, kg).
  void addBlock(int i, int j, const Mat2& block);
  /// b(i) += value (kg·m/s).
  void addToB(int i, const Vec2& value);
  /// Keeps particle i's velocity: its rows and columns of A become the identity's, its b zero.
  void fix(int i);
  /// Solves A Δv = b; one velocity change per particle, m/s. Throws std::runtime_error when A
  /// is singular or the result is not finite.
  std::vector<Vec2> solve();

 private:
  struct State;  // the blocks, b, the fixes and the solver's kept work (implicit_system.cpp)
  std::unique_ptr<State> state_;
};

}  // namespace a6
