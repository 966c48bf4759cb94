// The scales tolerances are relative to (suite.h): the size of the inputs each value is computed
// from, shared by the public and the hidden checks.
#pragma once

#include <algorithm>

#include "a6/forces.h"
#include "a6/particle.h"

namespace a6::test {

/// A spring force's scale: ks·max(l, l0) + kd·|v2 - v1|, the largest its two terms can be.
inline double springForceScale(const Vec2& x1, const Vec2& x2, const Vec2& v1, const Vec2& v2,
                               double restLength, double ks, double kd) {
  return std::abs(ks) * std::max((x2 - x1).norm(), std::abs(restLength)) +
         std::abs(kd) * (v2 - v1).norm();
}

/// The scale of the forces on one particle: m|g| + |b|·max(|T|, |T_air|) + k_d|v| + k_r times
/// the depths it is in (`contactDepth` too, the contact given to repulsionForce). Buoyancy is
/// measured by the temperatures, not their difference: float rounds each of them.
inline double externalForceScale(const Particle& p, const Environment& env,
                                 double contactDepth = 0) {
  double depths = std::max(contactDepth, 0.0);
  for (const HalfPlane& plane : env.planes) depths += std::max(contactWith(plane, p.x).depth, 0.0);
  for (const CircleObstacle& c : env.circles) depths += std::max(contactWith(c, p.x).depth, 0.0);
  return p.m * env.gravity.norm() +
         std::abs(env.buoyancy) * std::max(std::abs(p.temperature), std::abs(env.airTemperature)) +
         std::abs(env.drag) * p.v.norm() + std::abs(env.repulsion) * depths;
}

}  // namespace a6::test
