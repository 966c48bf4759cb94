// WRONG VERSION (task 3): a pinned particle's velocity is kept, but its position still moves
// with it (x += v dt for every particle): a pin at rest stays, a moving pin drifts.
// Task 3 — time stepping (slides "Time stepping", "Instability").
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  // 1. Initialise each force with the external forces.
  for (Particle& p : particles) p.f = externalForce(p);

  // 2. Add every spring's force to both of its particles.
  for (const Spring& s : springs) {
    const Vec2 f = springForce(s);
    s.p2->f += f;
    s.p1->f -= f;
  }

  // 3. Symplectic Euler: velocity first, then position with the new velocity.
  for (Particle& p : particles) {
    if (!p.pinned) p.v += p.f / p.m * dt;
    p.x += p.v * dt;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  // n substeps of frameDt / n: smaller steps keep stiff springs stable.
  const double dt = frameDt / substeps;
  for (int k = 0; k < substeps; ++k) step(dt);
}

}  // namespace a6
