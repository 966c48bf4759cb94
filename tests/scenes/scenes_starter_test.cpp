// The scenes with the STARTER files: nothing moves, no joint exists, no particle is emitted,
// but every scene builds, runs, draws, reports its energy and takes mouse input without
// crashing, so a student's first `a6_viewer` run shows a still picture and not a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/student_code.h"
#include "scenes/scene.h"

namespace a6 {
namespace {

class StarterScene : public ::testing::TestWithParam<std::string> {};

TEST_P(StarterScene, RunsSixtyFramesWithoutCrashing) {
  const std::string& name = GetParam();
  std::unique_ptr<Scene> scene = makeScene(name);
  ASSERT_NE(scene, nullptr) << name;
  Snapshot first = scene->snapshot();
  // Mouse input on whatever is at the centre of the view, then on a particle if there is one.
  scene->grab(first.view.center);
  scene->drag(first.view.center + Vec2(0.1, 0.1));
  scene->release();
  if (!first.particles.empty()) {
    scene->grab(first.particles.back().x);
    scene->drag(first.particles.back().x + Vec2(0.05, 0));
  }
  for (int frame = 0; frame < 60; ++frame) scene->advanceFrame();
  scene->release();
  const Snapshot last = scene->snapshot();
  EXPECT_EQ(last.scene, name);
  EXPECT_NEAR(last.time, 1.0, 1e-9) << name;
  const SceneEnergy e = scene->energy();
  EXPECT_FALSE(std::isnan(e.total())) << name;
  // A reset brings the scene back to its first picture.
  scene->reset(scene->params());
  EXPECT_EQ(scene->frame(), 0);
  EXPECT_EQ(scene->snapshot().particles.size(), first.particles.size()) << name;
}

INSTANTIATE_TEST_SUITE_P(AllScenes, StarterScene, ::testing::ValuesIn(sceneNames()),
                         [](const auto& info) { return info.param; });

TEST(StarterScenes, RunSceneThroughTheHarnessReturnsEverySnapshot) {
  auto student = harness::makeInProcess();
  for (const std::string& name : sceneNames()) {
    harness::SceneRequest request;
    request.scene = name;
    request.frames = {0, 30};
    const harness::SceneResult result = student->ask(request);
    ASSERT_TRUE(result.ok()) << name << ": " << result.error;
    ASSERT_EQ(result.snapshots.size(), 2u) << name;
  }
}

}  // namespace
}  // namespace a6
