// Task 2: the forces (slide "Some forces") and the obstacles they collide with.
#pragma once

#include <vector>

#include "a6/particle.h"

namespace a6 {

/// A solid half-plane: the points x with normal·x < offset are inside the solid.
struct HalfPlane {
  Vec2 normal = Vec2(0, 1);  ///< unit normal, pointing out of the solid into free space
  double offset = 0;         ///< signed distance of the boundary from the origin along normal, m
};

/// A solid disc.
struct CircleObstacle {
  Vec2 center = Vec2::Zero();  ///< m, world frame
  double radius = 1;           ///< m
};

/// How far a point has sunk into an obstacle, given by the framework.
struct Contact {
  double depth = 0;          ///< penetration depth, m; > 0 only when the point is inside
  Vec2 normal = Vec2(0, 1);  ///< unit normal pointing out of the obstacle
};

/// Framework: the contact of point x with an obstacle (depth <= 0 when x is outside).
Contact contactWith(const HalfPlane& plane, const Vec2& x);
Contact contactWith(const CircleObstacle& circle, const Vec2& x);

/// Everything around the particles: the parameters of the forces of task 2.
struct Environment {
  Vec2 gravity = Vec2(0, -9.81);        ///< gravitational acceleration g, m/s²
  double airTemperature = 293.15;       ///< T_air, K
  double buoyancy = 0;                  ///< buoyancy coefficient b, N/K
  double drag = 0;                      ///< drag coefficient k_d, N·s/m
  double repulsion = 0;                 ///< collision stiffness k_r, N/m
  std::vector<HalfPlane> planes;        ///< solid half-planes (floors, walls)
  std::vector<CircleObstacle> circles;  ///< solid discs
};

// TASK 2 (forces.cpp). Each returns a force in N, in the world frame.

/// Gravity: m g.
Vec2 gravityForce(const Particle& p, const Vec2& g);
/// Buoyancy: b (T - T_air) (0, 1). Hot particles rise, cold ones sink.
Vec2 buoyancyForce(const Particle& p, double b, double airTemperature);
/// Drag: -k_d v.
Vec2 dragForce(const Particle& p, double kd);
/// Penalty collision: k_r d n while the point is inside (depth d > 0), zero otherwise.
Vec2 repulsionForce(const Contact& contact, double kr);
/// The sum of all of the above for one particle: gravity, buoyancy, drag, and the repulsion of
/// every obstacle in env (use contactWith for each).
Vec2 externalForce(const Particle& p, const Environment& env);

}  // namespace a6
