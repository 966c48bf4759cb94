// WRONG VERSION (task 3, written blind from the handout): advance() calls step(frameDt) substeps
// times instead of step(frameDt / substeps), so it advances substeps x frameDt per frame.
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
    p.v += p.f / p.m * dt;
    p.x += p.v * dt;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  const double h = frameDt;
  for (int k = 0; k < substeps; ++k) step(h);
}

}  // namespace a6
