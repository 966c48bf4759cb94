// The framework's part of the particle system; emitParticle() and update() are task 5.
#include "a6/particle_system.h"

#include <cmath>

namespace a6 {

int ParticleSystem::emissionCount(double dt) {
  if (!(dt > 0) || !(emitter.rate > 0)) return 0;
  emissionDebt_ += emitter.rate * dt;
  const double whole = std::floor(emissionDebt_);
  emissionDebt_ -= whole;
  return static_cast<int>(whole);
}

Vec2 ParticleSystem::externalForce(const Particle& p) const {
  if (forceModel_.externalAmong) {
    const ParticlesView all{particles.size(),
                            [this](std::size_t i) -> const Particle& { return particles[i]; }};
    return forceModel_.externalAmong(p, all, env);
  }
  return forceModel_.external ? forceModel_.external(p, env) : a6::externalForce(p, env);
}

}  // namespace a6
