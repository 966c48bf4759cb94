// The renderer on a headless context: real pixels of a hand-made snapshot, determinism, and
// the contexts themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gl_fixture.h"
#include "render/palette.h"
#include "render/view_transform.h"
#include "sample_snapshots.h"

namespace a6::test {
namespace {

std::string str(Rgba c) {
  char text[48];
  std::snprintf(text, sizeof text, "(%d, %d, %d, %d)", c.r, c.g, c.b, c.a);
  return text;
}

// The pixel under world point p.
Rgba pixelAt(const Image& image, const View& view, Vec2 p) {
  const Vec2 px = ViewTransform(view, image.width, image.height).toPixel(p);
  return image.at(static_cast<int>(std::floor(px.x())), static_cast<int>(std::floor(px.y())));
}

#define EXPECT_COLOR(image, world, expected, what)                                               \
  do {                                                                                           \
    const Rgba actual_ = pixelAt(image, testSnapshot().view, world);                             \
    EXPECT_EQ(actual_, expected) << what << " at world (" << (world).x() << ", " << (world).y()  \
                                 << "): expected " << str(expected) << ", got " << str(actual_); \
  } while (0)

class RendererPixels : public HeadlessGL {};

TEST_F(RendererPixels, EachObjectHasItsColourWhereTheViewPutsIt) {
  const Snapshot s = testSnapshot();
  const Image image = renderer_->render(s, 256, 256);
  ASSERT_FALSE(image.empty()) << renderer_->error();
  ASSERT_EQ(image.width, 256);
  ASSERT_EQ(image.height, 256);

  // Background at the corners (top-right and top-left are empty by construction).
  EXPECT_EQ(image.at(255, 0), palette::kBackground) << str(image.at(255, 0));
  EXPECT_EQ(image.at(0, 0), palette::kBackground) << str(image.at(0, 0));
  // The floor (y < -1.5): solid below its line, its edge strip just below the line.
  EXPECT_COLOR(image, Vec2(-1.9, -1.9), palette::kSolid, "floor");
  EXPECT_COLOR(image, Vec2(-1.9, -1.5 - 0.5 / 64), palette::kSolidEdge, "floor edge");
  EXPECT_COLOR(image, Vec2(-1.9, -1.5 + 0.5 / 64), palette::kBackground, "just above the floor");
  EXPECT_COLOR(image, Vec2(1.2, -0.8), palette::kSolid, "circle obstacle");
  // Particles at their centres: pinned (black), free, hot (fire colour).
  EXPECT_COLOR(image, Vec2(-1.5, 1.5), palette::kPinned, "pinned particle A");
  EXPECT_COLOR(image, Vec2(0.25, 0.75), palette::kParticle, "free particle F");
  EXPECT_COLOR(image, Vec2(0.75, 0.75), palette::temperatureColor(900, 293.15, 900),
               "hot particle H");
  // Springs at their midpoints, one colour per type.
  EXPECT_COLOR(image, Vec2(-1.0, 1.5), palette::kStructural, "structural spring A-B");
  EXPECT_COLOR(image, Vec2(-1.0, 1.0), palette::kShear, "shear spring A-D");
  EXPECT_COLOR(image, Vec2(-1.0, 0.5), palette::kBending, "bending spring C-D");
  EXPECT_COLOR(image, Vec2(-0.5, 1.0), palette::kOtherSpring, "other spring B-D");
  // Box2D: the box's fill, the circle's fill, its spoke (angle 0: towards +x), the joint.
  EXPECT_COLOR(image, Vec2(0.5, -0.5), palette::bodyFill(0), "Box2D box");
  EXPECT_COLOR(image, Vec2(-0.95, -0.8), palette::bodyFill(1), "Box2D circle, left half");
  EXPECT_COLOR(image, Vec2(-0.8 + 0.15, -0.8), palette::outlineOf(palette::bodyFill(1)),
               "Box2D circle's spoke");
  EXPECT_COLOR(image, Vec2(0.5, 0.0), palette::jointColor("revolute"), "revolute joint");
}

TEST_F(RendererPixels, NothingIsDrawnAwayFromTheObjects) {
  const Snapshot s = testSnapshot();
  const Image image = renderer_->render(s, 256, 256);
  ASSERT_FALSE(image.empty()) << renderer_->error();
  // Pixel boxes of every object, 4 px larger; the floor covers everything from its line down.
  const ViewTransform view(s.view, 256, 256);
  struct Box {
    double x0, y0, x1, y1;
  };
  std::vector<Box> boxes;
  auto add = [&](Vec2 lo, Vec2 hi) {
    const Vec2 a = view.toPixel(lo), b = view.toPixel(hi);
    boxes.push_back({std::min(a.x(), b.x()) - 4, std::min(a.y(), b.y()) - 4,
                     std::max(a.x(), b.x()) + 4, std::max(a.y(), b.y()) + 4});
  };
  const Vec2 r(0.1, 0.1);  // particle radius with margin, pinned included
  for (const Particle& p : s.particles) add(p.x - r, p.x + r);
  for (const SpringData& sp : s.springs) {
    add(s.particles[sp.i].x.cwiseMin(s.particles[sp.j].x),
        s.particles[sp.i].x.cwiseMax(s.particles[sp.j].x));
  }
  for (const CircleObstacle& c : s.circles)
    add(c.center - Vec2(c.radius, c.radius), c.center + Vec2(c.radius, c.radius));
  add(Vec2(0.25, -0.75), Vec2(0.75, -0.25));                // box
  add(Vec2(-1.1, -1.1), Vec2(-0.5, -0.5));                  // circle shape
  add(Vec2(0.5, -0.25), Vec2(0.5, 0.25));                   // joint
  const double floorRow = view.toPixel(Vec2(0, -1.5)).y();  // 224
  int stray = 0, checked = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      if (y + 0.5 > floorRow - 1) continue;
      bool inside = false;
      for (const Box& b : boxes)
        inside |= x + 0.5 >= b.x0 && x + 0.5 <= b.x1 && y + 0.5 >= b.y0 && y + 0.5 <= b.y1;
      if (inside) continue;
      ++checked;
      if (image.at(x, y) != palette::kBackground) {
        if (++stray <= 5)
          ADD_FAILURE() << "stray pixel " << x << "," << y << ": " << str(image.at(x, y));
      }
    }
  }
  EXPECT_EQ(stray, 0);
  EXPECT_GT(checked, 256 * 256 / 3) << "the check covered too little of the image";
}

