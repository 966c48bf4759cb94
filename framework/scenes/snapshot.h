// What a scene looks like at one instant, as plain data: what the renderer draws, what the
// probe returns to the grader, what golden images are rendered from.
//
// The renderer draws snapshots, never scenes: it knows nothing of springs' physics or Box2D.
#pragma once

#include <string>
#include <vector>

#include "a6/forces.h"
#include "a6/spring.h"

namespace a6 {

/// A spring as data: particle indices instead of pointers.
struct SpringData {
  int i = 0, j = 0;  ///< indices of p1 and p2
  double restLength = 0, ks = 0, kd = 0;
  SpringType type = SpringType::Other;
};

/// A Box2D fixture in the world frame.
struct ShapeData {
  enum class Kind { Circle, Polygon, Edge } kind = Kind::Polygon;
  int body = -1;               ///< index of its body in the scene; -1 for the ground
  std::vector<Vec2> points;    ///< polygon vertices (counter-clockwise) or the edge's two ends, m
  Vec2 center = Vec2::Zero();  ///< circle centre, m
  double radius = 0;           ///< circle radius, m
  double angle = 0;            ///< body angle, rad (to draw a circle's spoke)
};

/// A joint, drawn as Box2D's testbed draws it: centreA - anchorA - anchorB - centreB (the
/// ground's side is left out, so a pendulum shows its rod from the pivot to the bob).
struct JointData {
  std::string type;  ///< revolute, prismatic, distance, wheel, mouse, other
  Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();  ///< world, m
  Vec2 centerA = Vec2::Zero(), centerB = Vec2::Zero();  ///< the bodies' origins, world, m
  bool groundA = false, groundB = false;  ///< the body on that side is static (the ground)
};

/// The part of the world a picture shows: a fixed camera per scene.
struct View {
  Vec2 center = Vec2(0, 0);  ///< m, world point at the image centre
  double height = 4;         ///< m of world shown from bottom to top (width follows the aspect)
};

/// Energies of a scene, J. Potential energy = gravity (measured from y = 0) + every spring
/// (mass-spring springs, penalty contacts, Box2D joint springs and the mouse joint).
struct SceneEnergy {
  double kinetic = 0;
  double potential = 0;
  double total() const { return kinetic + potential; }
};

struct Snapshot {
  std::string scene;
  double time = 0;  ///< s since the scene started
  std::vector<Particle> particles;
  double particleRadius = 0.02;  ///< m, drawing size of a particle
  std::vector<SpringData> springs;
  std::vector<HalfPlane> planes;
  std::vector<CircleObstacle> circles;
  std::vector<ShapeData> shapes;
  std::vector<JointData> joints;
  View view;
};

}  // namespace a6
