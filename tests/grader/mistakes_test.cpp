// The mistakes stage (grader/mistakes/): the rule that names a mistake, and the library against
// the wrong versions it is written from. End to end (a6_grade names each wrong version's
// mistake, and none for the solution, the alternatives and another seed): scores_test.cpp.
#include "mistakes/mistakes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using a6::Vec2;
using a6::grader::Likeness;
using a6::grader::mistakeLibrary;
using a6::grader::MistakeModel;
using a6::grader::nameMistakes;
using a6::grader::Transcript;
using a6::harness::JacobiansRequest;
using a6::harness::JacobiansResult;
using a6::harness::SpringForceRequest;
using a6::harness::SpringForceResult;

const fs::path kWrong = fs::path(A6_SOURCE_DIR) / "tests" / "wrong";

std::string expectOf(const std::string& id) {
  std::ifstream in(kWrong / id / "EXPECT");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// One exchange of a spring force, to add to a transcript.
struct SpringExchange {
  std::string check;
  SpringForceRequest request;
  SpringForceResult result;
};
void add(Transcript& t, const SpringExchange& x) { t.add(x.check, x.request, x.result); }

// A spring stretched to 1.5 m (rest 1 m, ks 10 N/m), its ends moving apart sideways and along it.
SpringExchange stretched(Vec2 answer) {
  SpringForceRequest r;
  r.p1.x = Vec2(0, 0), r.p2.x = Vec2(1.5, 0);
  r.p1.v = Vec2(0.5, 0.25), r.p2.v = Vec2(1, -0.5);
  r.restLength = 1, r.ks = 10, r.kd = 2;
  SpringForceResult result;
  result.force = answer;
  return {"Task1Spring.Stretched", r, result};
}

std::set<std::string> named(const Transcript& t, std::set<int> failing) {
  std::set<std::string> ids;
  for (const auto& m : nameMistakes(t, mistakeLibrary(), failing)) ids.insert(m.id);
  return ids;
}

TEST(MistakeLibrary, EveryModelIsAWrongVersionOfItsTask) {
  ASSERT_FALSE(mistakeLibrary().empty());
  std::set<std::string> ids;
  for (const MistakeModel& m : mistakeLibrary()) {
    EXPECT_TRUE(ids.insert(m.id).second) << m.id << " is in the library twice";
    EXPECT_EQ(m.text.rfind("Your ", 0), 0u) << m.id << ": the sentence speaks to the student";
    EXPECT_LT(m.text.size(), 400u) << m.id << ": one sentence";
    if (m.partByPart) continue;  // a combination of parts: a wrong version where one was written
    const std::string expect = expectOf(m.id);
    EXPECT_NE(expect.find("fail: " + std::to_string(m.task)), std::string::npos)
        << "tests/wrong/" << m.id << "/EXPECT must say 'fail: " << m.task << "'";
    EXPECT_NE(expect.find("mistake: " + m.id), std::string::npos)
        << "tests/wrong/" << m.id << "/EXPECT must say 'mistake: " << m.id << "'";
  }
}

TEST(MistakeLibrary, EveryWrongVersionThatNamesAMistakeHasItsModel) {
  std::set<std::string> ids;
  for (const MistakeModel& m : mistakeLibrary()) ids.insert(m.id);
  for (const auto& dir : fs::directory_iterator(kWrong)) {
    const std::string expect = expectOf(dir.path().filename().string());
    const auto at = expect.find("mistake: ");
    if (at == std::string::npos) continue;
    std::istringstream id(expect.substr(at + 9));
    std::string word;
    id >> word;
    EXPECT_TRUE(ids.count(word)) << dir.path() << " names " << word << ", which has no model";
  }
}

TEST(NameMistakes, TheWrongSignIsNamed) {
  // f2 = -ks (l - l0) e - kd ((v2 - v1)·e) e = -5 - 2 (0.5) = -6 along x; the wrong sign: +5 - 1.
  Transcript t;
  add(t, stretched(Vec2(4, 0)));
  EXPECT_EQ(named(t, {1}), std::set<std::string>{"t1_wrong_sign"});
  EXPECT_EQ(named(t, {2, 3}), std::set<std::string>{}) << "only a failing task's mistakes";
}

TEST(NameMistakes, TheReferenceIsNeverNamed) {
  Transcript t;
  add(t, stretched(Vec2(-6, 0)));
  EXPECT_EQ(named(t, {1, 2, 3, 4, 5, 6}), std::set<std::string>{});
  // Within float rounding of the reference: still nothing.
  add(t, stretched(Vec2(-6 * (1 + 1e-7), 1e-9)));
  EXPECT_EQ(named(t, {1}), std::set<std::string>{});
}

TEST(NameMistakes, AnAnswerLikeTheReferenceSomewhereVetoesTheMistake) {
  // The full relative velocity damps the sideways motion too: (-6, 1.5). Once like it, once like
  // the reference: not named.
  Transcript t;
  add(t, stretched(Vec2(-6, 1.5)));
  EXPECT_EQ(named(t, {1}), std::set<std::string>{"t1_damping_full_relative_velocity"});
  add(t, stretched(Vec2(-6, 0)));
  EXPECT_EQ(named(t, {1}), std::set<std::string>{});
}

// The same spring with p1 still and p2 moving along it at 1 m/s: u·e = 1, so each damping form
// differs from the others.
SpringExchange moving(Vec2 answer) {
  SpringExchange x = stretched(answer);
  x.request.p1.v = Vec2(0, 0), x.request.p2.v = Vec2(1, 0);
  return x;
}

TEST(NameMistakes, TheWrongPartIsNamedWhenTheAnswersSingleItOut) {
  // Damping with the wrong sign: -5 + 2 (0.5) = -4 on the first spring, -5 + 2 = -3 on the second.
  Transcript t;
  add(t, stretched(Vec2(-4, 0)));
  add(t, moving(Vec2(-3, 0)));
  const auto found = nameMistakes(t, mistakeLibrary(), {1});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].id, "t1_damping_sign");
  EXPECT_NE(found[0].text.find("damping term has the wrong sign"), std::string::npos)
      << found[0].text;
  EXPECT_NE(found[0].text.find("its elastic term is right"), std::string::npos) << found[0].text;
}

