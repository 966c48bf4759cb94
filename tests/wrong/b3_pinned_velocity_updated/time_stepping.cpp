// WRONG VERSION (task 3, written blind from the handout): Pinned particles are skipped only for the
// position update: their velocity still gets v += f/m dt, so a pinned particle keeps a growing
// velocity (which feeds the springs' damping) although it does not move.
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
    p.v += p.f / p.m * dt;
    if (p.pinned) continue;
    p.x += p.v * dt;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  const double h = frameDt / substeps;
  for (int k = 0; k < substeps; ++k) step(h);
}

}  // namespace a6
