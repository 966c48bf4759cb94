// Task 7, the implicit step, part by part: one linearised backward Euler step with the reference
// forces and the physics' Jacobians, solved densely, its parts (the off-diagonal blocks' sign, the
// power of h before dfdx, the term h² dfdx v of b, how Δv is applied, the pins' fix(), the order
// of v and x) each in the physics' form or a wrong one, with one or two parts wrong. The checks'
// small systems are modelled (a dense solve per step); the stiff cloth, and requests run on the
// student's own forces, are skipped. A wrong Jacobian makes every one of these differ: it is
// named by its own models (parts.cpp).
#include <Eigen/Dense>
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

#include "reference_models.inc"

using harness::SimulateRequest;
using harness::SimulateResult;

// One form of the step, part by part; the default is the physics'.
struct ImplicitForm {
  bool offDiagonalNegative = false;  ///< -K on the blocks (i, j) and (j, i), where +K belongs
  bool hBeforeDfdx = false;          ///< K = h dfdv + h dfdx: h where h² belongs
  bool rhsWithoutDfdxV = false;      ///< b = h f
  bool deltaVAsVelocity = false;     ///< v = Δv
  bool pinsNotFixed = false;         ///< no fix(): pins solved as free, then skipped
  bool positionFirst = false;        ///< x += h v before v += Δv
};

constexpr std::size_t kLargestModelled = 12;  // particles: a dense solve per step stays cheap

// The physics' Jacobians of the spring from p1 to p2 (zero for coincident ends).
void jacobians(const Particle& p1, const Particle& p2, const SpringData& d, Mat2& dfdx,
               Mat2& dfdv) {
  const Vec2 delta = p2.x - p1.x;
  const double l = delta.norm();
  dfdx = dfdv = Mat2::Zero();
  if (l < 1e-12) return;
  const Vec2 e = delta / l;
  const Mat2 along = e * e.transpose(), across = Mat2::Identity() - along;
  dfdx = -d.ks * (along + (1 - d.restLength / l) * across);
  dfdv = -d.kd * along;
}

// A = M - h dfdv - h² dfdx and b = h (f + h dfdx v), each part in the form's shape.
void assemble(const std::vector<Particle>& ps, const std::vector<SpringData>& springs, double h,
              const ImplicitForm& form, Eigen::MatrixXd& A, Eigen::VectorXd& b) {
  const Eigen::Index n = static_cast<Eigen::Index>(ps.size());
  A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  b = Eigen::VectorXd::Zero(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    A.block<2, 2>(2 * i, 2 * i) += ps[i].m * Mat2::Identity();
    b.segment<2>(2 * i) = h * ps[i].f;
  }
  for (const SpringData& d : springs) {
    Mat2 dfdx, dfdv;
    jacobians(ps[d.i], ps[d.j], d, dfdx, dfdv);
    const Mat2 K = h * dfdv + (form.hBeforeDfdx ? h : h * h) * dfdx;
    const Mat2 off = form.offDiagonalNegative ? Mat2(-K) : K;
    A.block<2, 2>(2 * d.i, 2 * d.i) -= K;
    A.block<2, 2>(2 * d.j, 2 * d.j) -= K;
    A.block<2, 2>(2 * d.i, 2 * d.j) += off;
    A.block<2, 2>(2 * d.j, 2 * d.i) += off;
    if (form.rhsWithoutDfdxV) continue;
    const Vec2 dfdxV = h * h * dfdx * (ps[d.j].v - ps[d.i].v);
    b.segment<2>(2 * d.j) += dfdxV;
    b.segment<2>(2 * d.i) -= dfdxV;
  }
}

void step(std::vector<Particle>& ps, const std::vector<SpringData>& springs, const Environment& env,
          double h, const ImplicitForm& form) {
  for (Particle& p : ps) p.f = referenceExternalForce(p, env);
  for (const SpringData& d : springs) {
    const Spring s{&ps[d.i], &ps[d.j], d.restLength, d.ks, d.kd, d.type};
    const Vec2 f = referenceSpringForce(s);
    ps[d.j].f += f;
    ps[d.i].f -= f;
  }
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  assemble(ps, springs, h, form, A, b);
  for (std::size_t i = 0; i < ps.size() && !form.pinsNotFixed; ++i) {
    if (!ps[i].pinned) continue;
    const Eigen::Index k = 2 * static_cast<Eigen::Index>(i);
    A.middleRows(k, 2).setZero(), A.middleCols(k, 2).setZero();
    A.block<2, 2>(k, k) = Mat2::Identity(), b.segment<2>(k).setZero();
  }
  const Eigen::VectorXd dv = A.fullPivLu().solve(b);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    Particle& p = ps[i];
    if (p.pinned) continue;
    const Vec2 change = dv.segment<2>(2 * static_cast<Eigen::Index>(i));
    if (form.positionFirst) p.x += p.v * h;
    p.v = form.deltaVAsVelocity ? change : Vec2(p.v + change);
    if (!form.positionFirst) p.x += p.v * h;
  }
}

