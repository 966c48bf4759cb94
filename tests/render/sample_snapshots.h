// Hand-made snapshots for the renderer's tests and sample images: no student code, no scenes,
// every position chosen so that the tests can say which colour each pixel must have.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include "scenes/snapshot.h"

namespace a6::test {

/// A 4 m x 4 m view centred on the origin: at 256x256, 64 px per metre, and world (x, y) is
/// pixel (128 + 64x, 128 - 64y). Every object sits well apart from the others:
///   particles A(-1.5, 1.5) pinned, B(-0.5, 1.5), C(-1.5, 0.5), D(-0.5, 0.5),
///   F(0.25, 0.75) free at air temperature, H(0.75, 0.75) hot (900 K);
///   springs A-B structural, A-D shear, C-D bending, B-D other (rest lengths = lengths);
///   floor y < -1.5; circle obstacle at (1.2, -0.8), r 0.3;
///   Box2D box of body 0 around (0.5, -0.5), half size 0.25; circle of body 1 at (-0.8, -0.8),
///   r 0.3, angle 0; a revolute joint from (0.5, -0.25) to (0.5, 0.25) between the box (centre
///   (0.5, -0.5), so a line from the centre to anchor A) and the ground (nothing beyond anchor B).
inline Snapshot testSnapshot() {
  Snapshot s;
  s.scene = "render_test";
  s.view.center = Vec2(0, 0);
  s.view.height = 4;
  s.particleRadius = 0.05;
  auto particle = [&](double x, double y, bool pinned = false, double temperature = 293.15) {
    Particle p;
    p.x = Vec2(x, y);
    p.pinned = pinned;
    p.temperature = temperature;
    s.particles.push_back(p);
    return static_cast<int>(s.particles.size()) - 1;
  };
  const int a = particle(-1.5, 1.5, true), b = particle(-0.5, 1.5), c = particle(-1.5, 0.5),
            d = particle(-0.5, 0.5);
  particle(0.25, 0.75);
  particle(0.75, 0.75, false, 900);
  auto spring = [&](int i, int j, SpringType type) {
    SpringData sd;
    sd.i = i, sd.j = j, sd.type = type;
    sd.restLength = (s.particles[j].x - s.particles[i].x).norm();
    sd.ks = 100;
    s.springs.push_back(sd);
  };
  spring(a, b, SpringType::Structural);
  spring(a, d, SpringType::Shear);
  spring(c, d, SpringType::Bending);
  spring(b, d, SpringType::Other);
  s.planes.push_back(HalfPlane{Vec2(0, 1), -1.5});
  s.circles.push_back(CircleObstacle{Vec2(1.2, -0.8), 0.3});
  ShapeData box;
  box.kind = ShapeData::Kind::Polygon;
  box.body = 0;
  box.points = {Vec2(0.25, -0.75), Vec2(0.75, -0.75), Vec2(0.75, -0.25), Vec2(0.25, -0.25)};
  s.shapes.push_back(box);
  ShapeData wheel;
  wheel.kind = ShapeData::Kind::Circle;
  wheel.body = 1;
  wheel.center = Vec2(-0.8, -0.8);
  wheel.radius = 0.3;
  wheel.angle = 0;
  s.shapes.push_back(wheel);
  JointData joint{"revolute", Vec2(0.5, -0.25), Vec2(0.5, 0.25)};
  joint.centerA = Vec2(0.5, -0.5);
  joint.groundB = true;
  s.joints.push_back(joint);
  return s;
}

/// A cloth-like grid of (n+1)² particles hanging from its pinned top corners, sagging in the
/// middle (so springs are stretched near the top and compressed below), over a floor and a
/// ball. Indices as in task 4: particle (i, j) at j*(n+1)+i.
inline Snapshot clothSnapshot(int n = 10) {
  Snapshot s;
  s.scene = "cloth_sample";
  s.view.center = Vec2(0, -0.9);
  s.view.height = 2.6;
  s.particleRadius = 0.012;
  const double size = 1.6, h = size / n;
  auto index = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double u = double(i) / n, v = double(j) / n;
      Particle p;
      // Rest grid, pulled down in the middle and squeezed sideways near the bottom.
      const double sag = 0.35 * std::sin(3.14159265358979 * u) * (0.3 + v);
      p.x = Vec2(-0.5 * size + u * size * (1 - 0.12 * v), -v * size * 0.9 - sag);
      p.pinned = j == 0 && (i == 0 || i == n);
      s.particles.push_back(p);
    }
  }
  auto spring = [&](int a, int b, SpringType type, double rest) {
    SpringData sd;
    sd.i = a, sd.j = b, sd.type = type, sd.restLength = rest;
    s.springs.push_back(sd);
  };
  const double diagonal = std::sqrt(2.0) * h;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      if (i < n) spring(index(i, j), index(i + 1, j), SpringType::Structural, h);
      if (j < n) spring(index(i, j), index(i, j + 1), SpringType::Structural, h);
      if (i < n && j < n) {
        spring(index(i, j), index(i + 1, j + 1), SpringType::Shear, diagonal);
        spring(index(i + 1, j), index(i, j + 1), SpringType::Shear, diagonal);
      }
      if (i + 2 <= n) spring(index(i, j), index(i + 2, j), SpringType::Bending, 2 * h);
      if (j + 2 <= n) spring(index(i, j), index(i, j + 2), SpringType::Bending, 2 * h);
    }
  }
  s.planes.push_back(HalfPlane{Vec2(0, 1), -2.1});
  s.circles.push_back(CircleObstacle{Vec2(0.55, -1.85), 0.2});
  return s;
}

