// Task 5: the particle system (slides "Particles", "Particle systems").
#pragma once

#include <cstdint>
#include <vector>

#include "a6/force_model.h"
#include "a6/forces.h"
#include "a6/random.h"

namespace a6 {

/// Where and how particles are born. Each range [min, max] is drawn uniformly.
struct EmitterSpec {
  Vec2 position = Vec2(0, 0);   ///< centre of the emitter, m
  double radius = 0.1;          ///< particles start uniformly in a disc of this radius, m
  Vec2 velocity = Vec2(0, 1);   ///< mean initial velocity, m/s
  double velocitySpread = 0.2;  ///< each velocity component gets a uniform offset in [-s, s], m/s
  double mass = 0.001;          ///< kg
  double temperatureMin = 600;  ///< K
  double temperatureMax = 900;  ///< K
  double lifetimeMin = 1.0;     ///< s
  double lifetimeMax = 2.0;     ///< s
  double rate = 200;            ///< particles per second
};

/// TASK 5 (particle_system.cpp). One new particle with a randomized initial state drawn from
/// rng: position in the emitter's disc, velocity = spec.velocity + a uniform offset per
/// component, temperature and lifetime uniform in their ranges, age 0, mass spec.mass.
Particle emitParticle(const EmitterSpec& spec, Random& rng);

/// A fountain or fire: an emitter, free particles (no springs) and their environment.
class ParticleSystem {
 public:
  explicit ParticleSystem(std::uint64_t seed = 1) : rng(seed) {}

  EmitterSpec emitter;
  Environment env;
  double coolingRate = 1.0;  ///< k_c in dT/dt = -k_c (T - T_air), 1/s
  std::vector<Particle> particles;
  Random rng;

  /// TASK 5 (particle_system.cpp). One step of dt seconds:
  ///   1. emit emissionCount(dt) new particles with emitParticle(emitter, rng),
  ///   2. for each particle: f = externalForce(p); v += f/m dt; x += v dt (symplectic Euler),
  ///   3. cool towards the air: T += -k_c (T - T_air) dt (or the exact exponential),
  ///   4. age += dt, and remove every particle whose age >= lifetime.
  void update(double dt);

  /// Framework: how many particles to emit in a step of dt seconds at emitter.rate; carries
  /// the fractional part over to the next step, so the long-run rate is exact.
  int emissionCount(double dt);
  /// The external force on p: your externalForce(p, env) unless swapped (see force_model.h).
  Vec2 externalForce(const Particle& p) const;
  void setForceModel(ForceModel model) { forceModel_ = std::move(model); }

 private:
  ForceModel forceModel_;
  double emissionDebt_ = 0;
};

}  // namespace a6
