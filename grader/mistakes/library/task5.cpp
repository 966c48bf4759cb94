// Task 5, the particle system. The update of particles already alive (no emission: rate 0) is
// deterministic: the reference (reference/steppers.h: forces with the reference model, symplectic
// Euler, cooling towards the air, ageing, removal at age >= lifetime) and the mistakes of
// tests/wrong/t5_* that change it answer ParticleRunRequest as those wrong versions do. The
// emitter's mistakes draw at random: they are recognised by what the emitted sample shows (every
// velocity the same; a disc crowded at its centre), beside what the reference's sample shows.
#include <algorithm>
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"
#include "reference/steppers.h"

namespace a6::grader::mistakes {

using reference::ParticleFlaw;
using reference::runParticles;
namespace {

using harness::ParticleRunRequest;
using harness::ParticlesResult;

// The counts after every step, and the particles alive at the end in the same order (removal
// keeps the order of the others).
bool same(const ParticlesResult& a, const ParticlesResult& b) {
  if (a.counts != b.counts || a.particles.size() != b.particles.size()) return false;
  for (std::size_t k = 0; k < a.particles.size(); ++k) {
    const Particle &p = a.particles[k], &q = b.particles[k];
    const double scale = std::max({1.0, q.x.norm(), q.v.norm()});
    if (!near(p.x, q.x, scale) || !near(p.v, q.v, scale) || !near(p.temperature, q.temperature) ||
        !near(p.age, q.age))
      return false;
  }
  return true;
}

// Emitted samples large enough to tell (the checks emit thousands).
constexpr std::size_t kSample = 200;

// Every emitted velocity exactly spec.velocity, where the spread asks for a uniform offset.
MistakeModel spreadModel() {
  auto judge = [](const Transcript& t) {
    std::vector<Likeness> out;
    for (const auto& x : t.of<harness::EmitRequest>()) {
      const EmitterSpec& spec = x.request.spec;
      if (spec.velocitySpread <= 0 || x.result.particles.size() < kSample) continue;
      const bool allMean = std::all_of(x.result.particles.begin(), x.result.particles.end(),
                                       [&](const Particle& p) { return p.v == spec.velocity; });
      out.push_back(shows(allMean, !allMean));
    }
    return out;
  };
  return MistakeModel{"t5_emitter_ignores_spread", 5,
                      "Your emitter behaves exactly like one that gives every particle exactly "
                      "spec.velocity: add a uniform offset in [-spread, spread] to each component, "
                      "drawn from rng.",
                      judge};
}

// The share of the sample within half the radius: a quarter when uniform over the disc's area,
// a half when the radius itself is drawn uniformly (about 0.035 either way at 200 particles);
// every particle at the centre (the starter) is neither.
MistakeModel discModel() {
  auto judge = [](const Transcript& t) {
    std::vector<Likeness> out;
    for (const auto& x : t.of<harness::EmitRequest>()) {
      const EmitterSpec& spec = x.request.spec;
      const auto& ps = x.result.particles;
      if (spec.radius <= 0 || ps.size() < kSample) continue;
      const auto inner = std::count_if(ps.begin(), ps.end(), [&](const Particle& p) {
        return (p.x - spec.position).norm() < spec.radius / 2;
      });
      const double share = static_cast<double>(inner) / static_cast<double>(ps.size());
      out.push_back(shows(share > 0.42 && share<0.58, share> 0.17 && share < 0.33));
    }
    return out;
  };
  return MistakeModel{"t5_uniform_radius_in_disc", 5,
                      "Your emitter behaves exactly like one that draws the radius uniformly in "
                      "[0, r]: that crowds the particles at the disc's centre; uniform over the "
                      "area needs r sqrt(u), which rng.inDisc(r) gives.",
                      judge};
}

}  // namespace

std::vector<MistakeModel> task5Mistakes() {
  const auto updateModel = flawModels<ParticleRunRequest, ParticleFlaw>(5, runParticles, same);
  return {
      updateModel("t5_position_before_velocity", ParticleFlaw::PositionFirst,
                  "Your update behaves exactly like explicit Euler: the position moves before "
                  "the velocity is updated; update v first, then x with the new velocity."),
      updateModel("t5_cooling_wrong_sign", ParticleFlaw::CoolingWrongSign,
                  "Your update behaves exactly like one whose cooling has the wrong sign: "
                  "particles move away from the air's temperature; T -= k_c (T - T_air) dt."),
      updateModel("t5_no_removal", ParticleFlaw::NoRemoval,
                  "Your update behaves exactly like one that ages particles but never removes "
                  "them: erase every particle whose age has reached its lifetime."),
      updateModel("t5_removal_off_by_one", ParticleFlaw::RemovalLate,
                  "Your update behaves exactly like one that removes a particle only when age > "
                  "lifetime, one step late: remove it once age >= lifetime."),
      spreadModel(),
      discModel(),
  };
}

}  // namespace a6::grader::mistakes
