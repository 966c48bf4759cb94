// WRONG VERSION (task 7, written blind from the handout): The solved Δv is used as the new velocity
// (v = dv[i]) instead of being added to it (v += dv[i]).
// Task 7 (extra credit) — implicit Euler
#include "a6/implicit.h"

#include "a6/mass_spring_system.h"

namespace a6 {

SpringJacobians springJacobians(const Spring& s) {
  SpringJacobians J;
  const Vec2 d = s.p2->x - s.p1->x;
  const double l = d.norm();
  if (l < 1e-12) return J;
  const Vec2 e = d / l;
  const Mat2 eeT = e * e.transpose();
  const Mat2 I = Mat2::Identity();
  J.dfdx = -s.ks * (eeT + (1.0 - s.restLength / l) * (I - eeT));
  J.dfdv = -s.kd * eeT;
  return J;
}

void MassSpringSystem::stepImplicit(double dt) {
  // a. forces, as in step().
  for (Particle& p : particles) p.f = externalForce(p);
  for (const Spring& s : springs) {
    const Vec2 f = springForce(s);
    s.p2->f += f;
    s.p1->f -= f;
  }

  // b. assemble.
  const int n = static_cast<int>(particles.size());
  ImplicitSystem sys(n);
  for (int i = 0; i < n; ++i) {
    const Particle& p = particles[i];
    sys.addBlock(i, i, p.m * Mat2::Identity());
    sys.addToB(i, dt * p.f);
  }
  const auto ends = springEnds();
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const int i = ends[k][0];
    const int j = ends[k][1];
    const SpringJacobians J = springJacobians(springs[k]);
    const Mat2 K = dt * J.dfdv + dt * dt * J.dfdx;
    sys.addBlock(i, i, -K);
    sys.addBlock(j, j, -K);
    sys.addBlock(i, j, K);
    sys.addBlock(j, i, K);
    const Vec2 dvij = particles[j].v - particles[i].v;
    const Vec2 bx = dt * dt * (J.dfdx * dvij);
    sys.addToB(j, bx);
    sys.addToB(i, -bx);
  }

  // c. pins.
  for (int i = 0; i < n; ++i)
    if (particles[i].pinned) sys.fix(i);

  // d. solve and update.
  const std::vector<Vec2> dv = sys.solve();
  for (int i = 0; i < n; ++i) {
    Particle& p = particles[i];
    if (p.pinned) continue;
    p.v = dv[i];
    p.x += p.v * dt;
  }
}

}  // namespace a6
