// CORRECT ALTERNATIVE (task 3): symplectic Euler with float intermediates, springs looped in
// reverse order.
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  const float h = float(dt);
  for (Particle& p : particles) p.f = externalForce(p);
  for (auto s = springs.rbegin(); s != springs.rend(); ++s) {
    const Eigen::Vector2f f = springForce(*s).cast<float>();
    s->p1->f -= f.cast<double>();
    s->p2->f += f.cast<double>();
  }
  for (Particle& p : particles) {
    if (p.pinned) continue;
    const Eigen::Vector2f a = p.f.cast<float>() / float(p.m);
    p.v += (a * h).cast<double>();
    p.x += (p.v.cast<float>() * h).cast<double>();
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  const float h = float(frameDt) / float(substeps);
  for (int k = 0; k < substeps; ++k) step(h);
}

}  // namespace a6