TEST_F(RendererPixels, YIsUpInTheImage) {
  // A single particle above the centre appears in the upper half of the image.
  Snapshot s;
  s.view.height = 4;
  Particle p;
  p.x = Vec2(0, 1);
  s.particles.push_back(p);
  const Image image = renderer_->render(s, 64, 64);
  ASSERT_FALSE(image.empty()) << renderer_->error();
  EXPECT_EQ(image.at(32, 16), palette::kParticle) << "world (0, 1) must be at pixel row 16";
  EXPECT_EQ(image.at(32, 48), palette::kBackground);
}

TEST_F(RendererPixels, StrainColoursShowStretchedAndCompressedSprings) {
  Snapshot s = testSnapshot();
  s.springs[0].restLength *= 0.5;  // A-B: strain +1, fully red
  s.springs[3].restLength *= 4;    // B-D: strain -0.75, fully blue
  RenderOptions options;
  options.colorSpringsByStrain = true;
  const Image image = renderer_->render(s, 256, 256, options);
  ASSERT_FALSE(image.empty()) << renderer_->error();
  EXPECT_COLOR(image, Vec2(-1.0, 1.5), palette::kStretched, "stretched spring A-B");
  EXPECT_COLOR(image, Vec2(-0.5, 1.0), palette::kCompressed, "compressed spring B-D");
  EXPECT_COLOR(image, Vec2(-1.0, 1.0), palette::kAtRest, "shear spring A-D at rest");
}

TEST_F(RendererPixels, HiddenSpringTypesAreNotDrawn) {
  RenderOptions options;
  options.setSpringVisible(SpringType::Structural, false);
  options.setSpringVisible(SpringType::Bending, false);
  const Image image = renderer_->render(testSnapshot(), 256, 256, options);
  ASSERT_FALSE(image.empty()) << renderer_->error();
  EXPECT_COLOR(image, Vec2(-1.0, 1.5), palette::kBackground, "hidden structural spring");
  EXPECT_COLOR(image, Vec2(-1.0, 0.5), palette::kBackground, "hidden bending spring");
  EXPECT_COLOR(image, Vec2(-1.0, 1.0), palette::kShear, "visible shear spring");
}

