// The framework's part of task 7: the sparse system of one implicit step and its solve.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>
#include <stdexcept>
#include <string>

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

// The conjugate gradient's relative residual |A Δv - b| / |b| to reach, its iterations at most,
// and the residual it must reach for its answer to be taken (else the sparse LU solves).
constexpr double kTolerance = 1e-10;
constexpr int kMaxIterations = 1000;
constexpr double kAcceptable = 1e-6;

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
  Eigen::SparseMatrix<double> a(2 * n_, 2 * n_);
  a.setFromTriplets(kept.begin(), kept.end());  // duplicates are summed

  // Conjugate gradient (A symmetric); a sparse LU where it does not converge (a compressed
  // spring can make A indefinite).
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kTolerance);
  cg.setMaxIterations(kMaxIterations);
  cg.compute(a);
  Eigen::VectorXd dv = cg.solve(b);
  if (!allFinite(dv) || !(cg.error() <= kAcceptable)) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(a);
    if (lu.info() != Eigen::Success) {
      throw std::runtime_error("ImplicitSystem::solve: the matrix is singular (" +
                               lu.lastErrorMessage() + ")");
    }
    dv = lu.solve(b);
  }
  if (!allFinite(dv)) throw std::runtime_error("ImplicitSystem::solve: the result is not finite");

  std::vector<Vec2> out(n_);
  for (int i = 0; i < n_; ++i) out[i] = dv.segment<2>(2 * i);
  return out;
}

}  // namespace a6
