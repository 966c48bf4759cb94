// The renderer's CPU half: triangles from snapshots, without GL.
#include "render/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "render/palette.h"
#include "render/view_transform.h"
#include "sample_snapshots.h"

namespace a6::test {
namespace {

TEST(ViewTransform, MapsTheViewOntoTheImage) {
  View view;
  view.center = Vec2(1, 2);
  view.height = 4;
  const ViewTransform t(view, 200, 100);  // 25 px per metre, 8 m wide
  EXPECT_DOUBLE_EQ(t.worldWidth(), 8);
  EXPECT_TRUE(t.toPixel(Vec2(1, 2)).isApprox(Vec2(100, 50)));
  EXPECT_TRUE(t.toPixel(Vec2(-3, 4)).isApprox(Vec2(0, 0)));     // top-left corner
  EXPECT_TRUE(t.toPixel(Vec2(5, 0)).isApprox(Vec2(200, 100)));  // bottom-right corner
  EXPECT_TRUE(t.toNdc(Vec2(5, 4)).isApprox(Vec2(1, 1)));
  EXPECT_TRUE(t.toWorld(t.toPixel(Vec2(0.3, -0.7))).isApprox(Vec2(0.3, -0.7)));
}

TEST(Geometry, IsWholeTrianglesAndDeterministic) {
  const Snapshot s = clothSnapshot();
  RenderOptions strain;
  strain.colorSpringsByStrain = true;
  for (const RenderOptions& options : {RenderOptions(), strain}) {
    const std::vector<Vertex> a = buildGeometry(s, 320, 240, options);
    const std::vector<Vertex> b = buildGeometry(s, 320, 240, options);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a.size() % 3, 0u);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vertex)), 0);
  }
}

TEST(Geometry, ParticlesAreDiscsOfTheDocumentedSegments) {
  Snapshot s;
  s.particles.resize(3);
  RenderOptions options;
  EXPECT_EQ(buildGeometry(s, 100, 100, options).size(), 3u * 3 * kParticleSegments);
  options.showParticles = false;
  EXPECT_TRUE(buildGeometry(s, 100, 100, options).empty());
}

TEST(Geometry, SkipsWhatCannotBeDrawnWithoutCrashing) {
  Snapshot s = testSnapshot();
  s.particles[1].x = Vec2(std::numeric_limits<double>::quiet_NaN(), 0);  // an exploded cloth
  s.particles[2].x = Vec2(1e300, -1e300);                                // beyond float range
  s.springs.push_back(SpringData{0, 99, 1, 1, 0, SpringType::Other});    // a bad index
  s.planes.push_back(HalfPlane{Vec2(0, 0), 1});                          // no normal
  const std::vector<Vertex> v = buildGeometry(s, 64, 64, RenderOptions());
  EXPECT_EQ(v.size() % 3, 0u);
  for (const Vertex& vertex : v) {
    ASSERT_TRUE(std::isfinite(vertex.x) && std::isfinite(vertex.y));
  }
  Snapshot badView = testSnapshot();
  badView.view.height = 0;
  EXPECT_TRUE(buildGeometry(badView, 64, 64, RenderOptions()).empty());
}

TEST(Palette, StrainAndTemperatureRamps) {
  EXPECT_EQ(palette::strainColor(0, 0.1), palette::kAtRest);
  EXPECT_EQ(palette::strainColor(0.5, 0.1), palette::kStretched);
  EXPECT_EQ(palette::strainColor(-0.5, 0.1), palette::kCompressed);
  const Rgba half = palette::strainColor(0.05, 0.1);
  EXPECT_GT(half.r, palette::kAtRest.r);
  EXPECT_LT(half.r, palette::kStretched.r);
  // Fire: hotter is brighter.
  auto brightness = [](Rgba c) { return c.r + c.g + c.b; };
  double previous = 0;
  for (double t : {300.0, 400.0, 500.0, 600.0, 700.0, 800.0, 900.0}) {
    const double b = brightness(palette::temperatureColor(t, 293.15, 900));
    if (t > 400) {
      EXPECT_GT(b, previous) << t << " K";
    }
    previous = b;
  }
  for (SpringType a :
       {SpringType::Structural, SpringType::Shear, SpringType::Bending, SpringType::Other}) {
    for (SpringType b :
         {SpringType::Structural, SpringType::Shear, SpringType::Bending, SpringType::Other}) {
      if (a != b) {
        EXPECT_NE(palette::springColor(a), palette::springColor(b));
      }
    }
  }
}

}  // namespace
}  // namespace a6::test
