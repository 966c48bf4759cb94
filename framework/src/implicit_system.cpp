// The framework's part of task 7: the sparse system of one implicit step and its solve.
//
// A step's system has the same shape at every step (the same springs, added in the same order),
// so what depends on the shape only is made once and kept by the system (its Shape): the sparse
// matrix's pattern, where each added block's entries go in it, and the factorisation's symbolic
// analysis (the AMD ordering and elimination tree, which cost about twice the numeric
// factorisation). A step then writes its values into the kept matrix and factorises it. The
// answer is the same, bit for bit, as from a matrix built afresh. MassSpringSystem keeps one
// system and empties it for every step (reset), so the shape outlives the step.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "a6/implicit.h"

namespace a6 {

// The types of ImplicitSystem::State (a named namespace: State is not in an anonymous one).
namespace implicit_solver {

using Sparse = Eigen::SparseMatrix<double>;

// One addBlock call: A(i, j) += value.
struct Block {
  int i, j;
  Mat2 value;
};

// What a system keeps from its last solve (see the top of this file). A copy starts without it.
struct Shape {
  Shape() = default;
  Shape(const Shape&) {}
  Shape& operator=(const Shape&) {
    n = -1;
    return *this;
  }

  int n = -1;                            ///< -1: no shape (none yet, or its making was interrupted)
  std::vector<std::array<int, 2>> keys;  // (i, j) of every block, in the order added
  std::vector<bool> fixed;
  std::vector<int> slots;     // 4 per block, (r, c) row-major: its index in a's values, or -1
  std::vector<int> identity;  // the indices of the fixed particles' diagonal entries
  Sparse a;
  Eigen::SimplicialLDLT<Sparse> ldlt;
};

}  // namespace implicit_solver

namespace {

using implicit_solver::Block;
using implicit_solver::Shape;
using implicit_solver::Sparse;

// The relative residual |A Δv - b| / |b| an answer must reach to be taken.
constexpr double kAcceptable = 1e-6;

void checkIndex(int i, int n, const char* what) {
  if (i < 0 || i >= n) {
    throw std::out_of_range(std::string("ImplicitSystem::") + what + ": particle " +
                            std::to_string(i) + " is not in [0, " + std::to_string(n) + ")");
  }
}

// The index of entry (row, col) in a's values; the entry is in a's pattern.
int indexOf(const Sparse& a, int row, int col) {
  const int* rows = a.innerIndexPtr();
  const int* first = rows + a.outerIndexPtr()[col];
  const int* last = rows + a.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(first, last, row) - rows);
}

bool sameShape(const Shape& w, int n, const std::vector<Block>& blocks,
               const std::vector<bool>& fixed) {
  if (w.n != n || w.keys.size() != blocks.size() || w.fixed != fixed) return false;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    if (w.keys[k][0] != blocks[k].i || w.keys[k][1] != blocks[k].j) return false;
  }
  return true;
}

// A's pattern: every block's entries except the fixed particles' rows and columns, and the
// identity's diagonal in their place; the slots; the symbolic analysis.
void reshape(Shape& w, int n, const std::vector<Block>& blocks, const std::vector<bool>& fixed) {
  w.n = -1;  // until the end: a throw (bad_alloc) halfway leaves no shape to match
  const auto kept = [&](const Block& b) { return !fixed[b.i] && !fixed[b.j]; };
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(4 * blocks.size() + 2 * n);
  for (const auto& b : blocks) {
    if (!kept(b)) continue;
    for (int e = 0; e < 4; ++e) pattern.emplace_back(2 * b.i + e / 2, 2 * b.j + e % 2, 0.0);
  }
  for (int i = 0; i < n; ++i) {
    if (fixed[i])
      pattern.emplace_back(2 * i, 2 * i, 0.0), pattern.emplace_back(2 * i + 1, 2 * i + 1, 0.0);
  }
  w.a = Sparse(2 * n, 2 * n);
  w.a.setFromTriplets(pattern.begin(), pattern.end());

  w.slots.assign(4 * blocks.size(), -1);
  w.keys.resize(blocks.size());
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const auto& b = blocks[k];
    w.keys[k] = {b.i, b.j};
    if (!kept(b)) continue;
    for (int e = 0; e < 4; ++e) w.slots[4 * k + e] = indexOf(w.a, 2 * b.i + e / 2, 2 * b.j + e % 2);
  }
  w.identity.clear();
  for (int i = 0; i < n; ++i) {
    if (!fixed[i]) continue;
    w.identity.push_back(indexOf(w.a, 2 * i, 2 * i));
    w.identity.push_back(indexOf(w.a, 2 * i + 1, 2 * i + 1));
  }
  w.ldlt.analyzePattern(w.a);
  w.n = n;
  w.fixed = fixed;
}

