#include <cmath>
#include <cstdio>
#include "suite.h"
namespace a6::test {
namespace {
TEST(Task6Joints, Explore2) {
  {
    harness::Box2DRequest r; r.scene = "bridge"; r.steps = 240;
    auto res = student().runBox2D(r);
    double minY = 9, minLoad = 9, maxGap = 0;
    for (auto& ps : res.poses) { for (int k = 0; k < 10; ++k) minY = std::min(minY, ps[k].position.y()); minLoad = std::min(minLoad, ps[10].position.y()); }
    for (auto& j : res.joints) maxGap = std::max(maxGap, (j.anchorA - j.anchorB).norm());
    std::printf("bridge minPlankY=%g minLoadY=%g end load=%s mid=%s gap=%g\n", minY, minLoad, str(res.poses.back()[10].position).c_str(), str(res.poses.back()[5].position).c_str(), maxGap);
    for (int s : {0, 30, 60, 120, 239}) std::printf("  load %d %s plank4 %s plank5 %s\n", s, str(res.poses[s][10].position).c_str(), str(res.poses[s][4].position).c_str(), str(res.poses[s][5].position).c_str());
  }
  {
    harness::Box2DRequest r; r.scene = "rope"; r.steps = 300;
    auto res = student().runBox2D(r);
    double maxD = 0; int first = -1;
    for (size_t s = 0; s < res.poses.size(); ++s) { double d = (res.poses[s][0].position - Vec2(0, 2)).norm(); if (d > 1.49 && first < 0) first = s; maxD = std::max(maxD, d); }
    std::printf("rope maxD=%.6f first>1.49 at %d\n", maxD, first);
  }
  {
    harness::Box2DRequest r; r.scene = "pendulum"; r.steps = 400;
    auto res = student().runBox2D(r);
    std::vector<double> cr;
    double prev = 0.1 * 1; // x at t=0 approx
    prev = std::sin(0.1);
    for (size_t s = 0; s < res.poses.size(); ++s) { double x = res.poses[s][0].position.x(); if ((prev > 0) != (x > 0)) { double t0 = s / 60.0, t1 = (s + 1) / 60.0; cr.push_back(t0 + (t1 - t0) * prev / (prev - x)); } prev = x; }
    for (double c : cr) std::printf(" %g", c);
    double T = 2 * (cr.back() - cr.front()) / (cr.size() - 1);
    double m = res.bodies[0].mass, I = res.bodies[0].inertia + m;
    double T0 = 2 * M_PI * std::sqrt(I / (m * 9.81));
    std::printf("\npendulum T=%.6f T0=%.6f rel=%g\n", T, T0, T / T0 - 1);
  }
  {
    harness::Box2DRequest r; r.scene = "car"; r.steps = 240;
    auto res = student().runBox2D(r);
    double maxA = 0, lat = 0, ymin = 9, ymax = -9;
    for (auto& ps : res.poses) {
      maxA = std::max(maxA, std::abs(ps[0].angle));
      double c = std::cos(ps[0].angle), s = std::sin(ps[0].angle);
      for (int w = 1; w <= 2; ++w) { Vec2 d = ps[w].position - ps[0].position; Vec2 l(c * d.x() + s * d.y(), -s * d.x() + c * d.y()); double x0 = w == 1 ? -1 : 1; double y0 = w == 1 ? -0.65 : -0.6; lat = std::max(lat, std::abs(l.x() - x0)); ymin = std::min(ymin, l.y() - y0); ymax = std::max(ymax, l.y() - y0); }
    }
    std::printf("car x end %g maxAngle %g lat %g susp [%g, %g]\n", res.poses.back()[0].position.x(), maxA, lat, ymin, ymax);
    for (int s : {59, 119, 179, 239}) std::printf("  x(%d)=%g", s, res.poses[s][0].position.x());
    std::printf("\n");
  }
}
}
}
