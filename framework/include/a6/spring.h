// Task 1: the spring (slides "Spring forces", "Spring implementation").
#pragma once

#include "a6/particle.h"

namespace a6 {

/// What a spring is for; the cloth builder (task 4) tags its springs, the renderer colours them.
enum class SpringType { Structural, Shear, Bending, Other };

/// A damped spring between two particles, as on the slide "Spring implementation".
///
/// The spring does not own its particles: p1 and p2 point into a system's particle storage,
/// which keeps them valid while particles are added (see MassSpringSystem::particles).
struct Spring {
  Particle* p1 = nullptr;  ///< first particle (receives -computeForce())
  Particle* p2 = nullptr;  ///< second particle (receives +computeForce())
  double restLength = 0;   ///< rest length l0, m
  double ks = 0;           ///< spring constant, N/m
  double kd = 0;           ///< damping coefficient, N·s/m
  SpringType type = SpringType::Other;

  /// TASK 1 (spring.cpp). The force on p2, in N, in the world frame; p1 gets the opposite.
  ///   d = x2 - x1, l = |d|, e = d / l, v_rel = (v2 - v1)·e
  ///   f2 = -ks (l - l0) e - kd v_rel e
  /// Coincident particles (l below 1e-12 m) give zero force, never NaN.
  Vec2 computeForce() const;
};

}  // namespace a6