// A's values, summed in the order the blocks were added.
void fill(Shape& w, const std::vector<Block>& blocks) {
  double* values = w.a.valuePtr();
  std::fill(values, values + w.a.nonZeros(), 0.0);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    for (int e = 0; e < 4; ++e) {
      const int slot = w.slots[4 * k + e];
      if (slot >= 0) values[slot] += blocks[k].value(e / 2, e % 2);
    }
  }
  for (const int slot : w.identity) values[slot] = 1.0;
}

bool solves(const Sparse& a, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  if (!x.allFinite()) return false;
  return (a * x - b).norm() <= kAcceptable * std::max(b.norm(), 1e-300);
}

// LDLᵀ, its cost independent of the springs' stiffness; a sparse LU where a pivot vanishes or A
// is not symmetric (LDLᵀ reads A's lower triangle only, so the residual tells).
Eigen::VectorXd solveSymmetric(Shape& w, const Eigen::VectorXd& b) {
  w.ldlt.factorize(w.a);
  if (w.ldlt.info() == Eigen::Success) {
    Eigen::VectorXd x = w.ldlt.solve(b);
    if (solves(w.a, x, b)) return x;
  }
  Eigen::SparseLU<Sparse> lu;
  lu.compute(w.a);
  if (lu.info() != Eigen::Success) {
    throw std::runtime_error("ImplicitSystem::solve: the matrix is singular (" +
                             lu.lastErrorMessage() + ")");
  }
  return lu.solve(b);
}

}  // namespace

struct ImplicitSystem::State {
  int n = 0;
  std::vector<implicit_solver::Block> blocks;
  Eigen::VectorXd b;
  std::vector<bool> fixed;
  implicit_solver::Shape shape;
};

ImplicitSystem::ImplicitSystem(int particles) : state_(std::make_unique<State>()) {
  reset(particles);
}

ImplicitSystem::~ImplicitSystem() = default;

ImplicitSystem::ImplicitSystem(const ImplicitSystem& other)
    : state_(std::make_unique<State>(*other.state_)) {}

ImplicitSystem& ImplicitSystem::operator=(const ImplicitSystem& other) {
  *state_ = *other.state_;
  return *this;
}

int ImplicitSystem::particles() const { return state_->n; }

void ImplicitSystem::reset(int particles) {
  if (particles < 0) throw std::invalid_argument("ImplicitSystem: a negative particle count");
  State& s = *state_;
  s.n = particles;
  s.blocks.clear();  // keeps its capacity for the next step's blocks
  s.b = Eigen::VectorXd::Zero(2 * particles);
  s.fixed.assign(particles, false);
}

void ImplicitSystem::addBlock(int i, int j, const Mat2& block) {
  checkIndex(i, state_->n, "addBlock");
  checkIndex(j, state_->n, "addBlock");
  state_->blocks.push_back({i, j, block});
}

void ImplicitSystem::addToB(int i, const Vec2& value) {
  checkIndex(i, state_->n, "addToB");
  state_->b.segment<2>(2 * i) += value;
}

void ImplicitSystem::fix(int i) {
  checkIndex(i, state_->n, "fix");
  state_->fixed[i] = true;
}

std::vector<Vec2> ImplicitSystem::solve() {
  State& s = *state_;
  if (!sameShape(s.shape, s.n, s.blocks, s.fixed)) reshape(s.shape, s.n, s.blocks, s.fixed);
  fill(s.shape, s.blocks);
  Eigen::VectorXd b = s.b;
  for (int i = 0; i < s.n; ++i) {
    if (s.fixed[i]) b.segment<2>(2 * i).setZero();
  }

  const Eigen::VectorXd dv = solveSymmetric(s.shape, b);
  if (!dv.allFinite()) throw std::runtime_error("ImplicitSystem::solve: the result is not finite");

  std::vector<Vec2> out(s.n);
  for (int i = 0; i < s.n; ++i) out[i] = dv.segment<2>(2 * i);
  return out;
}

}  // namespace a6
