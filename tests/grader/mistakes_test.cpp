// The mistakes stage (grader/mistakes/): the rule that names a mistake, and the library against
// the wrong versions it is written from. End to end (a6_grade names each wrong version's
// mistake, and none for the solution, the alternatives and another seed): scores_test.cpp.
#include "mistakes/mistakes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "a6/force_model.h"
#include "mistakes/library/measured/fit.h"
#include "mistakes/measure.h"
#include "reference/cloth.h"
#include "reference/steppers.h"

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

// The first word after "<key>: " in an EXPECT file, or "".
std::string wordAfter(const std::string& expect, const std::string& key) {
  const auto at = expect.find(key + ": ");
  if (at == std::string::npos) return "";
  std::istringstream id(expect.substr(at + key.size() + 2));
  std::string word;
  id >> word;
  return word;
}

// A wrong version's named mistake is a model's, or its diagnosis by measurement (which the
// catalogue leaves to it: mistakes/measure.h, combine).
TEST(MistakeLibrary, EveryWrongVersionThatNamesAMistakeHasItsModel) {
  std::set<std::string> ids;
  for (const MistakeModel& m : mistakeLibrary()) ids.insert(m.id);
  for (const auto& dir : fs::directory_iterator(kWrong)) {
    const std::string expect = expectOf(dir.path().filename().string());
    const std::string word = wordAfter(expect, "mistake");
    if (word.empty()) continue;
    EXPECT_TRUE(ids.count(word) || word == wordAfter(expect, "diagnosis"))
        << dir.path() << " names " << word << ", which has no model and is not its diagnosis";
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

// ---- the diagnosis by measurement (mistakes/measure.h, mistakes/library/measured/) -------------

namespace {

#include "reference/physics.inc"

namespace measured = a6::grader::measured;

// A part whose physics is -k x along (1, 0), measured at x = 1..5 with k = 2 and k = 3; the
// student's answer `yours(k, x)`.
measured::Part linearPart(double (*yours)(double k, double x)) {
  measured::Part part{"law",
                      "law",
                      "-k x",
                      "N",
                      false,
                      {{"k", true, 1}, {"x", false, 1}},
                      {{"-k x"}, {"k, a constant term", 0}},
                      {}};
  for (double k : {2.0, 3.0}) {
    for (double x : {1.0, 2.0, 3.5, 5.0}) {
      part.samples.push_back({{k, x},
                              Vec2(-k * x, 0),
                              Vec2(yours(k, x), 0),
                              {Vec2(-k * x, 0), Vec2(k, 0)},
                              "x = " + measured::number(x)});
    }
  }
  return part;
}

TEST(Measure, FloatRoundingIsRight) {
  const measured::Finding f = measure(linearPart(
      [](double k, double x) { return static_cast<double>(-static_cast<float>(k) * float(x)); }));
  EXPECT_EQ(f.verdict, measured::Verdict::Right) << f.how << f.measured;
}

TEST(Measure, AFactorIsMeasured) {
  const measured::Finding f = measure(linearPart([](double k, double x) { return -2.5 * k * x; }));
  ASSERT_EQ(f.verdict, measured::Verdict::Differs);
  EXPECT_EQ(f.key, "factor");
  EXPECT_EQ(f.how, "is 2.5 times the physics' size");
  const measured::Finding sign = measure(linearPart([](double k, double x) { return k * x; }));
  EXPECT_EQ(sign.how, "has the wrong sign (-1 times the physics')");
}

TEST(Measure, APowerOfAVariableIsMeasured) {
  const measured::Finding f = measure(linearPart([](double k, double x) { return -k * x * x; }));
  ASSERT_EQ(f.verdict, measured::Verdict::Differs);
  EXPECT_NE(f.how.find("times x, so it goes with x² where the physics' goes with x"),
            std::string::npos)
      << f.how;
}

TEST(Measure, AnAddedTermIsMeasured) {
  const measured::Finding f = measure(linearPart([](double k, double x) { return -k * x + k; }));
  ASSERT_EQ(f.verdict, measured::Verdict::Differs);
  EXPECT_EQ(f.how, "adds k, a constant term, which the slide does not have");
}

TEST(Measure, WhatNoFitExplainsIsOnlyMeasured) {
  const measured::Finding f =
      measure(linearPart([](double k, double x) { return -k * x + 0.1 * x * x * x; }));
  ASSERT_EQ(f.verdict, measured::Verdict::Unexplained);
  EXPECT_TRUE(f.how.empty()) << "no cause is named: " << f.how;
  EXPECT_NE(f.measured.find("at x = 5: yours (2.5, 0) N, the physics' (-10, 0) N"),
            std::string::npos)
      << f.measured;
}

TEST(Measure, NaNIsOnlyMeasured) {
  const measured::Finding f = measure(linearPart([](double k, double x) {
    return x == 2 ? std::numeric_limits<double>::quiet_NaN() : -k * x;
  }));
  EXPECT_EQ(f.verdict, measured::Verdict::Unexplained);
}

// The answers of a correct solution written in float to every designed input: the reference's,
// each number rounded to float.
double fl(double x) { return static_cast<double>(static_cast<float>(x)); }
Vec2 fl(const Vec2& v) { return Vec2(fl(v.x()), fl(v.y())); }

using a6::harness::Answer;
using a6::harness::answerTo;

Answer floatSimulation(const a6::harness::SimulateRequest& r) {
  auto result = r.implicit ? a6::grader::reference::simulateImplicit(r, {})
                           : a6::grader::reference::simulate(r, {});
  if (!result) return answerTo<a6::harness::SimulateRequest>({});
  for (auto& state : result->states) {
    for (a6::Particle& p : state) p.x = fl(p.x), p.v = fl(p.v);
  }
  return answerTo<a6::harness::SimulateRequest>(*result);
}

Answer floatParticles(const a6::harness::ParticleRunRequest& r) {
  a6::harness::ParticlesResult out;
  if (r.emitter.rate > 0) {  // one newborn, emitted first and then aged (its place is random)
    a6::Particle p;
    p.x = r.emitter.position, p.age = fl(r.dt), p.lifetime = 5;
    out.particles = {p};
  } else if (auto run = a6::grader::reference::runParticles(r, {})) {
    out = *run;
    for (a6::Particle& p : out.particles)
      p.x = fl(p.x), p.v = fl(p.v), p.temperature = fl(p.temperature), p.age = fl(p.age);
  }
  return answerTo<a6::harness::ParticleRunRequest>(out);
}

Answer floatForces(const a6::harness::ForcesRequest& r) {
  a6::harness::ForcesResult out;
  out.gravity = fl(referenceGravity(r.particle, r.env));
  out.buoyancy = fl(referenceBuoyancy(r.particle, r.env));
  out.drag = fl(referenceDrag(r.particle, r.env));
  out.repulsion = fl(referenceRepulsion(r.env.repulsion, r.contact));
  out.total = fl(referenceExternalForce(r.particle, r.env));
  return answerTo<a6::harness::ForcesRequest>(out);
}

Answer floatAnswer(const a6::grader::Designed& d) {
  if (const auto* r = std::get_if<SpringForceRequest>(&d.request)) {
    const SpringTerms terms = referenceSpringTerms(r->p1, r->p2, r->restLength, r->ks, r->kd);
    SpringForceResult out;
    out.force = fl(Vec2(fl(terms.elastic) + fl(terms.damping)));
    return answerTo<SpringForceRequest>(out);
  }
  if (const auto* r = std::get_if<JacobiansRequest>(&d.request)) {
    const auto j = referenceSpringJacobians(r->spring.p1.x, r->spring.p2.x, r->spring.restLength,
                                            r->spring.ks, r->spring.kd);
    JacobiansResult out;
    out.dfdx = j.dfdx.cast<float>().cast<double>(), out.dfdv = j.dfdv.cast<float>().cast<double>();
    return answerTo<JacobiansRequest>(out);
  }
  if (const auto* r = std::get_if<a6::harness::ForcesRequest>(&d.request)) return floatForces(*r);
  if (const auto* r = std::get_if<a6::harness::SimulateRequest>(&d.request))
    return floatSimulation(*r);
  if (const auto* r = std::get_if<a6::harness::ParticleRunRequest>(&d.request))
    return floatParticles(*r);
  if (const auto* r = std::get_if<a6::harness::ClothRequest>(&d.request))
    return answerTo<a6::harness::ClothRequest>(a6::grader::reference::referenceCloth(r->spec));
  ADD_FAILURE() << "a designed input of a kind this test does not answer: " << d.label;
  return a6::harness::failedAnswer(d.request, {});
}

TEST(Diagnose, ACorrectSolutionInFloatIsNeverDiagnosed) {
  Transcript t;
  for (const a6::grader::Designed& d : a6::grader::designedInputs()) {
    // Box2D runs in the probe only: task 6's inputs are proved on the wrong versions'
    // and the alternatives' gradings (scores_test.cpp).
    if (std::holds_alternative<a6::harness::Box2DRequest>(d.request)) continue;
    t.exchanges.push_back({d.label, d.request, floatAnswer(d)});
  }
  ASSERT_GT(t.exchanges.size(), 60u);
  const auto found = a6::grader::diagnose(t, {1, 2, 3, 4, 5, 6, 7});
  for (const auto& m : found) ADD_FAILURE() << m.id << ": " << m.text;
}

TEST(Diagnose, AnUnlistedMistakeIsNamedInTheSlidesWords) {
  // The elastic term times l0 / l (no wrong version or model has it): named as such.
  Transcript t;
  for (const a6::grader::Designed& d : a6::grader::designedInputs()) {
    if (std::holds_alternative<a6::harness::Box2DRequest>(d.request)) continue;
    a6::harness::Answer a = floatAnswer(d);
    if (const auto* r = std::get_if<SpringForceRequest>(&d.request)) {
      auto& result = std::get<SpringForceResult>(a);
      const double l = (r->p2.x - r->p1.x).norm();
      const Vec2 e = (r->p2.x - r->p1.x) / l;
      result.force += r->ks * (l - r->restLength) * e * (1 - r->restLength / l);
    }
    t.exchanges.push_back({d.label, d.request, a});
  }
  const auto found = a6::grader::diagnose(t, {1});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].id, "t1_elastic");
  EXPECT_FALSE(found[0].measuredOnly);
  EXPECT_NE(found[0].text.find("elastic term is the physics' -ks (l - l0) e times l0/l"),
            std::string::npos)
      << found[0].text;
}

}  // namespace
