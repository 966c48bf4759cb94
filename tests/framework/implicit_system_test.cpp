// The framework's half of task 7: ImplicitSystem assembles A Δv = b from 2x2 blocks and solves it.
// Its answers are checked against a dense solve of the same A and b, built here entry by entry,
// for a positive definite A, an indefinite one (a compressed spring), fixed particles, a
// non-symmetric A, and a shape kept from one solve to the next or changed between them (each
// system keeps its own: two systems never share anything).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <stdexcept>
#include <vector>

#include "a6/implicit.h"

namespace {

using a6::ImplicitSystem;
using a6::Mat2;
using a6::Vec2;

// A system and the same A and b, dense.
struct Both {
  explicit Both(int n)
      : system(n), a(Eigen::MatrixXd::Zero(2 * n, 2 * n)), b(Eigen::VectorXd::Zero(2 * n)) {}
  void addBlock(int i, int j, const Mat2& block) {
    system.addBlock(i, j, block);
    a.block<2, 2>(2 * i, 2 * j) += block;
  }
  void addToB(int i, const Vec2& value) {
    system.addToB(i, value);
    b.segment<2>(2 * i) += value;
  }
  // The dense system's rows and columns of i replaced by the identity's, b zero there.
  void fix(int i) {
    system.fix(i);
    fixes.push_back(i);
    a.middleRows<2>(2 * i).setZero();
    a.middleCols<2>(2 * i).setZero();
    a.block<2, 2>(2 * i, 2 * i).setIdentity();
    b.segment<2>(2 * i).setZero();
  }
  ImplicitSystem system;
  std::vector<int> fixes;
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
};

// A chain of n particles of mass `mass` joined by springs with the block K = `scale` (e eᵀ +
// `transverse` (I - e eᵀ)) in random directions, assembled as stepImplicit does; random b.
Both chain(int n, double mass, double scale, double transverse, unsigned seed, bool withB = true) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Both both(n);
  for (int i = 0; i < n; ++i) {
    both.addBlock(i, i, mass * Mat2::Identity());
    const Vec2 b(uniform(random), uniform(random));
    if (withB) both.addToB(i, b);
  }
  for (int i = 0; i + 1 < n; ++i) {
    const Vec2 e = Vec2(uniform(random), uniform(random)).normalized();
    const Mat2 outer = e * e.transpose();
    const Mat2 k = scale * (outer + transverse * (Mat2::Identity() - outer));
    both.addBlock(i, i, k), both.addBlock(i + 1, i + 1, k);
    both.addBlock(i, i + 1, -k), both.addBlock(i + 1, i, -k);
  }
  return both;
}

Eigen::VectorXd flat(const std::vector<Vec2>& dv) {
  Eigen::VectorXd out(2 * static_cast<int>(dv.size()));
  for (std::size_t i = 0; i < dv.size(); ++i) out.segment<2>(2 * static_cast<int>(i)) = dv[i];
  return out;
}

void expectSolves(const Both& both, const std::vector<Vec2>& dv) {
  const Eigen::VectorXd expected = both.a.fullPivLu().solve(both.b);
  const Eigen::VectorXd got = flat(dv);
  EXPECT_LE((got - expected).norm(), 1e-9 * expected.norm()) << "got\n"
                                                             << got.transpose() << "\nexpected\n"
                                                             << expected.transpose();
}

TEST(ImplicitSystem, SolvesAPositiveDefiniteSystem) {
  Both both = chain(12, 0.01, 50, 0.3, 1);
  expectSolves(both, both.system.solve());
}

TEST(ImplicitSystem, SolvesAnIndefiniteSystem) {
  // Transverse stiffness -3 (1 - l0/l < 0, compressed, and far stiffer than the masses): A has
  // negative eigenvalues.
  Both both = chain(12, 0.01, 50, -3, 2);
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(both.a).eigenvalues().minCoeff(), 0);
  expectSolves(both, both.system.solve());
}

TEST(ImplicitSystem, AFixedParticleKeepsItsVelocityAndIsLeftOutOfTheOthers) {
  Both both = chain(8, 0.01, 50, 0.3, 3);
  both.fix(0);
  both.fix(5);
  const std::vector<Vec2> dv = both.system.solve();
  EXPECT_EQ(dv[0], Vec2::Zero());
  EXPECT_EQ(dv[5], Vec2::Zero());
  expectSolves(both, dv);
}

TEST(ImplicitSystem, SolvesANonSymmetricSystem) {
  Both both = chain(6, 0.01, 50, 0.3, 4);
  Mat2 skew;
  skew << 0, 0.2, -0.1, 0;
  both.addBlock(2, 3, skew);  // without its transpose at (3, 2)
  expectSolves(both, both.system.solve());
}

// `system` emptied, then given both's A (its nonzero blocks, column by column) and fixes.
void refill(ImplicitSystem& system, const Both& both) {
  const int n = static_cast<int>(both.b.size()) / 2;
  system.reset(n);
  for (int col = 0; col < n; ++col) {
    for (int row = 0; row < n; ++row) {
      const Mat2 block = both.a.block<2, 2>(2 * row, 2 * col);
      if (!block.isZero()) system.addBlock(row, col, block);
    }
  }
  for (int row = 0; row < n; ++row) system.addToB(row, both.b.segment<2>(2 * row));
  for (const int fixed : both.fixes) system.fix(fixed);
}

