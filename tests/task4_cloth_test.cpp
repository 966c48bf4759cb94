// Task 4 — buildCloth. Oracles: the index layout of a6/cloth.h (particle (i, j) at index
// j (n+1) + i, at origin + (i, -j) h), the closed-form spring counts, and the exact SET of index
// pairs of each spring type. Springs are compared as unordered pairs, so a builder passes
// whatever order it creates its springs in and whichever end it calls p1.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cloth_result.h"
#include "suite.h"

namespace a6::test {
namespace task4_cloth {

using Pair = std::pair<int, int>;  // particle indices, smaller first
using PairSet = std::set<Pair>;

Pair unordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

ClothSpec clothSpec(int n, bool shear = true, bool bending = true) {
  ClothSpec spec;
  spec.n = n;
  spec.size = 1.0;
  spec.origin = Vec2(0, 0);
  spec.shear = shear;
  spec.bending = bending;
  return spec;
}

std::string input(const ClothSpec& s) {
  auto flag = [](bool b) { return b ? "true" : "false"; };
  return "  input: ClothSpec{n=" + std::to_string(s.n) + ", size=" + num(s.size) +
         ", origin=" + str(s.origin) + ", particleMass=" + num(s.particleMass) +
         ", shear=" + flag(s.shear) + ", bending=" + flag(s.bending) +
         ", pinTopCorners=" + flag(s.pinTopCorners) + "} built into a system that already held " +
         std::to_string(harness::clothPrelude().particles.size()) + " particles";
}

const char* typeName(SpringType t) {
  switch (t) {
    case SpringType::Structural:
      return "structural";
    case SpringType::Shear:
      return "shear";
    case SpringType::Bending:
      return "bending";
    default:
      return "other";
  }
}

// "(i,j)" grid coordinates of a particle index, for messages.
std::string cell(int index, int n) {
  if (index < 0 || index >= (n + 1) * (n + 1)) return "[index " + std::to_string(index) + "]";
  return "(" + std::to_string(index % (n + 1)) + "," + std::to_string(index / (n + 1)) + ")";
}

std::string pairs(const std::vector<Pair>& list, int n) {
  std::ostringstream out;
  const std::size_t shown = std::min<std::size_t>(list.size(), 8);
  for (std::size_t k = 0; k < shown; ++k) {
    out << (k ? ", " : "") << cell(list[k].first, n) << "-" << cell(list[k].second, n);
  }
  if (list.size() > shown) out << ", ... (" << list.size() << " in all)";
  return list.empty() ? "none" : out.str();
}

// Failures reported so far in the running test: loops over particles and springs stop at the
// first one that fails, so that a student reads one clear message, not hundreds.
int failures() {
  return ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
}

std::size_t countOf(const harness::ClothResult& r, SpringType t) {
  return static_cast<std::size_t>(
      std::count_if(r.springs.begin(), r.springs.end(),
                    [t](const harness::SpringData& s) { return s.type == t; }));
}

PairSet pairsOf(const harness::ClothResult& r, SpringType t) {
  PairSet out;
  for (const harness::SpringData& s : r.springs) {
    if (s.type == t) out.insert(unordered(s.i, s.j));
  }
  return out;
}

// Whether a pair of particles (indices in an n x n cloth) may be a spring of type t: the
// handout's table read as a property of the pair, the offset between the two grid cells
// (structural: one step along a row or column; shear: one step along both; bending: two steps
// along one). Not a list of the springs to build: together with a count computed by hand and
// no spring twice, it fixes the set.
bool joinsAs(const Pair& pair, int n, SpringType t) {
  const int particles = (n + 1) * (n + 1);
  if (pair.first < 0 || pair.second >= particles) return false;  // outside the cloth
  const int di = std::abs(pair.first % (n + 1) - pair.second % (n + 1));
  const int dj = std::abs(pair.first / (n + 1) - pair.second / (n + 1));
  switch (t) {
    case SpringType::Structural:
      return di + dj == 1;
    case SpringType::Shear:
      return di == 1 && dj == 1;
    case SpringType::Bending:
      return (di == 2 && dj == 0) || (di == 0 && dj == 2);
    default:
      return false;
  }
}

// The cloth's part of what the student's buildCloth made in a system that already held a
// prelude (cloth_result.h), indices relative to base.
harness::ClothResult build(const ClothSpec& spec) {
  return clothPart(student().ask(harness::ClothRequest{spec}), spec.n);
}

// Stops the check when buildCloth failed; addSpring's exception (an index outside the system,
// a spring from a particle to itself) is a grid that reaches outside itself, said in words.
::testing::AssertionResult builtWithoutError(const harness::ClothResult& r, const ClothSpec& spec) {
  if (r.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << currentTask() << ": buildCloth failed: " << r.error << "\n  " << input(spec)
         << hint(
                "the grid has (n+1) x (n+1) particles, (i,j) at base + j*(n+1) + i with i and j "
                "from 0 to n: a spring to (i+1,j) exists only for i < n, to (i,j+1) only for "
                "j < n, and a diagonal only inside a cell; add every particle before the first "
                "spring");
}
#define A6_ASSERT_BUILT(r, spec) ASSERT_TRUE(builtWithoutError(r, spec))

// Checks the pairs of one type: each joins the right neighbours (joinsAs), and there are as many
// different ones as `count`, computed by hand. Names the pairs that are wrong, and how many
// are missing.
void expectTopology(const ClothSpec& spec, SpringType t, std::size_t count, const char* pattern) {
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  const PairSet actual = pairsOf(r, t);
  std::vector<Pair> extra;
  for (const Pair& pair : actual) {
    if (!joinsAs(pair, spec.n, t)) extra.push_back(pair);
  }
  const std::size_t right = actual.size() - extra.size();
  const std::size_t missing = count > right ? count - right : 0;
  EXPECT_TRUE(missing == 0 && extra.empty())
      << currentTask() << ": the " << typeName(t)
      << " springs do not connect the right particles\n  " << input(spec)
      << "\n  expected pairs: " << pattern << " (" << count << " pairs)\n  missing: " << missing
      << " of them\n  wrong:   " << pairs(extra, spec.n)
      << hint(std::string("particle (i,j) is at index j*(n+1) + i; ") + typeName(t) +
              " springs connect " + pattern + ", and none may reach outside the grid");
}

// The other checks read a builder that forgot base as it meant it: this one costs the mistake.
TEST(Task4Cloth, BuildsAfterWhatTheSystemAlreadyHolds) {
  for (int n : {1, 4}) {
    const ClothSpec spec = clothSpec(n);
    const harness::ClothResult r = student().ask(harness::ClothRequest{spec});
    A6_ASSERT_BUILT(r, spec);
    // A cloth was appended (a stub that adds nothing leaves the prelude intact too)...
    const std::size_t base = harness::clothPrelude().particles.size();
    ASSERT_EQ(r.particles.size(), base + static_cast<std::size_t>((n + 1) * (n + 1)))
        << currentTask() << ": particles in the system after buildCloth, " << input(spec)
        << hint("append the (n+1)² particles of the cloth after the ones the system holds");
    // ...and the prelude is as it was, the springs and pins relative to base.
    const std::string problem = preludeProblem(r);
    EXPECT_TRUE(problem.empty()) << currentTask() << ": " << problem << "\n  " << input(spec)
                                 << hint(preludeAdvice());
    if (!problem.empty()) break;
  }
}

TEST(Task4Cloth, ParticleCountIsNPlusOneSquared) {
  for (int n : {1, 2, 3, 7}) {
    const ClothSpec spec = clothSpec(n);
    const harness::ClothResult r = build(spec);
    A6_ASSERT_BUILT(r, spec);
    EXPECT_EQ(r.particles.size(), static_cast<std::size_t>((n + 1) * (n + 1)))
        << currentTask() << ": " << input(spec)
        << hint("an n x n cloth has (n+1) x (n+1) particles: loop i and j from 0 to n inclusive");
  }
}

TEST(Task4Cloth, ParticlesSitOnTheGridInIndexOrder) {
  const ClothSpec spec = clothSpec(3);
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  ASSERT_EQ(r.particles.size(), 16u)
      << currentTask() << ": " << input(spec) << hint("(n+1)² particles");
  const double h = 1.0 / 3;
  for (int j = 0, before = failures(); j <= 3 && failures() == before; ++j) {
    for (int i = 0; i <= 3 && failures() == before; ++i) {
      EXPECT_VEC_NEAR(r.particles[clothIndex(i, j, 3)].x, Vec2(i * h, -j * h),
                      relativeTo(spec.size))
          << "particle (i,j) = (" << i << "," << j << ") at index " << clothIndex(i, j, 3) << ", "
          << input(spec)
          << hint(
                 "particle (i,j) goes at index j*(n+1) + i (rows from the top, columns from the "
                 "left) and at origin + (i, -j) * size/n: y decreases downwards");
    }
  }
}

TEST(Task4Cloth, OriginAndSizeAreRespected) {
  ClothSpec spec = clothSpec(5);
  spec.origin = Vec2(-1.25, 2.5);
  spec.size = 3.0;  // h = 0.6
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  ASSERT_EQ(r.particles.size(), 36u)
      << currentTask() << ": " << input(spec) << hint("(n+1)² particles");
  for (int j = 0, before = failures(); j <= 5 && failures() == before; ++j) {
    for (int i = 0; i <= 5 && failures() == before; ++i) {
      EXPECT_VEC_NEAR(r.particles[clothIndex(i, j, 5)].x, Vec2(-1.25 + 0.6 * i, 2.5 - 0.6 * j),
                      relativeTo(spec.size + spec.origin.norm()))
          << "particle (i,j) = (" << i << "," << j << "), " << input(spec)
          << hint("position = spec.origin + (i, -j) * h with h = spec.size / spec.n");
    }
  }
}

TEST(Task4Cloth, EveryParticleHasTheSpecMassAndStartsAtRest) {
  ClothSpec spec = clothSpec(4);
  spec.particleMass = 0.037;
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  ASSERT_EQ(r.particles.size(), 25u)
      << currentTask() << ": " << input(spec) << hint("(n+1)² particles");
  for (int k = 0, before = failures(); k < 25 && failures() == before; ++k) {
    EXPECT_CLOSE(r.particles[k].m, 0.037, relativeTo(0.037))
        << "particle " << cell(k, 4) << ", " << input(spec)
        << hint("every particle gets m = spec.particleMass");
    EXPECT_VEC_NEAR(r.particles[k].v, Vec2(0, 0), relativeTo(spec.size, 0))
        << "particle " << cell(k, 4) << ", " << input(spec)
        << hint("the cloth starts at rest: v = 0");
  }
}

TEST(Task4Cloth, SpringCountsMatchTheFormulas) {
  for (int n : {1, 2, 3, 6}) {
    const ClothSpec spec = clothSpec(n, true, true);
    const harness::ClothResult r = build(spec);
    A6_ASSERT_BUILT(r, spec);
    const std::size_t N = static_cast<std::size_t>(n);
    EXPECT_EQ(countOf(r, SpringType::Structural), 2 * N * (N + 1))
        << currentTask() << ": structural springs, " << input(spec)
        << hint(
               "2n(n+1) structural springs: n per row and per column, n+1 rows and n+1 columns; "
               "the last row and column need their springs too");
    EXPECT_EQ(countOf(r, SpringType::Shear), 2 * N * N)
        << currentTask() << ": shear springs, " << input(spec)
        << hint("2 shear springs (both diagonals) in each of the n² cells");
    EXPECT_EQ(countOf(r, SpringType::Bending), 2 * (N - 1) * (N + 1))
        << currentTask() << ": bending springs, " << input(spec)
        << hint("2(n-1)(n+1) bending springs: (i,j)-(i+2,j) needs i+2 <= n; an n=1 cloth has none");
    EXPECT_EQ(countOf(r, SpringType::Other), 0u)
        << currentTask() << ": springs tagged SpringType::Other, " << input(spec)
        << hint("tag every spring with its type (Structural, Shear or Bending) in addSpring");
  }
}

TEST(Task4Cloth, ShearAndBendingFlagsAddOrOmitTheirSprings) {
  const int n = 4;
  for (bool shear : {false, true}) {
    for (bool bending : {false, true}) {
      const ClothSpec spec = clothSpec(n, shear, bending);
      const harness::ClothResult r = build(spec);
      A6_ASSERT_BUILT(r, spec);
      EXPECT_EQ(countOf(r, SpringType::Structural), 40u)
          << currentTask() << ": structural springs, " << input(spec)
          << hint("structural springs (2n(n+1)) are always there, whatever the flags");
      EXPECT_EQ(countOf(r, SpringType::Shear), shear ? 32u : 0u)
          << currentTask() << ": shear springs, " << input(spec)
          << hint("add the 2n² shear springs only when spec.shear is true");
      EXPECT_EQ(countOf(r, SpringType::Bending), bending ? 30u : 0u)
          << currentTask() << ": bending springs, " << input(spec)
          << hint("add the 2(n-1)(n+1) bending springs only when spec.bending is true");
    }
  }
}

TEST(Task4Cloth, SpringsJoinTwoDifferentParticlesOfTheCloth) {
  for (int n : {1, 2, 5}) {
    const ClothSpec spec = clothSpec(n);
    const harness::ClothResult r = build(spec);
    A6_ASSERT_BUILT(r, spec);
    ASSERT_FALSE(r.springs.empty()) << currentTask() << ": no springs at all, " << input(spec)
                                    << hint("add the springs with system.addSpring");
    const int count = static_cast<int>(r.particles.size());
    const int before = failures();
    for (const harness::SpringData& s : r.springs) {
      if (failures() > before) break;
      EXPECT_TRUE(s.i >= 0 && s.j >= 0 && s.i < count && s.j < count)
          << currentTask() << ": a " << typeName(s.type) << " spring between indices " << s.i
          << " and " << s.j << " (-1: a particle outside the system), " << count << " particles, "
          << input(spec)
          << hint("springs must join particles of the system: use system.addSpring(a, b, ...)");
      EXPECT_NE(s.i, s.j) << currentTask() << ": a " << typeName(s.type) << " spring from particle "
                          << cell(s.i, n) << " to itself, " << input(spec)
                          << hint("a spring needs two different particles");
    }
  }
}

TEST(Task4Cloth, NoSpringAppearsTwice) {
  for (int n : {1, 2, 4}) {
    const ClothSpec spec = clothSpec(n);
    const harness::ClothResult r = build(spec);
    A6_ASSERT_BUILT(r, spec);
    std::set<Pair> seen;
    std::vector<Pair> twice;
    for (const harness::SpringData& s : r.springs) {
      if (!seen.insert(unordered(s.i, s.j)).second) twice.push_back(unordered(s.i, s.j));
    }
    EXPECT_TRUE(twice.empty())
        << currentTask()
        << ": springs that appear more than once (in either direction): " << pairs(twice, n)
        << "\n  " << input(spec)
        << hint(
               "add each spring once: (a,b) and (b,a) are the same spring; connect each particle "
               "to its right and lower neighbours only, not to all four");
  }
}

// The counts by hand: structural 2n(n+1), shear 2n², bending 2(n-1)(n+1).
TEST(Task4Cloth, StructuralSpringsJoinGridNeighbours) {
  for (const auto& [n, count] : {std::pair<int, std::size_t>{1, 4}, {2, 12}, {5, 60}}) {
    expectTopology(clothSpec(n, false, false), SpringType::Structural, count,
                   "(i,j)-(i+1,j) and (i,j)-(i,j+1)");
    expectTopology(clothSpec(n, true, true), SpringType::Structural, count,
                   "(i,j)-(i+1,j) and (i,j)-(i,j+1)");
  }
}

TEST(Task4Cloth, ShearSpringsJoinBothDiagonalsOfEveryCell) {
  for (const auto& [n, count] : {std::pair<int, std::size_t>{1, 2}, {2, 8}, {5, 50}}) {
    expectTopology(clothSpec(n, true, true), SpringType::Shear, count,
                   "(i,j)-(i+1,j+1) and (i+1,j)-(i,j+1)");
  }
}

TEST(Task4Cloth, BendingSpringsSkipOneParticle) {
  for (const auto& [n, count] : {std::pair<int, std::size_t>{1, 0}, {2, 6}, {3, 16}, {5, 48}}) {
    expectTopology(clothSpec(n, true, true), SpringType::Bending, count,
                   "(i,j)-(i+2,j) and (i,j)-(i,j+2)");
  }
}

TEST(Task4Cloth, RestLengthsAndConstantsFollowTheType) {
  ClothSpec spec = clothSpec(5);
  spec.size = 3.0;  // h = 0.6
  spec.ksStructural = 310, spec.kdStructural = 0.31;
  spec.ksShear = 47, spec.kdShear = 0.047;
  spec.ksBending = 13, spec.kdBending = 0.013;
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  ASSERT_FALSE(r.springs.empty()) << currentTask() << ": no springs at all, " << input(spec)
                                  << hint("add the springs with system.addSpring");
  const double h = 0.6;
  const int before = failures();
  for (const harness::SpringData& s : r.springs) {
    if (failures() > before) break;
    double l0 = 0, ks = 0, kd = 0;
    const char* which = "";
    switch (s.type) {
      case SpringType::Structural:
        l0 = h, ks = 310, kd = 0.31, which = "h, ksStructural, kdStructural";
        break;
      case SpringType::Shear:
        l0 = std::sqrt(2.0) * h, ks = 47, kd = 0.047, which = "sqrt(2) h, ksShear, kdShear";
        break;
      case SpringType::Bending:
        l0 = 2 * h, ks = 13, kd = 0.013, which = "2 h, ksBending, kdBending";
        break;
      default:
        ADD_FAILURE() << currentTask() << ": a spring tagged Other, " << input(spec)
                      << hint("tag each spring with its SpringType");
        continue;
    }
    const std::string where = std::string("a ") + typeName(s.type) + " spring " + cell(s.i, 5) +
                              "-" + cell(s.j, 5) + ", h = 0.6, " + input(spec);
    EXPECT_CLOSE(s.restLength, l0, relativeTo(spec.size))
        << where
        << hint(std::string("a ") + typeName(s.type) +
                " spring has rest length, ks, kd = " + which);
    EXPECT_CLOSE(s.ks, ks, relativeTo(ks)) << where
                                           << hint(std::string("a ") + typeName(s.type) +
                                                   " spring has rest length, ks, kd = " + which);
    EXPECT_CLOSE(s.kd, kd, relativeTo(kd)) << where
                                           << hint(std::string("a ") + typeName(s.type) +
                                                   " spring has rest length, ks, kd = " + which);
  }
}

TEST(Task4Cloth, EverySpringStartsAtItsRestLength) {
  ClothSpec spec = clothSpec(4);
  spec.origin = Vec2(0.3, -0.7);
  spec.size = 2.0;
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  ASSERT_FALSE(r.springs.empty()) << currentTask() << ": no springs at all, " << input(spec)
                                  << hint("add the springs with system.addSpring");
  const int count = static_cast<int>(r.particles.size());
  const int before = failures();
  for (const harness::SpringData& s : r.springs) {
    if (failures() > before) break;
    ASSERT_TRUE(s.i >= 0 && s.j >= 0 && s.i < count && s.j < count)
        << currentTask() << ": a spring between indices " << s.i << " and " << s.j << ", " << count
        << " particles" << hint("springs must join particles of the system");
    const double distance = (r.particles[s.j].x - r.particles[s.i].x).norm();
    EXPECT_CLOSE(s.restLength, distance, relativeTo(spec.size + spec.origin.norm()))
        << "a " << typeName(s.type) << " spring " << cell(s.i, 4) << "-" << cell(s.j, 4)
        << ": its rest length vs the distance between its particles, " << input(spec)
        << hint(
               "the cloth must start relaxed: a spring's rest length is the distance between the "
               "grid points it joins (h, sqrt(2) h or 2 h)");
  }
}

TEST(Task4Cloth, OnlyTheTopCornersArePinned) {
  for (int n : {1, 2, 5}) {
    const ClothSpec spec = clothSpec(n);
    const harness::ClothResult r = build(spec);
    A6_ASSERT_BUILT(r, spec);
    ASSERT_EQ(r.particles.size(), static_cast<std::size_t>((n + 1) * (n + 1)))
        << currentTask() << ": " << input(spec) << hint("(n+1)² particles");
    const int before = failures();
    for (int k = 0; k < static_cast<int>(r.particles.size()) && failures() == before; ++k) {
      const bool corner = k == clothIndex(0, 0, n) || k == clothIndex(n, 0, n);
      EXPECT_EQ(r.particles[k].pinned, corner)
          << currentTask() << ": particle " << cell(k, n)
          << (corner ? " should be pinned" : " should not be pinned") << ", " << input(spec)
          << hint(
                 "pin exactly the top corners (0,0) and (n,0), at indices 0 and n; row j = 0 is "
                 "the top");
    }
  }
}

TEST(Task4Cloth, NothingIsPinnedWhenPinTopCornersIsFalse) {
  ClothSpec spec = clothSpec(3);
  spec.pinTopCorners = false;
  const harness::ClothResult r = build(spec);
  A6_ASSERT_BUILT(r, spec);
  ASSERT_EQ(r.particles.size(), 16u)
      << currentTask() << ": " << input(spec) << hint("(n+1)² particles");
  for (int k = 0, before = failures(); k < 16 && failures() == before; ++k) {
    EXPECT_FALSE(r.particles[k].pinned)
        << currentTask() << ": particle " << cell(k, 3) << " is pinned, " << input(spec)
        << hint("pin the corners only when spec.pinTopCorners is true");
  }
}

}  // namespace task4_cloth
}  // namespace a6::test