std::optional<SimulateResult> simulate(const SimulateRequest& r, const ImplicitForm& form) {
  if (!r.implicit || !r.referenceForces || r.particles.size() > kLargestModelled)
    return std::nullopt;
  const int n = static_cast<int>(r.particles.size());
  for (const SpringData& d : r.springs) {
    if (d.i < 0 || d.j < 0 || d.i >= n || d.j >= n || d.i == d.j) return std::nullopt;
  }
  std::vector<Particle> ps = r.particles;
  SimulateResult out;
  const int every = std::max(1, r.recordEvery);
  const int substeps = r.stepOnly ? 1 : std::max(1, r.substeps);
  for (int frame = 1; frame <= r.frames; ++frame) {
    for (int k = 0; k < substeps; ++k) step(ps, r.springs, r.env, r.frameDt / substeps, form);
    if (frame % every == 0 || frame == r.frames) {
      out.recordedFrames.push_back(frame);
      out.states.push_back(ps);
    }
  }
  return out;
}

// One wrong form of one part of the step: its key (the model's id; a one-part form's is the
// wrong version's it was first written from, tests/wrong/t7_<key>), what it does, and the form.
struct WrongPart {
  const char* key;
  const char* does;
  void (*apply)(ImplicitForm&);
};

const std::vector<WrongPart>& wrongParts() {
  static const std::vector<WrongPart> parts = {
      {"off_diagonal_sign",
       "adds -K on the off-diagonal blocks (i, j) and (j, i): they take +K, the diagonal ones -K",
       [](ImplicitForm& f) { f.offDiagonalNegative = true; }},
      {"h_instead_of_h_squared",
       "puts h dfdx in A where the physics has h² dfdx: A = M - h dfdv - h² dfdx",
       [](ImplicitForm& f) { f.hBeforeDfdx = true; }},
      {"rhs_without_dfdx_v",
       "leaves h² dfdx (v_j - v_i) out of b: b = h (f + h dfdx v), spring by spring",
       [](ImplicitForm& f) { f.rhsWithoutDfdxV = true; }},
      {"delta_v_as_velocity", "uses the solve's Δv as the new velocity: it is the change, v += Δv",
       [](ImplicitForm& f) { f.deltaVAsVelocity = true; }},
      {"pinned_rows_not_fixed",
       "never fix()es the pinned particles, so the others are solved as if the pins could move",
       [](ImplicitForm& f) { f.pinsNotFixed = true; }},
      {"position_before_velocity",
       "moves x with the old velocity (x += h v before v += Δv): apply Δv first",
       [](ImplicitForm& f) { f.positionFirst = true; }},
  };
  return parts;
}

MistakeModel model(const std::vector<const WrongPart*>& wrong) {
  ImplicitForm form;
  std::string key, text = "Your stepImplicit ";
  for (const WrongPart* part : wrong) {
    part->apply(form);
    key += (key.empty() ? "" : "_and_") + std::string(part->key);
    text += (part == wrong.front() ? "" : "; it ") + std::string(part->does);
  }
  auto judge = [form](const Transcript& t) {
    return judgeEach(
        t.of<harness::SimulateRequest>(),
        [](const SimulateRequest& r) { return simulate(r, ImplicitForm{}); },
        [form](const SimulateRequest& r) { return simulate(r, form); }, sameRun);
  };
  MistakeModel m{"t7_" + key, 7, text + ".", judge};
  m.partByPart = true;
  return m;
}

}  // namespace

// Every step with one or two parts in a wrong form (MistakeModel::partByPart).
std::vector<MistakeModel> task7Mistakes() {
  std::vector<MistakeModel> models;
  const std::vector<WrongPart>& parts = wrongParts();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    models.push_back(model({&parts[i]}));
    for (std::size_t j = i + 1; j < parts.size(); ++j)
      models.push_back(model({&parts[i], &parts[j]}));
  }
  return models;
}

}  // namespace a6::grader::mistakes