TEST(NameMistakes, AnswersThatFitTwoExplanationsNameNothing) {
  // Ends at rest: every damping form is zero, so +ks (l - l0) e fits the wrong elastic sign with
  // any of them. Nothing singles one out: nothing is named.
  SpringExchange x = stretched(Vec2(5, 0));
  x.request.p1.v = x.request.p2.v = Vec2(0, 0);
  Transcript t;
  add(t, x);
  EXPECT_EQ(named(t, {1}), std::set<std::string>{});
  // An answer no form of the parts gives: nothing either.
  add(t, stretched(Vec2(123, 4)));
  EXPECT_EQ(named(t, {1}), std::set<std::string>{});
}

TEST(NameMistakes, AMistakeTheModelDoesNotHaveNamesNothing) {
  // Damping with the wrong sign, as above; then the spring with its ends at rest, where that
  // model answers as the reference (-5), answered -7: some other mistake is there, and the
  // sentence would say "its elastic term is right". Nothing is named.
  Transcript t;
  add(t, stretched(Vec2(-4, 0)));
  add(t, moving(Vec2(-3, 0)));
  EXPECT_EQ(named(t, {1}), std::set<std::string>{"t1_damping_sign"});
  SpringExchange still = stretched(Vec2(-7, 0));
  still.request.p1.v = still.request.p2.v = Vec2(0, 0);
  add(t, still);
  EXPECT_EQ(named(t, {1}), std::set<std::string>{});
}

TEST(NameMistakes, AJacobianBlockIsNamedByItsPart) {
  // The spring along x, stretched to 1.5 m (l0 1, ks 10, kd 2): dfdx = -10 diag(1, 1/3), dfdv =
  // -2 diag(1, 0). dfdv with the outer product left out: -2 I; dfdx right.
  const SpringForceRequest r = stretched(Vec2(0, 0)).request;
  JacobiansResult j;
  j.dfdx << -10, 0, 0, -10.0 / 3;
  j.dfdv << -2, 0, 0, -2;
  Transcript t;
  t.add("Task7Jacobians.Stretched", JacobiansRequest{r}, j);
  EXPECT_EQ(named(t, {7}), std::set<std::string>{"t7_dfdv_no_outer_product"});
  EXPECT_EQ(named(t, {1}), std::set<std::string>{}) << "a Jacobian request tells task 1 nothing";
}

TEST(NameMistakes, AStubIsNamedNothing) {
  // Zero Jacobians for a spring at its rest length with kd = 0 are what dfdx_isotropic with dfdv
  // missing gives there: a stub's zeros never name a mistake.
  SpringForceRequest r = stretched(Vec2(0, 0)).request;
  r.p2.x = Vec2(1, 0);
  r.kd = 0;
  Transcript t;
  t.add("Task7Jacobians.AtRest", JacobiansRequest{r}, JacobiansResult{});
  EXPECT_EQ(named(t, {7}), std::set<std::string>{});
  add(t, stretched(Vec2(0, 0)));  // the force of a stub computeForce
  EXPECT_EQ(named(t, {1, 7}), std::set<std::string>{});
}

TEST(NameMistakes, NaNIsLikeTheMissingGuard) {
  SpringExchange x = stretched(Vec2(NAN, NAN));
  x.request.p2.x = x.request.p1.x;
  Transcript t;
  add(t, x);
  EXPECT_EQ(named(t, {1}), std::set<std::string>{"t1_nan_for_coincident_particles"});
}

}  // namespace
