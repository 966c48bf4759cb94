// The particle: the state every task shares.
//
// Conventions (all tasks): SI units, a 2D world frame with x to the right and y up,
// gravity along -y. Particle state is double precision.
#pragma once

#include <Eigen/Core>
#include <limits>

namespace a6 {

using Vec2 = Eigen::Vector2d;

/// One point mass. Plain data: copy it freely; the systems own their particles.
struct Particle {
  Vec2 x = Vec2::Zero();  ///< position in the world frame, m
  Vec2 v = Vec2::Zero();  ///< velocity in the world frame, m/s
  Vec2 f = Vec2::Zero();  ///< force accumulated during the current step, N
  double m = 1.0;         ///< mass, kg (always > 0)
  bool pinned = false;    ///< a pinned particle never moves: x and v stay as they are

  // Used by the particle system (task 5); the mass-spring tasks ignore them.
  double temperature = 293.15;                                ///< temperature, K
  double age = 0.0;                                           ///< time since emission, s
  double lifetime = std::numeric_limits<double>::infinity();  ///< removed once age >= lifetime, s
};

}  // namespace a6
