// A correct task 7 written another way: the Jacobians from the projector P = I - e eᵀ, the
// springs assembled before the masses and in reverse order, the pinned particles fixed first,
// each spring's two right-hand-side terms added as one vector per particle.
#include "a6/implicit.h"

#include "a6/mass_spring_system.h"

namespace a6 {

SpringJacobians springJacobians(const Spring& s) {
  const Vec2 d = s.p2->x - s.p1->x;
  const double length = d.norm();
  if (!(length >= 1e-12)) return SpringJacobians{};
  const Vec2 dir = d / length;
  const Mat2 along = dir * dir.transpose();
  const Mat2 across = Mat2::Identity() - along;
  SpringJacobians out;
  out.dfdx = -s.ks * along - s.ks * (1 - s.restLength / length) * across;
  out.dfdv = -(s.kd * along);
  return out;
}

void MassSpringSystem::stepImplicit(double dt) {
  const int count = static_cast<int>(particles.size());
  std::vector<Vec2> force(count);
  for (int k = 0; k < count; ++k) force[k] = externalForce(particles[k]);
  const std::vector<std::array<int, 2>> ends = springEnds();
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const Vec2 f = springForce(springs[k]);
    force[ends[k][1]] += f;
    force[ends[k][0]] -= f;
  }
  for (int k = 0; k < count; ++k) particles[k].f = force[k];

  ImplicitSystem system(count);
  for (int k = 0; k < count; ++k) {
    if (particles[k].pinned) system.fix(k);
  }
  std::vector<Vec2> rhs(count, Vec2::Zero());
  for (std::size_t k = springs.size(); k-- > 0;) {
    const int a = ends[k][0], b = ends[k][1];
    const SpringJacobians jac = springJacobians(springs[k]);
    const Mat2 block = dt * (jac.dfdv + dt * jac.dfdx);
    system.addBlock(b, a, block);
    system.addBlock(a, b, block);
    system.addBlock(a, a, -block);
    system.addBlock(b, b, -block);
    const Vec2 term = jac.dfdx * (particles[b].v - particles[a].v) * (dt * dt);
    rhs[b] += term;
    rhs[a] -= term;
  }
  for (int k = 0; k < count; ++k) {
    system.addBlock(k, k, Mat2::Identity() * particles[k].m);
    system.addToB(k, rhs[k] + force[k] * dt);
  }

  const std::vector<Vec2> change = system.solve();
  for (int k = 0; k < count; ++k) {
    if (particles[k].pinned) continue;
    particles[k].v = particles[k].v + change[k];
    particles[k].x = particles[k].x + dt * particles[k].v;
  }
}

}  // namespace a6
