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
#include <Eigen/SparseCore>
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
///   ImplicitSystem sys(n);
///   sys.addBlock(i, j, block);   // A's block (i, j) += block
///   sys.addToB(i, value);        // b's entries of particle i += value
///   sys.fix(i);                  // Δv of particle i is zero (a pinned particle)
///   std::vector<Vec2> dv = sys.solve();   // dv[i]: the velocity change of particle i, m/s
///
/// A must be symmetric (add block (i, j) and its transpose at (j, i)); the solve is a sparse
/// Cholesky factorisation, Eigen's SimplicialLDLT (which also takes the indefinite A that a
/// compressed spring can make), and a sparse LU where that fails. Blocks and fixes may come in
/// any order; a system built the same way at every step (the same springs, in the same order)
/// reuses the last step's matrix shape and ordering, which makes its solve about three times
/// cheaper and leaves its answer unchanged.
class ImplicitSystem {
 public:
  explicit ImplicitSystem(int particles);
  ~ImplicitSystem();
  ImplicitSystem(const ImplicitSystem&) = default;
  ImplicitSystem(ImplicitSystem&&) = default;
  ImplicitSystem& operator=(const ImplicitSystem&) = default;
  ImplicitSystem& operator=(ImplicitSystem&&) = default;
  int particles() const { return n_; }
  /// A(i, j) += block (2x2, kg).
  void addBlock(int i, int j, const Mat2& block);
  /// b(i) += value (kg·m/s).
  void addToB(int i, const Vec2& value);
  /// Keeps particle i's velocity: its rows and columns of A become the identity's, its b zero.
  void fix(int i);
  /// Solves A Δv = b; one velocity change per particle, m/s. Throws std::runtime_error when A
  /// is singular or the result is not finite.
  std::vector<Vec2> solve() const;

  /// One addBlock call: A(i, j) += value.
  struct Block {
    int i, j;
    Mat2 value;
  };

 private:
  int n_;
  std::vector<Block> blocks_;
  Eigen::VectorXd b_;
  std::vector<bool> fixed_;
};

}  // namespace a6
