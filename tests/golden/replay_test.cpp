// Replays (framework/render/replay.h): the frames a replay shows, the energy of a snapshot by
// hand, packing and unpacking, and (Committed.*, with A6_FRESH_REPLAYS naming a folder that
// a6_render_solution --replays just wrote) that the reference replays in tests/golden/replays/
// are the solution's runs as they are now.
#include "render/replay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace a6::paths {
extern const char golden_dir[];  // tests/golden (cmake/A6FastBuild.cmake, a6_configured_path)
}  // namespace a6::paths

namespace a6::replay {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

TEST(ReplayFrames, AboutSixtyEvenlySpacedFromZeroToTheLast) {
  std::vector<int> sixty;
  for (int f = 0; f <= 60; ++f) sixty.push_back(f);
  EXPECT_EQ(replayFrames(60), sixty);
  const std::vector<int> long_ = replayFrames(300);
  EXPECT_EQ(long_.size(), 61u);
  EXPECT_EQ(long_.front(), 0);
  EXPECT_EQ(long_.back(), 300);
  EXPECT_EQ(long_[1], 5);
  EXPECT_EQ(replayFrames(3), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(replayFrames(0), (std::vector<int>{0}));
}

TEST(Energy, ByHand) {
  // 2 kg at height 3 m moving at 1 m/s under g = 10: ½·2·1 = 1 J kinetic, 2·10·3 = 60 J
  // potential; a 100 N/m spring of rest length 1 m stretched to 2 m: ½·100·1 = 50 J more.
  Snapshot s;
  Particle a, b;
  a.m = 2, a.x = Vec2(0, 3), a.v = Vec2(1, 0);
  b.m = 1, b.x = Vec2(2, 3), b.v = Vec2(0, 0);
  s.particles = {a, b};
  const std::vector<SpringData> springs = {{0, 1, 1.0, 100, 0, SpringType::Other}};
  const Energy e = energyOf(s, springs, Vec2(0, -10));
  EXPECT_TRUE(e.known);
  EXPECT_DOUBLE_EQ(e.kinetic, 1);
  EXPECT_DOUBLE_EQ(e.potential, 60 + 30 + 50);
  Snapshot bodies;
  bodies.shapes.push_back({});
  EXPECT_FALSE(energyOf(bodies, {}, Vec2(0, -10)).known) << "Box2D's bodies: unknown";
}

TEST(Pack, PositionsComeBackWithinHalfAStepAndNaNStaysNaN) {
  Recording r;
  r.scene = "test";
  Snapshot s;
  s.view.center = Vec2(1, 2), s.view.height = 4;
  Particle p;
  p.x = Vec2(1.2345, 0.5);
  Particle q;
  q.x = Vec2(NAN, 3);
  s.particles = {p, q};
  s.springs = {{0, 1, 1, 10, 0, SpringType::Structural}};
  ShapeData box;
  box.points = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)};
  s.shapes = {box};
  s.joints.push_back({"revolute", Vec2(0, 0), Vec2(0.5, 0.5), Vec2(0, 1), Vec2(1, 1), true, false});
  r.frames = {0, 1};
  r.snapshots = {s, s};
  r.snapshots[1].springs.clear();  // lean: the first frame's springs serve
  const Json packed = pack(r);
  EXPECT_EQ(packed["springs"], Json::array({0, 1, 0}));
  EXPECT_EQ(packed["counts"], Json::array({Json::array({2, 1}), Json::array({2, 1})}));
  const Unpacked u = unpack(packed);
  const double half = 4.0 / 8000 / 2;
  ASSERT_EQ(u.particles.size(), 2u);
  EXPECT_NEAR(u.particles[1][0].x(), 1.2345, half);
  EXPECT_NEAR(u.particles[1][0].y(), 0.5, half);
  EXPECT_TRUE(std::isnan(u.particles[1][1].x()));
  ASSERT_EQ(u.shapePoints[0].size(), 3u);
  EXPECT_NEAR(u.shapePoints[0][2].y(), 1, half);
  EXPECT_EQ(u.energy.size(), 2u);
  EXPECT_FALSE(u.drawn);
}

TEST(Pack, ABrokenPackIsAnErrorThatSaysSo) {
  EXPECT_THROW(unpack(Json::object()), std::runtime_error);
  Recording r;
  r.frames = {0};
  r.snapshots = {Snapshot{}};
  r.snapshots[0].particles.resize(3);
  Json packed = pack(r);
  packed["data"] = "AAAA";  // fewer points than the counts say
  EXPECT_THROW(unpack(packed), std::runtime_error);
}

Json readJson(const fs::path& file) {
  std::ifstream in(file);
  return Json::parse(in, nullptr, false);
}

TEST(Committed, ReferenceReplaysAreTheSolutionsRunsAsTheyAreNow) {
  const char* fresh = std::getenv("A6_FRESH_REPLAYS");
  if (fresh == nullptr) GTEST_SKIP() << "A6_FRESH_REPLAYS names no fresh folder";
  const fs::path committed = fs::path(a6::paths::golden_dir) / "replays";
  int compared = 0;
  for (const auto& e : fs::directory_iterator(fresh)) {
    const fs::path name = e.path().filename();
    SCOPED_TRACE(name.string());
    ASSERT_TRUE(fs::exists(committed / name))
        << "tests/golden/replays/" << name.string() << " is missing: write the reference "
        << "replays again with a6_render_solution --replays (docs/rendering.md)";
    const Unpacked now = unpack(readJson(e.path())), then = unpack(readJson(committed / name));
    ASSERT_EQ(now.frames, then.frames);
    // Within a hundredth of the view: the replay's "parted" threshold.
    const double tolerance = 0.01 * now.view.height;
    for (std::size_t f = 0; f < now.frames.size(); ++f) {
      ASSERT_EQ(now.particles[f].size(), then.particles[f].size()) << "frame " << now.frames[f];
      for (std::size_t i = 0; i < now.particles[f].size(); ++i) {
        ASSERT_LE((now.particles[f][i] - then.particles[f][i]).norm(), tolerance)
            << "frame " << now.frames[f] << ", particle " << i
            << ": write the reference replays again (a6_render_solution --replays)";
      }
    }
    ++compared;
  }
  EXPECT_GT(compared, 0);
  int committedFiles = 0;
  for (const auto& e : fs::directory_iterator(committed))
    committedFiles += e.path().extension() == ".json";
  EXPECT_EQ(committedFiles, compared) << "a committed replay whose scene no image checks any more";
}

}  // namespace
}  // namespace a6::replay
