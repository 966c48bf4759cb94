// WRONG VERSION (task 5, written blind from the handout): Dead particles are removed before ageing
// (the age += dt comes after the removal), so a particle whose age reaches its lifetime in this
// step survives one step too long.
// Task 5 — the particle system
#include "a6/particle_system.h"

#include <algorithm>

namespace a6 {

Particle emitParticle(const EmitterSpec& spec, Random& rng) {
  Particle p;
  p.x = spec.position + rng.inDisc(spec.radius);
  const double s = spec.velocitySpread;
  p.v = spec.velocity + Vec2(rng.uniform(-s, s), rng.uniform(-s, s));
  p.temperature = rng.uniform(spec.temperatureMin, spec.temperatureMax);
  p.lifetime = rng.uniform(spec.lifetimeMin, spec.lifetimeMax);
  p.age = 0.0;
  p.m = spec.mass;
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
