// WRONG VERSION (task 5): the emitter draws the radius uniformly in [0, r] and a uniform angle,
// which crowds the particles at the centre of the disc (uniform over the area needs r sqrt(u)).
// Task 5 — the particle system (slides "Particles", "Particle systems").
#include "a6/particle_system.h"

#include <algorithm>
#include <cmath>

namespace a6 {

// The emitter: a new particle with a randomized initial state.
Particle emitParticle(const EmitterSpec& spec, Random& rng) {
  Particle p;
  const double radius = rng.uniform(0, spec.radius), angle = rng.uniform(0, 2 * M_PI);
  p.x = spec.position + radius * Vec2(std::cos(angle), std::sin(angle));
  p.v = spec.velocity + Vec2(rng.uniform(-spec.velocitySpread, spec.velocitySpread),
                             rng.uniform(-spec.velocitySpread, spec.velocitySpread));
  p.m = spec.mass;
  p.temperature = rng.uniform(spec.temperatureMin, spec.temperatureMax);
  p.lifetime = rng.uniform(spec.lifetimeMin, spec.lifetimeMax);
  p.age = 0;
  return p;
}

void ParticleSystem::update(double dt) {
  // 1. Emit.
  const int count = emissionCount(dt);
  for (int k = 0; k < count; ++k) particles.push_back(emitParticle(emitter, rng));

  for (Particle& p : particles) {
    // 2. Forces (gravity, buoyancy, drag, collisions) and symplectic Euler.
    p.f = externalForce(p);
    p.v += p.f / p.m * dt;
    p.x += p.v * dt;
    // 3. Cool towards the air: dT/dt = -k_c (T - T_air).
    p.temperature -= coolingRate * (p.temperature - env.airTemperature) * dt;
    // 4. Age.
    p.age += dt;
  }

  // 4. Remove the particles that have lived their lifetime.
  particles.erase(std::remove_if(particles.begin(), particles.end(),
                                 [](const Particle& p) { return p.age >= p.lifetime; }),
                  particles.end());
}

}  // namespace a6
