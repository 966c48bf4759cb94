// Tasks 1 and 7 measured: the spring force's elastic and damping terms, and springJacobians'
// blocks split along the spring (e eᵀ) and across it (I - e eᵀ).
//
// The springs lie along e at 0.5 rad, so no answer hides in an axis. Still springs (v1 = v2 = 0)
// show the elastic term alone; a moving spring's force less its still twin's shows the damping
// term. Each variable (l, l0, ks, kd, the velocities) is varied on its own around one spring.
#include <cmath>
#include <optional>

#include "mistakes/library/measured/tasks.h"

namespace a6::grader::measured {
namespace {

#include "reference/physics.inc"

using harness::JacobiansRequest;
using harness::SpringForceRequest;

const Vec2 kFrom(0.4, -0.2);
const Vec2 kE(std::cos(0.5), std::sin(0.5)), kN(-std::sin(0.5), std::cos(0.5));

struct SpringInput {
  double l, l0, ks, kd;
};

// The still springs: l around l0 = 1.3 (and l = l0, where the elastic term is zero), then ks,
// kd and l0 changed one at a time.
const std::vector<SpringInput>& stillSprings() {
  static const std::vector<SpringInput> springs = {
      {0.6, 1.3, 40, 0.7}, {1.9, 1.3, 40, 0.7}, {2.6, 1.3, 40, 0.7}, {3.7, 1.3, 40, 0.7},
      {1.3, 1.3, 40, 0.7}, {2.6, 1.3, 90, 0.7}, {2.6, 1.3, 40, 1.6}, {3.4, 2.1, 40, 0.7},
      {1.0, 2.1, 40, 0.7}, {1.9, 1.3, 40, 1.6}, {1.9, 1.3, 90, 0.7}, {3.4, 1.3, 40, 0.7}};
  return springs;
}

// The moving springs: the velocities (v1, v2) along e and n, on the spring l = 1.9.
struct Motion {
  SpringInput spring;
  double v1e, v1n, v2e, v2n;
};

const std::vector<Motion>& motions() {
  static const SpringInput s{1.9, 1.3, 40, 0.7};
  static const std::vector<Motion> m = {{s, 0, 0, 0.8, 0},
                                        {s, 0, 0, -1.7, 0.3},
                                        {s, 0.5, 0, 0, 0},
                                        {s, 0.3, 0.9, 1.1, -0.4},
                                        {s, 0, 0, 0, 1.2},
                                        {s, -0.6, 0.2, 0.9, 0},
                                        {{1.9, 1.3, 40, 1.6}, 0.3, 0.9, 1.1, -0.4},
                                        {{1.9, 1.3, 90, 0.7}, 0.3, 0.9, 1.1, -0.4},
                                        {{3.4, 1.3, 40, 0.7}, 0.3, 0.9, 1.1, -0.4}};
  return m;
}

SpringForceRequest requestOf(const SpringInput& s, const Vec2& v1, const Vec2& v2) {
  SpringForceRequest r;
  r.p1.x = kFrom, r.p2.x = kFrom + s.l * kE;
  r.p1.v = v1, r.p2.v = v2;
  r.p1.m = r.p2.m = 1;
  r.restLength = s.l0, r.ks = s.ks, r.kd = s.kd;
  return r;
}

// What a request's spring is, in the slide's words.
std::string where(const SpringForceRequest& r) {
  return "l = " + number((r.p2.x - r.p1.x).norm()) + ", l0 = " + number(r.restLength) +
         ", ks = " + number(r.ks) + ", kd = " + number(r.kd);
}

std::vector<double> valuesOf(const SpringForceRequest& r) {
  return {r.ks, r.kd, (r.p2.x - r.p1.x).norm(), r.restLength};
}

std::vector<Variable> springVariables() {
  return {{"ks", true}, {"kd", true}, {"l", false}, {"l0", false}};
}

Part elasticPart(const Transcript& t) {
  Part part{"elastic",
            "spring force's elastic term",
            "-ks (l - l0) e",
            "N",
            false,
            springVariables(),
            {{"-ks l e"}, {"ks l0 e"}},
            {}};
  for (const auto& x : answersTo<SpringForceRequest>(t, "t1.still")) {
    const SpringForceRequest& r = x.request;
    const double l = (r.p2.x - r.p1.x).norm();
    Sample s{valuesOf(r), {}, x.result.force, {-r.ks * l * kE, r.ks * r.restLength * kE}, where(r)};
    s.physics = referenceSpringTerms(r.p1, r.p2, r.restLength, r.ks, r.kd).elastic;
    part.samples.push_back(std::move(s));
  }
  return part;
}

// The still twin's answer of a moving spring's request, if it was answered.
std::optional<Vec2> stillForce(const Transcript& t, const SpringForceRequest& moving) {
  for (const auto& x : answersTo<SpringForceRequest>(t, "t1.still")) {
    const SpringForceRequest& r = x.request;
    if (r.p2.x == moving.p2.x && r.restLength == moving.restLength && r.ks == moving.ks &&
        r.kd == moving.kd)
      return x.result.force;
  }
  return std::nullopt;
}

Part dampingPart(const Transcript& t) {
  Part part{"damping",
            "spring force's damping term",
            "-kd ((v2 - v1)·e) e",
            "N",
            false,
            springVariables(),
            {},
            {}};
  part.variables.push_back({"|(v2 - v1)·e|", false});
  part.terms = {{"-kd (v2·e) e"},
                {"kd (v1·e) e, p1's velocity"},
                {"-kd ((v2 - v1)·n) n, the relative velocity across the spring", 0}};
  for (const auto& x : answersTo<SpringForceRequest>(t, "t1.moving")) {
    const SpringForceRequest& r = x.request;
    const std::optional<Vec2> still = stillForce(t, r);
    if (!still) continue;
    const Vec2 u = r.p2.v - r.p1.v;
    Sample s{valuesOf(r), {}, x.result.force - *still, {}, {}};
    s.values.push_back(std::max(std::abs(u.dot(kE)), 1e-3));
    s.physics = referenceSpringTerms(r.p1, r.p2, r.restLength, r.ks, r.kd).damping;
    s.terms = {-r.kd * r.p2.v.dot(kE) * kE, r.kd * r.p1.v.dot(kE) * kE, -r.kd * u.dot(kN) * kN};
    s.where = where(r) + ", v1 = " + vector(r.p1.v) + ", v2 = " + vector(r.p2.v);
    part.samples.push_back(std::move(s));
  }
  return part;
}

// One scalar part of a Jacobian block M: its along part eᵀ M e, its across part nᵀ M n, or its
// mixed part (eᵀ M n + nᵀ M e) / 2, which the physics does not have.
enum class Piece { Along, Across, Mixed };

double pieceOf(const Mat2& m, Piece piece) {
  if (piece == Piece::Along) return kE.dot(m * kE);
  if (piece == Piece::Across) return kN.dot(m * kN);
  return (kE.dot(m * kN) + kN.dot(m * kE)) / 2;
}

// The slide's terms of each piece of dfdx and dfdv at one spring (scalars, in x), with the
// alternatives students write.
std::vector<Term> jacobianTerms(bool dfdx, Piece piece) {
  if (piece == Piece::Mixed) return {};
  if (dfdx && piece == Piece::Along) return {{"-ks"}, {"ks l0/l, the across part's term", 0}};
  if (dfdx) return {{"-ks"}, {"ks l0/l"}};
  if (piece == Piece::Along) return {{"-kd"}};
  return {{"-kd (I - e eᵀ), damping across the spring", 0}};
}

std::vector<Vec2> jacobianTermValues(bool dfdx, Piece piece, const SpringForceRequest& r) {
  const double l = (r.p2.x - r.p1.x).norm();
  if (piece == Piece::Mixed) return {};
  if (dfdx && piece == Piece::Along) return {Vec2(-r.ks, 0), Vec2(r.ks * r.restLength / l, 0)};
  if (dfdx) return {Vec2(-r.ks, 0), Vec2(r.ks * r.restLength / l, 0)};
  if (piece == Piece::Along) return {Vec2(-r.kd, 0)};
  return {Vec2(-r.kd, 0)};
}

Part jacobianPart(const Transcript& t, bool dfdx, Piece piece) {
  static const char* const kPieces[] = {"along the spring (e eᵀ)", "across the spring (I - e eᵀ)",
                                        "mixing along and across (e nᵀ + n eᵀ)"};
  static const char* const kFormulas[2][3] = {{"-kd", "0", "0"}, {"-ks", "-ks (1 - l0/l)", "0"}};
  const int k = static_cast<int>(piece);
  static const char* const kTags[] = {"along", "across", "mixed"};
  const std::string block = dfdx ? "dfdx" : "dfdv";
  Part part{block + "_" + kTags[k],
            block + "'s part " + kPieces[k],
            kFormulas[dfdx][k],
            dfdx ? "N/m" : "N·s/m",
            true,
            springVariables(),
            jacobianTerms(dfdx, piece),
            {}};
  for (const auto& x : answersTo<JacobiansRequest>(t, "t7.jacobians")) {
    const SpringForceRequest& r = x.request.spring;
    const SpringJacobians physics =
        referenceSpringJacobians(r.p1.x, r.p2.x, r.restLength, r.ks, r.kd);
    const Mat2& yours = dfdx ? x.result.dfdx : x.result.dfdv;
    const Mat2& theirs = dfdx ? physics.dfdx : physics.dfdv;
    part.samples.push_back({valuesOf(r), Vec2(pieceOf(theirs, piece), 0),
                            Vec2(pieceOf(yours, piece), 0), jacobianTermValues(dfdx, piece, r),
                            where(r), (dfdx ? r.ks : r.kd) * (1 + r.restLength)});
  }
  return part;
}

// A block's along and across parts that differ alike (the same words) are the block's.
void mergeBlock(std::vector<Finding>& f, std::size_t along, const char* block) {
  Finding &a = f[along], &b = f[along + 1];
  if (a.verdict != Verdict::Differs || b.verdict != Verdict::Differs || a.how != b.how ||
      a.key != "factor")
    return;
  a.part = block;
  a.tag = block;
  f.erase(f.begin() + static_cast<std::ptrdiff_t>(along) + 1);
}

}  // namespace

void designSpring(std::vector<Designed>& out) {
  for (const SpringInput& s : stillSprings()) {
    const SpringForceRequest r = requestOf(s, Vec2::Zero(), Vec2::Zero());
    out.push_back(designed("t1.still", r));
    out.push_back(designed("t7.jacobians", JacobiansRequest{r}));
  }
  for (const Motion& m : motions()) {
    const SpringForceRequest r =
        requestOf(m.spring, m.v1e * kE + m.v1n * kN, m.v2e * kE + m.v2n * kN);
    out.push_back(designed("t1.moving", r));
  }
}

std::vector<Finding> measureSpringForce(const Transcript& t) {
  return {measure(elasticPart(t)), measure(dampingPart(t))};
}

std::vector<Finding> measureJacobians(const Transcript& t) {
  std::vector<Finding> f;
  for (bool dfdx : {true, false}) {
    for (Piece piece : {Piece::Along, Piece::Across, Piece::Mixed})
      f.push_back(measure(jacobianPart(t, dfdx, piece)));
  }
  mergeBlock(f, 3, "dfdv");  // the later block first: the indices before it stay
  mergeBlock(f, 0, "dfdx");
  return f;
}

}  // namespace a6::grader::measured
