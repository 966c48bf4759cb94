// Alternative (correct) task 3: the same symplectic Euler step with other loop orders:
// particles initialised back to front, springs accumulated in reverse order (p1 first), and
// the update written as v += (dt / m) f.
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  for (std::size_t k = particles.size(); k-- > 0;) {
    particles[k].f = externalForce(particles[k]);
  }

  for (auto s = springs.rbegin(); s != springs.rend(); ++s) {
    const Vec2 f2 = springForce(*s);
    s->p1->f -= f2;
    s->p2->f += f2;
  }

  for (std::size_t k = particles.size(); k-- > 0;) {
    Particle& p = particles[k];
    if (p.pinned) continue;
    const double dtOverM = dt / p.m;
    p.v += dtOverM * p.f;
    p.x += dt * p.v;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  for (int remaining = substeps; remaining > 0; --remaining) step(frameDt / substeps);
}

}  // namespace a6
