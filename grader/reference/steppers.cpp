// The reference steppers, in forms (see steppers.h).
#include "reference/steppers.h"

#include <Eigen/Dense>
#include <algorithm>

namespace a6::grader::reference {

namespace {
#include "reference/physics.inc"
}  // namespace

using harness::ParticleRunRequest;
using harness::ParticlesResult;
using harness::SimulateRequest;
using harness::SimulateResult;

// Task 3 -----------------------------------------------------------------------------------------

namespace {

// Runs r's frames, each n substeps step(dt) of dt = frameDt / n (n = 1 when r steps once a frame),
// and gives `particles` after every recordEvery-th frame and the last (task 7's too).
template <class Step>
SimulateResult run(const SimulateRequest& r, const std::vector<Particle>& particles, Step step) {
  SimulateResult out;
  const int every = std::max(1, r.recordEvery);
  const int substeps = r.stepOnly ? 1 : std::max(1, r.substeps);
  for (int frame = 1; frame <= r.frames; ++frame) {
    for (int k = 0; k < substeps; ++k) step(r.frameDt / substeps);
    if (frame % every == 0 || frame == r.frames) {
      out.recordedFrames.push_back(frame);
      out.states.push_back(particles);
    }
  }
  return out;
}

struct System {
  std::vector<Particle> particles;
  std::vector<SpringData> springs;
  Environment env;
};

// 1. each particle's external force, 2. every spring's force on both ends (tasks 3 and 7).
void accumulateForces(std::vector<Particle>& ps, const std::vector<SpringData>& springs,
                      const Environment& env, const StepForm& form) {
  for (Particle& p : ps) {
    const Vec2 f = referenceExternalForce(p, env);
    p.f = form.forcesKept ? Vec2(p.f + f) : f;
  }
  for (const SpringData& d : springs) {
    Particle& p1 = ps[static_cast<std::size_t>(d.i)];
    Particle& p2 = ps[static_cast<std::size_t>(d.j)];
    const Spring spring{&p1, &p2, d.restLength, d.ks, d.kd, d.type};
    const Vec2 f = referenceSpringForce(spring);
    p2.f += form.springEnds == 2 ? Vec2(-f) : f;
    p1.f += form.springEnds == 0 ? Vec2(-f) : f;
  }
}

// 3. velocity, then position with the new velocity (or the form's order, division and pins).
void step(System& s, double dt, const StepForm& form) {
  accumulateForces(s.particles, s.springs, s.env, form);
  for (Particle& p : s.particles) {
    if (p.pinned && form.pins == 0) continue;
    const bool moveV = !p.pinned || form.pins != 3, moveX = !p.pinned || form.pins != 2;
    const Vec2 dv = form.noMassDivision ? Vec2(p.f * dt) : referenceVelocityChange(p, dt);
    if (form.positionFirst && moveX) p.x += referencePositionChange(p, dt);
    if (moveV) p.v += dv;
    if (!form.positionFirst && moveX) p.x += referencePositionChange(p, dt);
  }
}

}  // namespace

std::optional<SimulateResult> simulate(const SimulateRequest& r, const StepForm& form) {
  if (!r.referenceForces || r.implicit) return std::nullopt;
  for (const SpringData& d : r.springs) {
    const int n = static_cast<int>(r.particles.size());
    if (d.i < 0 || d.j < 0 || d.i >= n || d.j >= n) return std::nullopt;
  }
  System s{r.particles, r.springs, r.env};
  return run(r, s.particles,
             [&](double dt) { step(s, form.substepFullDt ? r.frameDt : dt, form); });
}

// Task 5 -----------------------------------------------------------------------------------------

namespace {

void update(std::vector<Particle>& particles, const ParticleRunRequest& r, ParticleFlaw flaw) {
  const double dt = r.dt,
               cooling = flaw == ParticleFlaw::CoolingWrongSign ? -r.coolingRate : r.coolingRate;
  for (Particle& p : particles) {
    p.f = referenceExternalForce(p, r.env);
    if (flaw == ParticleFlaw::PositionFirst) p.x += referencePositionChange(p, dt);
    p.v += referenceVelocityChange(p, dt);
    if (flaw != ParticleFlaw::PositionFirst) p.x += referencePositionChange(p, dt);
    p.temperature += referenceCooling(p, r.env, cooling, dt);
    p.age += dt;
  }
  if (flaw == ParticleFlaw::NoRemoval) return;
  const auto dead = [flaw](const Particle& p) {
    return flaw == ParticleFlaw::RemovalLate ? p.age > p.lifetime : p.age >= p.lifetime;
  };
  particles.erase(std::remove_if(particles.begin(), particles.end(), dead), particles.end());
}

}  // namespace

std::optional<ParticlesResult> runParticles(const ParticleRunRequest& r, ParticleFlaw flaw) {
  if (!r.referenceForces || r.emitter.rate != 0 || r.steps > 100000) return std::nullopt;
  ParticlesResult out;
  out.particles = r.initial;
  for (int k = 0; k < r.steps; ++k) {
    update(out.particles, r, flaw);
    out.counts.push_back(static_cast<int>(out.particles.size()));
  }
  return out;
}

// Task 7 -----------------------------------------------------------------------------------------

namespace {

constexpr std::size_t kLargestModelled = 12;  // particles: a dense solve per step stays cheap

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
    const auto [dfdx, dfdv] =
        referenceSpringJacobians(ps[d.i].x, ps[d.j].x, d.restLength, d.ks, d.kd);
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
  accumulateForces(ps, springs, env, StepForm{});
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
    if (form.positionFirst) p.x += referencePositionChange(p, h);
    p.v = form.deltaVAsVelocity ? change : Vec2(p.v + change);
    if (!form.positionFirst) p.x += referencePositionChange(p, h);
  }
}

}  // namespace

std::optional<SimulateResult> simulateImplicit(const SimulateRequest& r, const ImplicitForm& form) {
  if (!r.implicit || !r.referenceForces || r.particles.size() > kLargestModelled)
    return std::nullopt;
  const int n = static_cast<int>(r.particles.size());
  for (const SpringData& d : r.springs) {
    if (d.i < 0 || d.j < 0 || d.i >= n || d.j >= n || d.i == d.j) return std::nullopt;
  }
  std::vector<Particle> ps = r.particles;
  return run(r, ps, [&](double dt) { step(ps, r.springs, r.env, dt, form); });
}

}  // namespace a6::grader::reference
