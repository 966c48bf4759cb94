#include "render/geometry.h"

#include <algorithm>
#include <cmath>

#include "render/palette.h"
#include "render/view_transform.h"

namespace a6 {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Segments for a circle of `radiusPx` pixels: the chords stay within a quarter pixel of the arc.
int circleSegments(double radiusPx) {
  if (!(radiusPx > 1)) return 16;
  const double n = kPi / std::acos(std::max(1.0 - 0.25 / radiusPx, -1.0));
  return std::clamp(static_cast<int>(std::ceil(n)), 16, 256);
}

// Emits triangles in world coordinates; converts each vertex to NDC once.
class Painter {
 public:
  Painter(const ViewTransform& view, std::vector<Vertex>& out) : view_(view), out_(out) {}

  /// Pixels to metres.
  double px(double pixels) const { return pixels * view_.metersPerPixel(); }

  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, Rgba color) {
    // An exploded simulation (NaN, or beyond float range): skip the triangle.
    Vertex v[3];
    int k = 0;
    for (const Vec2* p : {&a, &b, &c}) {
      const Vec2 ndc = view_.toNdc(*p);
      v[k] = Vertex{static_cast<float>(ndc.x()),
                    static_cast<float>(ndc.y()),
                    color.r,
                    color.g,
                    color.b,
                    color.a};
      if (!std::isfinite(v[k].x) || !std::isfinite(v[k].y)) return;
      ++k;
    }
    out_.insert(out_.end(), v, v + 3);
  }

  void quad(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Rgba color) {
    triangle(a, b, c, color);
    triangle(a, c, d, color);
  }

  /// A convex polygon, as a fan.
  void convex(const std::vector<Vec2>& points, Rgba color) {
    for (size_t k = 2; k < points.size(); ++k) triangle(points[0], points[k - 1], points[k], color);
  }

  void disc(const Vec2& center, double radius, int segments, Rgba color) {
    if (!(radius > 0)) return;
    Vec2 previous = center + Vec2(radius, 0);
    for (int k = 1; k <= segments; ++k) {
      const double angle = 2 * kPi * k / segments;
      const Vec2 next = k == segments
                            ? Vec2(center + Vec2(radius, 0))
                            : Vec2(center + radius * Vec2(std::cos(angle), std::sin(angle)));
      triangle(center, previous, next, color);
      previous = next;
    }
  }

  /// The annulus between two radii.
  void ring(const Vec2& center, double inner, double outer, int segments, Rgba color) {
    inner = std::max(inner, 0.0);
    if (!(outer > inner)) return;
    for (int k = 0; k < segments; ++k) {
      const double a0 = 2 * kPi * k / segments, a1 = 2 * kPi * ((k + 1) % segments) / segments;
      const Vec2 e0(std::cos(a0), std::sin(a0)), e1(std::cos(a1), std::sin(a1));
      quad(center + inner * e0, center + outer * e0, center + outer * e1, center + inner * e1,
           color);
    }
  }

  /// A straight line `width` metres thick, with square (butt) ends at a and b.
  void line(const Vec2& a, const Vec2& b, double width, Rgba color) {
    const Vec2 d = b - a;
    const double length = d.norm();
    if (!(length > 1e-12) || !(width > 0)) return;
    const Vec2 n = Vec2(-d.y(), d.x()) * (0.5 * width / length);
    quad(a - n, b - n, b + n, a + n, color);
  }

  /// A line with round ends (and so round joins when lines share ends).
  void roundLine(const Vec2& a, const Vec2& b, double width, Rgba color) {
    line(a, b, width, color);
    const int segments = circleSegments(0.5 * width / view_.metersPerPixel());
    disc(a, 0.5 * width, segments, color);
    disc(b, 0.5 * width, segments, color);
  }

  const ViewTransform& view() const { return view_; }

 private:
  const ViewTransform& view_;
  std::vector<Vertex>& out_;
};

// Keeps the part of `polygon` where normal·x <= offset (Sutherland-Hodgman, one plane).
std::vector<Vec2> clip(const std::vector<Vec2>& polygon, const Vec2& normal, double offset) {
  std::vector<Vec2> kept;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec2& p = polygon[k];
    const Vec2& q = polygon[(k + 1) % polygon.size()];
    const double dp = normal.dot(p) - offset, dq = normal.dot(q) - offset;
    if (dp <= 0) kept.push_back(p);
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) kept.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return kept;
}

void drawHalfPlane(Painter& paint, const HalfPlane& plane, const RenderOptions& options) {
  const double length = plane.normal.norm();
  if (!(length > 1e-12) || !std::isfinite(plane.offset)) return;
  const Vec2 n = plane.normal / length;
  const double offset = plane.offset / length;
  // The view's rectangle, with a margin, cut by the plane.
  const ViewTransform& view = paint.view();
  const double margin = 0.1 * std::max(view.worldWidth(), view.view.height) + paint.px(8);
  const double hw = 0.5 * view.worldWidth() + margin, hh = 0.5 * view.view.height + margin;
  const Vec2 c = view.view.center;
  const std::vector<Vec2> rect = {c + Vec2(-hw, -hh), c + Vec2(hw, -hh), c + Vec2(hw, hh),
                                  c + Vec2(-hw, hh)};
  const std::vector<Vec2> solid = clip(rect, n, offset);
  paint.convex(solid, palette::kSolid);
  // Its edge: a strip inside the solid, so free space stays exactly free.
  paint.convex(clip(solid, -n, -(offset - paint.px(options.outlineWidthPx))), palette::kSolidEdge);
}

