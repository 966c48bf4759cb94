// The framework's part of task 7: the sparse system of one implicit step and its solve.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/IterativeSolvers>

#include "a6/implicit.h"

namespace a6 {

namespace {

void checkIndex(int i, int n, const char* what) {
  if (i < 0 || i >= n) {
    throw std::out_of_range(std::string("ImplicitSystem::") + what + ": particle " +
                            std::to_string(i) + " is not in [0, " + std::to_string(n) + ")");
  }
}

bool allFinite(const Eigen::VectorXd& x) { return x.allFinite(); }

using Sparse = Eigen::SparseMatrix<double>;

// The conjugate gradient's relative residual |A Δv - b| / |b| to reach, its iterations at most,
// and the residual it must reach for its answer to be taken (else the sparse LU solves).
constexpr double kTolerance = 1e-8;
constexpr int kMaxIterations = 1000;
constexpr double kAcceptable = 1e-6;

// MINRES on D A D y = D b, x = D y, with D = |diag A|^-1/2: the symmetric scaling that Jacobi
// preconditioning is for CG, kept symmetric for MINRES, which takes an indefinite A.
Eigen::VectorXd solveIndefinite(const Sparse& a, const Eigen::VectorXd& b, double& error) {
  Eigen::VectorXd d = a.diagonal().cwiseAbs().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Sparse scaled = d.asDiagonal() * a * d.asDiagonal();
  Eigen::MINRES<Sparse, Eigen::Lower | Eigen::Upper, Eigen::IdentityPreconditioner> minres;
  minres.setTolerance(kTolerance);
  minres.setMaxIterations(kMaxIterations);
  minres.compute(scaled);
  const Eigen::VectorXd x = d.asDiagonal() * minres.solve(d.asDiagonal() * b);
  error = minres.error();
  return x;
}

// Conjugate gradient while A is positive definite (every spring stretched); MINRES where a
// compressed spring makes A indefinite and CG stalls; a sparse LU as the last resort.
Eigen::VectorXd solveSymmetric(const Sparse& a, const Eigen::VectorXd& b) {
  Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kTolerance);
  cg.setMaxIterations(kMaxIterations);
  cg.compute(a);
  Eigen::VectorXd x = cg.solve(b);
  if (allFinite(x) && cg.error() <= kAcceptable) return x;
  double error = 0;
  x = solveIndefinite(a, b, error);
  if (allFinite(x) && error <= kAcceptable) return x;
  Eigen::SparseLU<Sparse> lu;
  lu.compute(a);
  if (lu.info() != Eigen::Success) {
    throw std::runtime_error("ImplicitSystem::solve: the matrix is singular (" +
                             lu.lastErrorMessage() + ")");
  }
  return lu.solve(b);
}

}  // namespace

ImplicitSystem::ImplicitSystem(int particles)
    : n_(particles), b_(Eigen::VectorXd::Zero(2 * particles)), fixed_(particles, false) {
  if (particles < 0) throw std::invalid_argument("ImplicitSystem: a negative particle count");
  entries_.reserve(static_cast<std::size_t>(particles) * 4 * 9);
}

void ImplicitSystem::addBlock(int i, int j, const Mat2& block) {
  checkIndex(i, n_, "addBlock");
  checkIndex(j, n_, "addBlock");
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) entries_.emplace_back(2 * i + r, 2 * j + c, block(r, c));
  }
}

void ImplicitSystem::addToB(int i, const Vec2& value) {
  checkIndex(i, n_, "addToB");
  b_.segment<2>(2 * i) += value;
}

void ImplicitSystem::fix(int i) {
  checkIndex(i, n_, "fix");
  fixed_[i] = true;
}

std::vector<Vec2> ImplicitSystem::solve() const {
  // A without the fixed particles' rows and columns, and the identity in their place.
  std::vector<Eigen::Triplet<double>> kept;
  kept.reserve(entries_.size() + 2 * n_);
  for (const auto& t : entries_) {
    if (!fixed_[t.row() / 2] && !fixed_[t.col() / 2]) kept.push_back(t);
  }
  Eigen::VectorXd b = b_;
  for (int i = 0; i < n_; ++i) {
    if (!fixed_[i]) continue;
    kept.emplace_back(2 * i, 2 * i, 1.0);
    kept.emplace_back(2 * i + 1, 2 * i + 1, 1.0);
    b.segment<2>(2 * i).setZero();
  }
  Sparse a(2 * n_, 2 * n_);
  a.setFromTriplets(kept.begin(), kept.end());  // duplicates are summed

  const Eigen::VectorXd dv = solveSymmetric(a, b);
  if (!allFinite(dv)) throw std::runtime_error("ImplicitSystem::solve: the result is not finite");

  std::vector<Vec2> out(n_);
  for (int i = 0; i < n_; ++i) out[i] = dv.segment<2>(2 * i);
  return out;
}

}  // namespace a6