Eigen::VectorXd freshAnswer(const Both& both) {
  ImplicitSystem fresh;
  refill(fresh, both);
  return flat(fresh.solve());
}

TEST(ImplicitSystem, ShapesKeptOrChangedBetweenSolvesGiveTheSameAnswers) {
  Both first = chain(10, 0.01, 50, 0.3, 5);
  const Eigen::VectorXd cold = flat(first.system.solve());
  expectSolves(first, first.system.solve());
  EXPECT_EQ(flat(first.system.solve()), cold) << "the same system, solved twice";

  Both sameShape = chain(10, 0.02, 900, -0.01, 6);  // the same blocks, other values
  Both longer = chain(11, 0.01, 50, 0.3, 7);
  Both fewer = chain(10, 0.01, 50, 0.3, 5);
  fewer.fix(9);
  // One system emptied and filled again for each (as implicitSystem() is at every step): the
  // shape kept, changed, and back again, each answer the same as a fresh system's, bit for bit.
  ImplicitSystem kept;
  for (const Both* both : {&first, &sameShape, &longer, &fewer, &sameShape, &first}) {
    refill(kept, *both);
    const std::vector<Vec2> dv = kept.solve();
    expectSolves(*both, dv);
    EXPECT_EQ(flat(dv), freshAnswer(*both)) << "a kept shape changed the answer";
  }
  // A copy has the same content and answers the same; the original is unchanged by it.
  ImplicitSystem copy = kept;
  EXPECT_EQ(flat(copy.solve()), flat(kept.solve()));
  EXPECT_EQ(copy.particles(), 10);
}

TEST(ImplicitSystem, TwoSystemsSolvedInTurnKeepTheirOwnShapes) {
  Both small = chain(5, 0.01, 50, 0.3, 11);
  Both large = chain(40, 0.01, 50, 0.3, 12);
  const Eigen::VectorXd smallAlone = flat(small.system.solve());
  const Eigen::VectorXd largeAlone = flat(large.system.solve());
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(flat(small.system.solve()), smallAlone);
    EXPECT_EQ(flat(large.system.solve()), largeAlone);
  }
}

TEST(ImplicitSystem, AResetSystemIsEmpty) {
  Both both = chain(6, 0.01, 50, 0.3, 13);
  both.system.solve();
  both.system.reset(3);
  EXPECT_EQ(both.system.particles(), 3);
  // No blocks are left: A is singular until new ones come.
  EXPECT_THROW(both.system.solve(), std::runtime_error);
  for (int i = 0; i < 3; ++i) both.system.addBlock(i, i, 2 * Mat2::Identity());
  for (const Vec2& dv : both.system.solve()) EXPECT_EQ(dv, Vec2::Zero()) << "b was emptied";
  EXPECT_THROW(both.system.addBlock(3, 3, Mat2::Identity()), std::out_of_range);
  EXPECT_THROW(both.system.reset(-1), std::invalid_argument);
}

TEST(ImplicitSystem, NoParticlesAndAZeroRightHandSide) {
  EXPECT_TRUE(ImplicitSystem(0).solve().empty());
  Both still = chain(7, 0.01, 50, 0.3, 9, /*withB=*/false);
  for (const Vec2& dv : still.system.solve()) EXPECT_EQ(dv, Vec2::Zero());
}

TEST(ImplicitSystem, BlocksAddedInAnotherOrderGiveTheSameAnswer) {
  Both both = chain(9, 0.01, 50, 0.3, 8);
  ImplicitSystem reversed(9);
  Both copy = chain(9, 0.01, 50, 0.3, 8);
  // The same A, its blocks added column by column from the last, then b.
  for (int j = 8; j >= 0; --j) {
    for (int i = 0; i < 9; ++i) {
      if (!copy.a.block<2, 2>(2 * i, 2 * j).isZero())
        reversed.addBlock(i, j, copy.a.block<2, 2>(2 * i, 2 * j));
    }
  }
  for (int i = 0; i < 9; ++i) reversed.addToB(i, copy.b.segment<2>(2 * i));
  expectSolves(both, reversed.solve());
}

TEST(ImplicitSystem, ASingularSystemThrows) {
  ImplicitSystem system(3);
  system.addBlock(0, 0, Mat2::Identity());
  system.addToB(1, Vec2(1, 0));  // particles 1 and 2 have no block at all
  EXPECT_THROW(system.solve(), std::runtime_error);
}

TEST(ImplicitSystem, IndicesOutsideTheSystemThrow) {
  ImplicitSystem system(3);
  EXPECT_THROW(system.addBlock(0, 3, Mat2::Identity()), std::out_of_range);
  EXPECT_THROW(system.addBlock(-1, 0, Mat2::Identity()), std::out_of_range);
  EXPECT_THROW(system.addToB(3, Vec2::Zero()), std::out_of_range);
  EXPECT_THROW(system.fix(-1), std::out_of_range);
  EXPECT_THROW(ImplicitSystem(-1), std::invalid_argument);
}

}  // namespace
