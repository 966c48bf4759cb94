// CORRECT ALTERNATIVE (task 7): the Jacobians and the step's blocks and right-hand side computed
// in float, handed to ImplicitSystem (which solves in double).
#include "a6/implicit.h"

#include "a6/mass_spring_system.h"

namespace a6 {

SpringJacobians springJacobians(const Spring& s) {
  const Eigen::Vector2f d = (s.p2->x - s.p1->x).cast<float>();
  const float l = d.norm();
  if (l < 1e-6f) return {};  // coincident particles: no direction
  const Eigen::Vector2f e = d / l;
  const Eigen::Matrix2f eeT = e * e.transpose();
  const Eigen::Matrix2f across = Eigen::Matrix2f::Identity() - eeT;
  SpringJacobians j;
  j.dfdx = (-float(s.ks) * (eeT + (1.0f - float(s.restLength) / l) * across)).cast<double>();
  j.dfdv = (-float(s.kd) * eeT).cast<double>();
  return j;
}

void MassSpringSystem::stepImplicit(double dt) {
  const int count = static_cast<int>(particles.size());
  for (Particle& p : particles) p.f = externalForce(p);
  for (const Spring& s : springs) {
    const Vec2 f = springForce(s);
    s.p2->f += f;
    s.p1->f -= f;
  }
  const float h = float(dt);
  ImplicitSystem system(count);
  for (int i = 0; i < count; ++i) {
    system.addBlock(i, i, particles[i].m * Mat2::Identity());
    system.addToB(i, (h * particles[i].f.cast<float>()).cast<double>());
  }
  const std::vector<std::array<int, 2>> ends = springEnds();
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const auto [i, j] = ends[k];
    const SpringJacobians jac = springJacobians(springs[k]);
    const Eigen::Matrix2f dfdx = jac.dfdx.cast<float>();
    const Mat2 K = (h * jac.dfdv.cast<float>() + h * h * dfdx).cast<double>();
    system.addBlock(i, i, -K);
    system.addBlock(j, j, -K);
    system.addBlock(i, j, K);
    system.addBlock(j, i, K);
    const Eigen::Vector2f v = (particles[j].v - particles[i].v).cast<float>();
    const Vec2 dfdxV = (h * h * (dfdx * v)).cast<double>();
    system.addToB(j, dfdxV);
    system.addToB(i, -dfdxV);
  }
  for (int i = 0; i < count; ++i) {
    if (particles[i].pinned) system.fix(i);
  }
  const std::vector<Vec2> dv = system.solve();
  for (int i = 0; i < count; ++i) {
    Particle& p = particles[i];
    if (p.pinned) continue;
    p.v += dv[i];
    p.x += p.v * dt;
  }
}

}  // namespace a6
