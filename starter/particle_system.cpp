// Task 5 — the particle system
// Slides: "Particles", "Particle systems".
//
// The emitter gives each new particle a randomized initial state; always draw from the
// framework's generator `rng` (a6/random.h) so that a run is reproducible from its seed:
//
//     x = spec.position + rng.inDisc(spec.radius)
//     v = spec.velocity + (uniform in [-s, s], uniform in [-s, s])       s = velocitySpread
//     temperature uniform in [temperatureMin, temperatureMax]
//     lifetime    uniform in [lifetimeMin, lifetimeMax]
//     m = spec.mass, age = 0
//
// The update, one step of dt seconds:
//
//     1. emit emissionCount(dt) new particles (push them onto `particles`)
//     2. for every particle: f = externalForce(p)  (gravity, buoyancy, drag, collisions)
//                            v += f / m dt;  x += v dt                 (symplectic Euler)
//     3. cool towards the air: T += -k_c (T - T_air) dt, with k_c = coolingRate
//     4. age += dt; remove every particle with age >= lifetime
//
// Done when: `ctest -R Task5` passes (tests named Task5Particles.*): the emitter's ranges and
// distributions, emission counts, hot particles rising, cooling, ageing and removal.
#include "a6/particle_system.h"

namespace a6 {

Particle emitParticle(const EmitterSpec& spec, Random& rng) {
  // TODO(task 5): the randomized initial state above.
  Particle p;
  p.x = spec.position;
  p.m = spec.mass;
  return p;
}

void ParticleSystem::update(double dt) {
  // TODO(task 5): emit, forces and integration, cooling, ageing and removal.
}

}  // namespace a6
