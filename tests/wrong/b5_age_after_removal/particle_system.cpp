// WRONG VERSION (task 5, written blind from the handout): Dead particles are removed before age +=
// dt in the same step (removal tests the previous age), so each particle survives one step past its
// lifetime.
// Task 5 — the particle system
#include "a6/particle_system.h"

#include <algorithm>

namespace a6 {

Particle emitParticle(const EmitterSpec& spec, Random& rng) {
  Particle p;
  p.x = spec.position + rng.inDisc(spec.radius);
  const double s = spec.velocitySpread;
  const double ox = rng.uniform(-s, s);
  const double oy = rng.uniform(-s, s);
  p.v = spec.velocity + Vec2(ox, oy);
  p.temperature = rng.uniform(spec.temperatureMin, spec.temperatureMax);
  p.lifetime = rng.uniform(spec.lifetimeMin, spec.lifetimeMax);
  p.m = spec.mass;
  p.age = 0.0;
  return p;
}

void ParticleSystem::update(double dt) {
  const int count = emissionCount(dt);
  for (int k = 0; k < count; ++k) particles.push_back(emitParticle(emitter, rng));

  for (Particle& p : particles) {
    p.f = externalForce(p);
    p.v += p.f / p.m * dt;
    p.x += p.v * dt;
    p.temperature += -coolingRate * (p.temperature - env.airTemperature) * dt;
  }

  particles.erase(std::remove_if(particles.begin(), particles.end(),
                                 [](const Particle& p) { return p.age >= p.lifetime; }),
                  particles.end());
  for (Particle& p : particles) p.age += dt;
}

}  // namespace a6