TEST_F(RendererPixels, JointsLinkTheBodiesCentresLikeBox2DsTestbed) {
  // testSnapshot()'s revolute joint: box centre (0.5, -0.5) to anchor A (0.5, -0.25), anchor A
  // to anchor B (0.5, 0.25); its B side is the ground, so nothing beyond anchor B.
  const Image image = renderer_->render(testSnapshot(), 256, 256);
  ASSERT_FALSE(image.empty()) << renderer_->error();
  const Rgba revolute = palette::jointColor("revolute");
  EXPECT_COLOR(image, Vec2(0.5, -0.4), revolute, "box centre to anchor A");
  EXPECT_COLOR(image, Vec2(0.5, 0.0), revolute, "anchor A to anchor B");
  EXPECT_COLOR(image, Vec2(0.5, 0.4), palette::kBackground, "beyond anchor B (the ground)");

  // A pendulum: the pivot on the ground, the rod from the pivot to the bob's centre. A distance
  // joint is only its two anchors, whatever its bodies' centres.
  Snapshot s;
  s.view.height = 4;
  JointData rod{"revolute", Vec2(-1, 1), Vec2(-1, 1), Vec2(-1.5, 1.5), Vec2(-1, -1), true, false};
  JointData rope{"distance", Vec2(1, 1), Vec2(1, 0), Vec2(1.5, 1.5), Vec2(1, -1), false, false};
  s.joints = {rod, rope};
  const Image pendulum = renderer_->render(s, 256, 256);
  ASSERT_FALSE(pendulum.empty()) << renderer_->error();
  auto at = [&](Vec2 p) { return pixelAt(pendulum, s.view, p); };
  EXPECT_EQ(at(Vec2(-1, 0)), revolute) << "the pendulum's rod";
  EXPECT_EQ(at(Vec2(-1.25, 1.25)), palette::kBackground) << "towards the ground's centre";
  EXPECT_EQ(at(Vec2(1, 0.5)), palette::jointColor("distance")) << "the rope";
  EXPECT_EQ(at(Vec2(1, -0.5)), palette::kBackground) << "a rope has no strut to its body";
  EXPECT_EQ(at(Vec2(1.25, 1.25)), palette::kBackground) << "a rope has no strut to its body";
}

TEST_F(RendererPixels, LineThicknessIsInPixelsAtAnySize) {
  // A horizontal structural spring through the centre is springWidthPx rows thick at any size.
  Snapshot s;
  s.view.height = 2;
  Particle p;
  p.x = Vec2(-0.8, 0);
  s.particles.push_back(p);
  p.x = Vec2(0.8, 0);
  s.particles.push_back(p);
  s.springs.push_back(SpringData{0, 1, 1.6, 1, 0, SpringType::Structural});
  for (int size : {64, 256, 512}) {
    const Image image = renderer_->render(s, size, size);
    ASSERT_FALSE(image.empty()) << renderer_->error();
    int rows = 0;
    for (int y = 0; y < size; ++y) rows += image.at(size / 4, y) == palette::kStructural;
    EXPECT_EQ(rows, 2) << "at " << size << "x" << size;
  }
}

TEST_F(RendererPixels, TheSameSnapshotGivesTheSameBytes) {
  const Snapshot s = clothSnapshot();
  RenderOptions strain;
  strain.colorSpringsByStrain = true;
  for (const RenderOptions& options : {RenderOptions(), strain}) {
    const Image first = renderer_->render(s, 256, 192, options);
    ASSERT_FALSE(first.empty()) << renderer_->error();
    renderer_->render(box2dSnapshot(), 100, 100);  // something else in between
    const Image second = renderer_->render(s, 256, 192, options);
    EXPECT_TRUE(compare(second, first, 0).identical);

    // A fresh context and renderer.
    ContextResult fresh = makeHeadlessContext(64, 64, HeadlessBackend::OSMesa);
    if (!fresh) fresh = makeHeadlessContext(64, 64);
    ASSERT_TRUE(fresh) << fresh.error;
    Renderer other(*fresh.context);
    ASSERT_TRUE(other.ok()) << other.error();
    const Image third = other.render(s, 256, 192, options);
    EXPECT_TRUE(compare(third, first, 0).identical)
        << "fresh context " << fresh.context->description() << " vs " << context_->description();
  }
}

