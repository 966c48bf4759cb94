// Task 7 (extra credit) — implicit Euler (slide "Instability": "a more robust integration
// scheme"; Baraff and Witkin, "Large steps in cloth simulation", 1998).
#include "a6/implicit.h"

#include "a6/mass_spring_system.h"

namespace a6 {

SpringJacobians springJacobians(const Spring& s) {
  // Direction and length of the spring: d = x2 - x1, l = |d|, e = d / l.
  const Vec2 d = s.p2->x - s.p1->x;
  const double l = d.norm();
  if (l < 1e-12) return {};  // coincident particles: no direction
  const Vec2 e = d / l;
  const Mat2 eeT = e * e.transpose();
  const Mat2 identity = Mat2::Identity();

  // dfdx = -ks (e eᵀ + (1 - l0/l) (I - e eᵀ)),  dfdv = -kd e eᵀ.
  SpringJacobians j;
  j.dfdx = -s.ks * (eeT + (1 - s.restLength / l) * (identity - eeT));
  j.dfdv = -s.kd * eeT;
  return j;
}

void MassSpringSystem::stepImplicit(double dt) {
  const int count = static_cast<int>(particles.size());

  // 1. The forces, as in step(): external, then every spring's on both of its particles.
  for (Particle& p : particles) p.f = externalForce(p);
  for (const Spring& s : springs) {
    const Vec2 f = springForce(s);
    s.p2->f += f;
    s.p1->f -= f;
  }

  // 2. A = M - dt ∂f/∂v - dt² ∂f/∂x and b = dt (f + dt ∂f/∂x v), particle by particle...
  ImplicitSystem& system = implicitSystem();
  for (int i = 0; i < count; ++i) {
    const Particle& p = particles[i];
    system.addBlock(i, i, p.m * Mat2::Identity());
    system.addToB(i, dt * p.f);
  }
  // ...and spring by spring: K = dt ∂f2/∂v2 + dt² ∂f2/∂x2 on the diagonal blocks, -K off it.
  const std::vector<std::array<int, 2>> ends = springEnds();
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const auto [i, j] = ends[k];
    const SpringJacobians jac = springJacobians(springs[k]);
    const Mat2 K = dt * jac.dfdv + dt * dt * jac.dfdx;
    system.addBlock(i, i, -K);
    system.addBlock(j, j, -K);
    system.addBlock(i, j, K);
    system.addBlock(j, i, K);
    // dt² ∂f/∂x v: the spring's force on p2 changes by dfdx (v2 - v1), on p1 by the opposite.
    const Vec2 dfdxV = dt * dt * jac.dfdx * (particles[j].v - particles[i].v);
    system.addToB(j, dfdxV);
    system.addToB(i, -dfdxV);
  }

  // 3. Pinned particles keep their velocity: Δv = 0.
  for (int i = 0; i < count; ++i) {
    if (particles[i].pinned) system.fix(i);
  }

  // 4. Solve for Δv; then v += Δv and x += v dt with the new v.
  const std::vector<Vec2> dv = system.solve();
  for (int i = 0; i < count; ++i) {
    Particle& p = particles[i];
    if (p.pinned) continue;
    p.v += dv[i];
    p.x += p.v * dt;
  }
}

}  // namespace a6