void drawCircleObstacle(Painter& paint, const CircleObstacle& circle,
                        const RenderOptions& options) {
  const int segments = circleSegments(circle.radius / paint.view().metersPerPixel());
  paint.disc(circle.center, circle.radius, segments, palette::kSolid);
  paint.ring(circle.center, circle.radius - paint.px(options.outlineWidthPx), circle.radius,
             segments, palette::kSolidEdge);
}

void drawShape(Painter& paint, const ShapeData& shape, const RenderOptions& options) {
  const Rgba fill = palette::bodyFill(shape.body), edge = palette::outlineOf(fill);
  const double w = paint.px(options.outlineWidthPx);
  switch (shape.kind) {
    case ShapeData::Kind::Polygon: {
      paint.convex(shape.points, fill);
      for (size_t k = 0; k < shape.points.size(); ++k) {
        paint.roundLine(shape.points[k], shape.points[(k + 1) % shape.points.size()], w, edge);
      }
      break;
    }
    case ShapeData::Kind::Circle: {
      const int segments = circleSegments(shape.radius / paint.view().metersPerPixel());
      paint.disc(shape.center, shape.radius, segments, fill);
      paint.ring(shape.center, shape.radius - w, shape.radius, segments, edge);
      // The spoke shows the body's angle.
      const Vec2 spoke(std::cos(shape.angle), std::sin(shape.angle));
      paint.line(shape.center, shape.center + (shape.radius - 0.5 * w) * spoke, w, edge);
      break;
    }
    case ShapeData::Kind::Edge: {
      if (shape.points.size() >= 2)
        paint.roundLine(shape.points[0], shape.points[1], 1.5 * w, edge);
      break;
    }
  }
}

Rgba springColor(const SpringData& spring, const Snapshot& s, const RenderOptions& options) {
  if (options.colorSpringsByStrain) {
    const double length = (s.particles[spring.j].x - s.particles[spring.i].x).norm();
    const double strain =
        spring.restLength > 0 ? (length - spring.restLength) / spring.restLength : 0.0;
    return palette::strainColor(strain, options.strainForFullColor);
  }
  return options.colorSpringsByType ? palette::springColor(spring.type) : palette::kPlainSpring;
}

void drawSprings(Painter& paint, const Snapshot& s, const RenderOptions& options) {
  const int count = static_cast<int>(s.particles.size());
  for (SpringType type :
       {SpringType::Bending, SpringType::Shear, SpringType::Structural, SpringType::Other}) {
    if (!options.springVisible(type)) continue;
    const double width = paint.px(options.springWidth(type));
    for (const SpringData& spring : s.springs) {
      if (spring.type != type || spring.i < 0 || spring.j < 0 || spring.i >= count ||
          spring.j >= count) {
        continue;
      }
      paint.line(s.particles[spring.i].x, s.particles[spring.j].x, width,
                 springColor(spring, s, options));
    }
  }
}

void drawParticles(Painter& paint, const Snapshot& s, const RenderOptions& options) {
  const double radius = std::max(s.particleRadius, paint.px(options.minParticleRadiusPx));
  // Free particles first, pinned ones on top.
  for (bool pinned : {false, true}) {
    for (const Particle& p : s.particles) {
      if (p.pinned != pinned) continue;
      Rgba color = palette::kParticle;
      if (pinned) {
        color = palette::kPinned;
      } else if (std::abs(p.temperature - options.ambientTemperature) > 1e-9) {
        color = palette::temperatureColor(p.temperature, options.ambientTemperature,
                                          options.hotTemperature);
      }
      paint.disc(p.x, pinned ? radius * options.pinnedScale : radius, kParticleSegments, color);
    }
  }
}

void drawJoints(Painter& paint, const Snapshot& s, const RenderOptions& options) {
  const double width = paint.px(options.jointWidthPx), dot = paint.px(options.anchorRadiusPx);
  const int segments = circleSegments(options.anchorRadiusPx);
  for (const JointData& joint : s.joints) {
    const Rgba color = palette::jointColor(joint.type);
    // As Box2D's testbed (b2Joint::Draw): a distance or mouse joint is its two anchors; any
    // other joint also links each body's centre to its anchor, except on the ground's side, so
    // a pendulum shows its rod from the pivot to the bob and a wheel joint its strut.
    const bool anchorsOnly = joint.type == "distance" || joint.type == "mouse";
    if (!anchorsOnly && !joint.groundA) paint.line(joint.centerA, joint.anchorA, width, color);
    paint.line(joint.anchorA, joint.anchorB, width, color);
    if (!anchorsOnly && !joint.groundB) paint.line(joint.anchorB, joint.centerB, width, color);
    paint.disc(joint.anchorA, dot, segments, color);
    paint.disc(joint.anchorB, dot, segments, color);
  }
}

}  // namespace

std::vector<Vertex> buildGeometry(const Snapshot& snapshot, int width, int height,
                                  const RenderOptions& options) {
  std::vector<Vertex> vertices;
  if (width <= 0 || height <= 0 || !(snapshot.view.height > 0)) return vertices;
  const ViewTransform view(snapshot.view, width, height);
  Painter paint(view, vertices);
  if (options.showObstacles) {
    for (const HalfPlane& plane : snapshot.planes) drawHalfPlane(paint, plane, options);
    for (const CircleObstacle& circle : snapshot.circles)
      drawCircleObstacle(paint, circle, options);
  }
  if (options.showShapes) {
    for (const ShapeData& shape : snapshot.shapes) drawShape(paint, shape, options);
  }
  drawSprings(paint, snapshot, options);
  if (options.showParticles) drawParticles(paint, snapshot, options);
  if (options.showJoints) drawJoints(paint, snapshot, options);
  return vertices;
}

}  // namespace a6
