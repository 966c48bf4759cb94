// Task 3, time stepping: the reference symplectic Euler step with the reference forces (the
// checks of task 3 ask the probe for them too: referenceForces), advance(T, n) as n steps of
// T / n, and the mistakes of tests/wrong/t3_*, each answering SimulateRequest as that wrong
// version does. Requests run on the student's own forces cannot be modelled: they are skipped.
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

#include "reference_models.inc"

using harness::SimulateRequest;
using harness::SimulateResult;

enum class Flaw {
  None,
  PositionFirst,
  NoMassDivision,
  ForcesNotReset,
  NoPinning,
  SpringSameSign,
  SubstepsFullDt
};

struct System {
  std::vector<Particle> particles;
  std::vector<SpringData> springs;
  Environment env;
};

// 1. each particle's external force, 2. every spring's force on both ends.
void accumulateForces(System& s, Flaw flaw) {
  for (Particle& p : s.particles) {
    const Vec2 f = referenceExternalForce(p, s.env);
    p.f = flaw == Flaw::ForcesNotReset ? Vec2(p.f + f) : f;
  }
  for (const SpringData& d : s.springs) {
    Particle& p1 = s.particles[static_cast<std::size_t>(d.i)];
    Particle& p2 = s.particles[static_cast<std::size_t>(d.j)];
    const Spring spring{&p1, &p2, d.restLength, d.ks, d.kd, d.type};
    const Vec2 f = referenceSpringForce(spring);
    p2.f += f;
    p1.f += flaw == Flaw::SpringSameSign ? f : Vec2(-f);
  }
}

// 3. velocity, then position with the new velocity (or the flaw's order and division).
void step(System& s, double dt, Flaw flaw) {
  accumulateForces(s, flaw);
  for (Particle& p : s.particles) {
    if (p.pinned && flaw != Flaw::NoPinning) continue;
    const Vec2 dv = (flaw == Flaw::NoMassDivision ? p.f : Vec2(p.f / p.m)) * dt;
    if (flaw == Flaw::PositionFirst) p.x += p.v * dt;
    p.v += dv;
    if (flaw != Flaw::PositionFirst) p.x += p.v * dt;
  }
}

std::optional<SimulateResult> simulate(const SimulateRequest& r, Flaw flaw) {
  if (!r.referenceForces) return std::nullopt;
  for (const SpringData& d : r.springs) {
    const int n = static_cast<int>(r.particles.size());
    if (d.i < 0 || d.j < 0 || d.i >= n || d.j >= n) return std::nullopt;
  }
  System s{r.particles, r.springs, r.env};
  SimulateResult out;
  const int every = std::max(1, r.recordEvery);
  const int substeps = r.stepOnly ? 1 : std::max(1, r.substeps);
  const double dt = r.stepOnly || flaw == Flaw::SubstepsFullDt ? r.frameDt : r.frameDt / substeps;
  for (int frame = 1; frame <= r.frames; ++frame) {
    for (int k = 0; k < substeps; ++k) step(s, dt, flaw);
    if (frame % every == 0 || frame == r.frames) {
      out.recordedFrames.push_back(frame);
      out.states.push_back(s.particles);
    }
  }
  return out;
}

// The recorded positions and velocities, each within the tolerance of the run's largest value.
bool same(const SimulateResult& a, const SimulateResult& b) {
  if (a.recordedFrames != b.recordedFrames || a.states.size() != b.states.size()) return false;
  double scale = 0;
  for (const auto& state : b.states) {
    for (const Particle& p : state) scale = std::max({scale, p.x.norm(), p.v.norm()});
  }
  for (std::size_t k = 0; k < a.states.size(); ++k) {
    if (a.states[k].size() != b.states[k].size()) return false;
    for (std::size_t i = 0; i < a.states[k].size(); ++i) {
      const Particle &p = a.states[k][i], &q = b.states[k][i];
      if (!near(p.x, q.x, scale) || !near(p.v, q.v, scale)) return false;
    }
  }
  return true;
}

MistakeModel model(const char* id, Flaw flaw, const char* text) {
  auto judge = [flaw](const Transcript& t) {
    return judgeEach(
        t.simulations, [](const SimulateRequest& r) { return simulate(r, Flaw::None); },
        [flaw](const SimulateRequest& r) { return simulate(r, flaw); }, same);
  };
  return MistakeModel{id, 3, text, judge};
}

}  // namespace

std::vector<MistakeModel> task3Mistakes() {
  return {
      model("t3_position_before_velocity", Flaw::PositionFirst,
            "Your step behaves exactly like explicit Euler: x += v dt comes before v += f/m dt, "
            "so the position moves with the old velocity and a spring's energy grows every step; "
            "update the velocity first, then the position with the new velocity."),
      model("t3_force_not_divided_by_mass", Flaw::NoMassDivision,
            "Your step behaves exactly like v += f dt: the force is not divided by the mass; the "
            "acceleration is f / m."),
      model("t3_forces_not_reset", Flaw::ForcesNotReset,
            "Your step behaves exactly like one that never resets the forces (p.f += "
            "externalForce(p)): each step adds on top of the last step's total; start each step "
            "with p.f = externalForce(p)."),
      model("t3_missing_pinning", Flaw::NoPinning,
            "Your step behaves exactly like one that moves pinned particles too: skip every "
            "particle with pinned set when you update v and x."),
      model("t3_spring_force_same_sign", Flaw::SpringSameSign,
            "Your step behaves exactly like one that gives both ends of a spring +f: p2 gets +f "
            "and p1 must get -f, or momentum is not conserved."),
      model("t3_substeps_reuse_frame_dt", Flaw::SubstepsFullDt,
            "Your advance behaves exactly like n steps of the whole frame time: each substep "
            "must be frameDt / n long, or the simulation runs n times too fast."),
  };
}

}  // namespace a6::grader::mistakes

namespace a6::grader {

std::optional<harness::SimulateResult> referenceSimulation(const harness::SimulateRequest& r) {
  return mistakes::simulate(r, mistakes::Flaw::None);
}

}  // namespace a6::grader
