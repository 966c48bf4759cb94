// WRONG VERSION (task 3, written blind from the handout): The spring force is applied with swapped
// signs: p1 gets +f and p2 gets -f (instead of p2 += f, p1 -= f), so every spring pushes where it
// should pull.
// Task 3 — time stepping
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  for (Particle& p : particles) p.f = externalForce(p);
  for (const Spring& s : springs) {
    const Vec2 f = springForce(s);
    s.p1->f += f;
    s.p2->f -= f;
  }
  for (Particle& p : particles) {
    if (p.pinned) continue;
    p.v += p.f / p.m * dt;
    p.x += p.v * dt;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  const double h = frameDt / substeps;
  for (int k = 0; k < substeps; ++k) step(h);
}

}  // namespace a6
