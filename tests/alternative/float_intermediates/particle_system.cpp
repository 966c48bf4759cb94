// CORRECT ALTERNATIVE (task 5): the particle system with float intermediates.
#include "a6/particle_system.h"

#include <algorithm>

namespace a6 {

Particle emitParticle(const EmitterSpec& spec, Random& rng) {
  Particle p;
  p.x = spec.position + rng.inDisc(spec.radius);
  const float vx = float(rng.uniform(-spec.velocitySpread, spec.velocitySpread));
  const float vy = float(rng.uniform(-spec.velocitySpread, spec.velocitySpread));
  p.v = spec.velocity + Vec2(vx, vy);
  p.m = spec.mass;
  p.temperature = float(rng.uniform(spec.temperatureMin, spec.temperatureMax));
  p.lifetime = float(rng.uniform(spec.lifetimeMin, spec.lifetimeMax));
  p.age = 0;
  return p;
}

void ParticleSystem::update(double dt) {
  const float h = float(dt);
  const int count = emissionCount(dt);
  for (int k = 0; k < count; ++k) particles.push_back(emitParticle(emitter, rng));
  for (Particle& p : particles) {
    p.f = externalForce(p);
    const Eigen::Vector2f a = p.f.cast<float>() / float(p.m);
    p.v += (a * h).cast<double>();
    p.x += (p.v.cast<float>() * h).cast<double>();
    p.temperature -= float(coolingRate) * (float(p.temperature) - float(env.airTemperature)) * h;
    p.age += h;
  }
  particles.erase(std::remove_if(particles.begin(), particles.end(),
                                 [](const Particle& p) { return p.age >= p.lifetime; }),
                  particles.end());
}

}  // namespace a6