namespace sample {

inline void addPolygon(Snapshot& s, int body, std::vector<Vec2> points) {
  ShapeData shape;
  shape.kind = ShapeData::Kind::Polygon;
  shape.body = body;
  shape.points = std::move(points);
  s.shapes.push_back(shape);
}

/// A box of half sizes (hx, hy) centred on c, turned by `angle` (rad).
inline void addBox(Snapshot& s, int body, Vec2 c, double hx, double hy, double angle) {
  const Vec2 ex(std::cos(angle), std::sin(angle)), ey(-std::sin(angle), std::cos(angle));
  addPolygon(
      s, body,
      {c - hx * ex - hy * ey, c + hx * ex - hy * ey, c + hx * ex + hy * ey, c - hx * ex + hy * ey});
}

inline void addCircle(Snapshot& s, int body, Vec2 c, double r, double angle) {
  ShapeData shape;
  shape.kind = ShapeData::Kind::Circle;
  shape.body = body;
  shape.center = c;
  shape.radius = r;
  shape.angle = angle;
  s.shapes.push_back(shape);
}

/// A joint as toSnapshot fills it: anchors, the bodies' centres, which side is the ground.
inline void addJoint(Snapshot& s, const char* type, Vec2 anchorA, Vec2 anchorB, Vec2 centerA,
                     Vec2 centerB, bool groundA) {
  JointData j{type, anchorA, anchorB, centerA, centerB, groundA, false};
  s.joints.push_back(j);
}

}  // namespace sample

/// A Box2D-like picture: a ground edge and box, a pendulum (revolute), a rope (distance joint),
/// a car (polygon chassis, two wheels on wheel joints), a piston (prismatic), a mouse joint.
inline Snapshot box2dSnapshot() {
  using namespace sample;
  Snapshot s;
  s.scene = "box2d_sample";
  s.view.center = Vec2(0, 1.2);
  s.view.height = 4;
  // Ground: an edge along y = 0 and a static box.
  ShapeData edge;
  edge.kind = ShapeData::Kind::Edge;
  edge.points = {Vec2(-3, 0), Vec2(3, 0)};
  s.shapes.push_back(edge);
  addBox(s, -1, Vec2(2.2, 0.15), 0.3, 0.15, 0);
  // Pendulum: pivot (-1.5, 3), bob at angle 0.5 rad.
  const Vec2 pivot(-1.5, 3.0), bob = pivot + 0.9 * Vec2(std::sin(0.5), -std::cos(0.5));
  addCircle(s, 0, bob, 0.12, 0.5);
  addJoint(s, "revolute", pivot, pivot, Vec2(0, 0), bob, true);  // the rod: pivot to the bob
  // A tilted box hanging from a rope.
  addBox(s, 1, Vec2(-0.4, 2.0), 0.2, 0.12, 0.3);
  addJoint(s, "distance", Vec2(-0.6, 3.0), Vec2(-0.45, 2.12), Vec2(0, 0), Vec2(-0.4, 2.0), true);
  // Car: chassis and two wheels with spokes at different angles.
  addPolygon(s, 2,
             {Vec2(-0.9, 0.45), Vec2(0.1, 0.45), Vec2(0.15, 0.65), Vec2(-0.2, 0.85),
              Vec2(-0.7, 0.85), Vec2(-0.9, 0.65)});
  addCircle(s, 3, Vec2(-0.7, 0.2), 0.2, 1.0);
  addCircle(s, 4, Vec2(-0.05, 0.2), 0.2, 2.5);
  const Vec2 chassis(-0.4, 0.6);
  addJoint(s, "wheel", Vec2(-0.7, 0.2), Vec2(-0.7, 0.2), chassis, Vec2(-0.7, 0.2), false);
  addJoint(s, "wheel", Vec2(-0.05, 0.2), Vec2(-0.05, 0.2), chassis, Vec2(-0.05, 0.2), false);
  // Piston: a slider on a prismatic joint above a static base.
  addBox(s, -1, Vec2(1.2, 0.1), 0.25, 0.1, 0);
  addBox(s, 5, Vec2(1.2, 0.9), 0.15, 0.3, 0);
  addJoint(s, "prismatic", Vec2(1.2, 0.2), Vec2(1.2, 0.9), Vec2(0, 0), Vec2(1.2, 0.9), true);
  // A box dragged by the mouse.
  addBox(s, 0, Vec2(0.9, 2.4), 0.2, 0.2, -0.4);
  addJoint(s, "mouse", Vec2(1.6, 2.9), Vec2(1.0, 2.5), Vec2(0, 0), Vec2(0.9, 2.4), true);
  return s;
}

/// A fire-like plume: particles rising from an emitter at (0, 0), hottest at the bottom (900 K)
/// and cooling towards the air (293.15 K) as they rise, above a floor with a round obstacle.
/// Positions come from a fixed linear congruential sequence: the same picture every time.
inline Snapshot fireSnapshot(int count = 400) {
  Snapshot s;
  s.scene = "fire_sample";
  s.view.center = Vec2(0, 1.3);
  s.view.height = 3;
  s.particleRadius = 0.025;
  unsigned state = 12345;
  auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / 16777216.0;
  };
  for (int k = 0; k < count; ++k) {
    const double t = uniform();  // the particle's age as a fraction of its life
    Particle p;
    p.x = Vec2((uniform() - 0.5) * (0.15 + 0.9 * t), 0.05 + 2.4 * t);
    p.temperature = 293.15 + (900 - 293.15) * std::pow(1 - t, 1.5);
    s.particles.push_back(p);
  }
  s.planes.push_back(HalfPlane{Vec2(0, 1), 0});
  s.circles.push_back(CircleObstacle{Vec2(0.6, 1.6), 0.15});
  return s;
}

}  // namespace a6::test
