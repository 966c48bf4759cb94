// The words of the checks' messages (suite.h, quantities.h): numbers for people, quantities named
// in words with their units, never by the checks' own code.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>

#include "quantities.h"
#include "suite.h"

namespace a6::test {
namespace {

TEST(Numbers, SevenDigitsAtMostAndNoBinaryNoise) {
  EXPECT_EQ(num(-5.199999999999999), "-5.2");
  EXPECT_EQ(num(0.00035000000000000005), "0.00035");
  EXPECT_EQ(num(9.5811388300841898e-05), "9.581139e-5");
  EXPECT_EQ(num(1e30), "1e30");
  EXPECT_EQ(num(-0.0), "0");
  EXPECT_EQ(num(12.6), "12.6");
  EXPECT_EQ(num(1.0 / 64), "0.015625");
  EXPECT_EQ(num(NAN), "nan");
  EXPECT_EQ(str(Vec2(-0.0, 2.5)), "(0, 2.5)");
}

TEST(Quantities, NamedInWordsWithTheirUnits) {
  EXPECT_EQ(quantityOf("forceOf(r)").words, "the force on p2");
  EXPECT_EQ(quantityOf("forceOf(r)").unit, "N");
  EXPECT_EQ(quantityOf("result.particles[0].v").words, "particle 0's velocity");
  EXPECT_EQ(quantityOf("result.particles[0].v").unit, "m/s");
  EXPECT_EQ(quantityOf("s[1].x").words, "particle 1's position");
  EXPECT_EQ(quantityOf("forcesOf(r).buoyancy").words, "the buoyancy force");
  EXPECT_EQ(quantityOf("j.anchorB").unit, "m");
  EXPECT_EQ(quantityOf("p.temperature").unit, "K");
}

TEST(Quantities, AnExpressionNotInTheTableIsNeverShown) {
  const Quantity q = quantityOf("quadrant[q] / n");
  EXPECT_EQ(q.words, "the value checked");
  EXPECT_EQ(q.unit, "");
}

TEST(Messages, AFailureNamesTheQuantityWithItsUnitNotTheCode) {
  const Vec2 actual(10, 0);
  const ::testing::AssertionResult r =
      vecNear("forceOf(r)", "e", "t", actual, Vec2(-10, 0), Tolerance{20, 1e-5, true});
  ASSERT_FALSE(r);
  const std::string text = r.message();
  EXPECT_NE(text.find("the force on p2"), std::string::npos) << text;
  EXPECT_NE(text.find("expected: (-10, 0) N"), std::string::npos) << text;
  EXPECT_NE(text.find("actual:   (10, 0) N"), std::string::npos) << text;
  EXPECT_EQ(text.find("forceOf"), std::string::npos) << text;
}

// The messages GoogleTest gives the failures of `assertions`, as a student reads them.
template <class Assertions>
std::vector<std::string> readAs(Assertions assertions) {
  ::testing::TestPartResultArray parts;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &parts);
    assertions();
  }
  std::vector<std::string> messages;
  for (int k = 0; k < parts.size(); ++k) messages.push_back(messageOf(parts.GetTestPartResult(k)));
  return messages;
}

::testing::AssertionResult refused() {
  return ::testing::AssertionFailure() << "Task 3 (time_stepping.cpp): expected 2 states (a)";
}

TEST(Messages, GoogleTestsOwnWordsAreLeftOut) {
  const harness::SpringForceResult timedOut = [] {
    harness::SpringForceResult r;
    r.fail(harness::Fault::TimedOut, "your code took longer than 2 s");
    return r;
  }();
  const int* none = nullptr;
  const std::vector<std::string> read = readAs([&] {
    EXPECT_TRUE(timedOut.ok()) << "the words after";
    EXPECT_TRUE(refused());
    EXPECT_NE(none, nullptr) << "the scene failed";
    ADD_FAILURE() << "added";
    A6_EXPECT_RAN(timedOut);
    EXPECT_LT(3.5, 2.25) << "the stretch";
    EXPECT_TRUE(timedOut.ok());
  });
  ASSERT_EQ(read.size(), 7u);
  EXPECT_EQ(read[0], "the words after");
  EXPECT_EQ(read[1], "Task 3 (time_stepping.cpp): expected 2 states (a)");
  EXPECT_EQ(read[2], "the scene failed");
  EXPECT_EQ(read[3], "added");
  EXPECT_EQ(read[4], "Task ?: your code failed: your code took longer than 2 s");
  // A comparison keeps its numbers; a bare one, with no words of its own, keeps GoogleTest's.
  EXPECT_EQ(read[5].rfind("Expected: (3.5) < (2.25), actual: 3.5 vs 2.25\nthe stretch", 0), 0u)
      << read[5];
  EXPECT_NE(read[6].find("timedOut.ok()"), std::string::npos) << read[6];
}

TEST(Messages, AFailedRunStopsTheCheckEvenInAnUnbracedIf) {
  harness::SpringForceResult crashed;
  crashed.fail(harness::Fault::Crashed, "your code crashed");
  bool after = false, elseRan = false;
  auto check = [&] {
    if (true)
      A6_ASSERT_RAN(crashed);
    else
      elseRan = true;  // binds to the outer if: never runs
    after = true;      // FAIL() returned before this
  };
  const std::vector<std::string> read = readAs(check);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0], "Task ?: your code failed: your code crashed");
  EXPECT_FALSE(after);
  EXPECT_FALSE(elseRan);
}

TEST(Messages, AHintIsLeftOutOfACheckWhoseCodeGaveNoAnswer) {
  EXPECT_EQ(hint("check the sign"), "\n  hint: check the sign");
  noteCodeFailed();
  EXPECT_TRUE(codeFailedInThisCheck());
  EXPECT_EQ(hint("check the sign"), "");
}

TEST(Messages, NoValueIsComparedAfterTheCodeGaveNoAnswer) {
  noteCodeFailed();
  const ::testing::AssertionResult r =
      vecNear("forceOf(r)", "e", "t", Vec2(0, 0), Vec2(-10, 0), Tolerance{20, 1e-5, true});
  ASSERT_FALSE(r);
  EXPECT_EQ(std::string(r.message()),
            "Task ?: the force on p2: not compared (your code gave no answer: see above)");
  EXPECT_FALSE(scalarNear("x", "e", "t", 1, 1, Tolerance{1, 1e-5, true}))
      << "even an equal default is not the student's answer";
}

TEST(Messages, TheNextCheckHasItsHintsAgain) {
  EXPECT_FALSE(codeFailedInThisCheck());
  EXPECT_EQ(hint("check the sign"), "\n  hint: check the sign");
}

}  // namespace
}  // namespace a6::test