TEST_F(RendererPixels, RejectsBadSizesWithAMessage) {
  const Image image = renderer_->render(testSnapshot(), 0, 10);
  EXPECT_TRUE(image.empty());
  EXPECT_NE(renderer_->error().find("invalid size"), std::string::npos) << renderer_->error();
  EXPECT_FALSE(renderer_->render(testSnapshot(), 16, 16).empty()) << "a failure must not stick";
}

// The contexts.

class HeadlessContext : public HeadlessGL {};

TEST_F(HeadlessContext, DescribesItsRenderer) {
  const GLContext& context = *context_;
  std::printf("[ headless ] %s: %s\n", context.backend().c_str(), context.description().c_str());
  EXPECT_FALSE(context.renderer().empty());
  EXPECT_NE(context.version().find("Core Profile"), std::string::npos) << context.version();
  int major = 0, minor = 0;
  ASSERT_EQ(std::sscanf(context.version().c_str(), "%d.%d", &major, &minor), 2);
  EXPECT_GE(major * 10 + minor, 33) << context.version();
  EXPECT_EQ(context.width(), 256);
  EXPECT_EQ(context.height(), 256);
}

TEST_F(HeadlessContext, EachBuiltBackendWorksOrSaysWhy) {
  for (HeadlessBackend backend : {HeadlessBackend::OSMesa, HeadlessBackend::EGL}) {
    ContextResult result = makeHeadlessContext(16, 16, backend);
    if (result) {
      std::printf("[ headless ] %s: %s\n", toString(backend),
                  result.context->description().c_str());
      Renderer renderer(*result.context);
      EXPECT_TRUE(renderer.ok()) << renderer.error();
    } else {
      std::printf("[ headless ] %s unavailable: %s\n", toString(backend), result.error.c_str());
      EXPECT_NE(result.error.find(backend == HeadlessBackend::EGL ? "EGL" : "OSMesa"),
                std::string::npos)
          << "the error must name the backend: " << result.error;
    }
  }
}

TEST(HeadlessContextErrors, RejectsAnEmptySize) {
  ContextResult result = makeHeadlessContext(0, 16);
  EXPECT_FALSE(result);
  EXPECT_NE(result.error.find("invalid size"), std::string::npos) << result.error;
}

TEST(HeadlessContextErrors, ParsesBackendNames) {
  HeadlessBackend backend = HeadlessBackend::Auto;
  EXPECT_TRUE(parseHeadlessBackend("egl", &backend));
  EXPECT_EQ(backend, HeadlessBackend::EGL);
  EXPECT_TRUE(parseHeadlessBackend("osmesa", &backend));
  EXPECT_EQ(backend, HeadlessBackend::OSMesa);
  EXPECT_FALSE(parseHeadlessBackend("vulkan", &backend));
}

// A context without some GL functions: the loader names every missing one.
class PartialContext : public GLContext {
 public:
  bool makeCurrent() override { return true; }
  GLProc getProcAddress(const char* name) const override {
    static void (*const dummy)() = [] {};
    const std::string n = name;
    return n == "glDrawArrays" || n == "glReadPixels" ? nullptr : dummy;
  }
  int width() const override { return 1; }
  int height() const override { return 1; }
  std::string backend() const override { return "test"; }
};

TEST(GLLoader, NamesEveryMissingFunction) {
  PartialContext context;
  GLFunctions gl;
  const std::string error = gl.load(context);
  EXPECT_NE(error.find("glDrawArrays"), std::string::npos) << error;
  EXPECT_NE(error.find("glReadPixels"), std::string::npos) << error;
  EXPECT_EQ(error.find("glClear,"), std::string::npos) << error;
  Renderer renderer(context);
  EXPECT_FALSE(renderer.ok());
  EXPECT_NE(renderer.error().find("glDrawArrays"), std::string::npos) << renderer.error();
  EXPECT_TRUE(renderer.render(testSnapshot(), 8, 8).empty());
}

}  // namespace
}  // namespace a6::test
