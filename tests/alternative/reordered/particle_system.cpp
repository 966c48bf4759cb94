// Alternative (correct) task 5: the same particle system with another order of random draws
// (lifetime and temperature first, then velocity, then position, by polar coordinates), the
// exact exponential cooling, integration back to front, and removal by swap-and-pop.
#include "a6/particle_system.h"

#include <cmath>

namespace a6 {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Particle emitParticle(const EmitterSpec& spec, Random& rng) {
  Particle p;
  p.lifetime = rng.uniform(spec.lifetimeMin, spec.lifetimeMax);
  p.temperature = rng.uniform(spec.temperatureMin, spec.temperatureMax);
  const double vy = rng.uniform(-spec.velocitySpread, spec.velocitySpread);
  const double vx = rng.uniform(-spec.velocitySpread, spec.velocitySpread);
  p.v = Vec2(spec.velocity.x() + vx, spec.velocity.y() + vy);
  // Uniform in the disc: the radius goes as sqrt(u) so that the area density is flat.
  const double angle = 2.0 * kPi * rng.uniform();
  const double r = spec.radius * std::sqrt(rng.uniform());
  p.x = spec.position + r * Vec2(std::cos(angle), std::sin(angle));
  p.m = spec.mass;
  p.age = 0.0;
  return p;
}

void ParticleSystem::update(double dt) {
  for (int k = emissionCount(dt); k > 0; --k) particles.push_back(emitParticle(emitter, rng));

  const double cooling = std::exp(-coolingRate * dt);
  for (std::size_t k = particles.size(); k-- > 0;) {
    Particle& p = particles[k];
    p.f = externalForce(p);
    p.v += (dt / p.m) * p.f;
    p.x += dt * p.v;
    p.temperature = env.airTemperature + (p.temperature - env.airTemperature) * cooling;
    p.age += dt;
    // Every particle after k is done already: the last one may take this place.
    if (p.age >= p.lifetime) {
      particles[k] = particles.back();
      particles.pop_back();
    }
  }
}

}  // namespace a6
