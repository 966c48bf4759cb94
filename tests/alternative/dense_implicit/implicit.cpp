// A correct task 7 written another way, as a student with a small cloth might: no
// ImplicitSystem, but a dense matrix over the free particles only (a pinned particle's Δv is zero,
// so its rows and columns are simply left out) solved by Eigen's dense LU; the Jacobian written
// as -ks ((1 - l0/l) I + (l0/l) e eᵀ); the forces kept in a local array; each spring's rows
// filled particle by particle.
#include "a6/implicit.h"

#include <Eigen/Dense>
#include <deque>

#include "a6/mass_spring_system.h"

namespace a6 {

SpringJacobians springJacobians(const Spring& s) {
  const Vec2 d = s.p2->x - s.p1->x;
  const double lengthSquared = d.dot(d);
  SpringJacobians jac;
  if (lengthSquared < 1e-24) return jac;
  const double ratio = s.restLength / std::sqrt(lengthSquared);
  const Mat2 projector = d * d.transpose() / lengthSquared;
  jac.dfdx = -s.ks * ((1 - ratio) * Mat2::Identity() + ratio * projector);
  jac.dfdv = -s.kd * projector;
  return jac;
}

namespace {

// The row (and column) of each free particle's x entry in the dense system; -1 for a pinned one.
std::vector<int> freeRows(const std::deque<Particle>& particles, int* size) {
  std::vector<int> row(particles.size(), -1);
  *size = 0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles[i].pinned) row[i] = (*size += 2) - 2;
  }
  return row;
}

}  // namespace

void MassSpringSystem::stepImplicit(double dt) {
  const int count = static_cast<int>(particles.size());
  std::vector<Vec2> force(count);
  for (int i = 0; i < count; ++i) force[i] = externalForce(particles[i]);
  const std::vector<std::array<int, 2>> ends = springEnds();
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const Vec2 f = springForce(springs[k]);
    force[ends[k][0]] -= f;
    force[ends[k][1]] += f;
  }
  for (int i = 0; i < count; ++i) particles[i].f = force[i];

  int size = 0;
  const std::vector<int> row = freeRows(particles, &size);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(size);
  for (int i = 0; i < count; ++i) {
    if (row[i] < 0) continue;
    a.block<2, 2>(row[i], row[i]) += particles[i].m * Mat2::Identity();
    b.segment<2>(row[i]) += dt * force[i];
  }
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const SpringJacobians jac = springJacobians(springs[k]);
    const Mat2 dfdxStep = dt * dt * jac.dfdx;
    const Mat2 k2 = dt * jac.dfdv + dfdxStep;  // ∂(h f2) / ∂Δv2, with x's change h Δv
    const Vec2 relative = particles[ends[k][1]].v - particles[ends[k][0]].v;
    // Particle `self` feels sign * f2: by its own Δv the derivative is -K, by the other's +K.
    for (const int side : {0, 1}) {
      const int self = ends[k][side], other = ends[k][1 - side];
      if (row[self] < 0) continue;
      const double sign = side == 1 ? 1.0 : -1.0;
      a.block<2, 2>(row[self], row[self]) -= k2;
      if (row[other] >= 0) a.block<2, 2>(row[self], row[other]) += k2;
      b.segment<2>(row[self]) += sign * (dfdxStep * relative);
    }
  }

  const Eigen::VectorXd dv = a.partialPivLu().solve(b);
  for (int i = 0; i < count; ++i) {
    if (row[i] < 0) continue;
    particles[i].v += dv.segment<2>(row[i]);
    particles[i].x += dt * particles[i].v;
  }
}

}  // namespace a6
