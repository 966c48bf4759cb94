// WRONG VERSION (task 3, written blind from the handout): The position is updated before the
// velocity (x += v dt with the OLD v, then v += f/m dt): explicit Euler instead of symplectic
// Euler.
// Task 3 — time stepping
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  for (Particle& p : particles) p.f = externalForce(p);
  for (const Spring& s : springs) {
    const Vec2 f = springForce(s);
    s.p2->f += f;
    s.p1->f -= f;
  }
  for (Particle& p : particles) {
    if (p.pinned) continue;
    p.x += p.v * dt;
    p.v += p.f / p.m * dt;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  const double h = frameDt / substeps;
  for (int k = 0; k < substeps; ++k) step(h);
}

}  // namespace a6
