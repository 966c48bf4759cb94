// The viewer's command line (no window needed).
#include <gtest/gtest.h>

#include "viewer/viewer_options.h"

namespace a6::viewer {
namespace {

ParseResult parse(std::vector<std::string> args) { return parseOptions(args); }

TEST(ViewerOptions, DefaultsWithoutArguments) {
  const ParseResult r = parse({});
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.options.scene, "cloth_shear");
  EXPECT_EQ(r.options.width, 800);
  EXPECT_EQ(r.options.height, 600);
  EXPECT_EQ(r.options.frames, -1);
  EXPECT_TRUE(r.options.gui);
  EXPECT_FALSE(r.options.sideBySide);
}

TEST(ViewerOptions, SideBySide) {
  const ParseResult r = parse({"--scene", "stiff_cloth_implicit", "--side-by-side"});
  ASSERT_TRUE(r) << r.error;
  EXPECT_TRUE(r.options.sideBySide);
  EXPECT_FALSE(parse({"--side-by-side=yes"}));
}

TEST(ViewerOptions, SmokeTestCommandLine) {
  const ParseResult r = parse({"--scene", "fire", "--frames", "60", "--size", "480x360",
                               "--screenshot", "out/fire.png", "--no-gui"});
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.options.scene, "fire");
  EXPECT_EQ(r.options.frames, 60);
  EXPECT_EQ(r.options.width, 480);
  EXPECT_EQ(r.options.height, 360);
  EXPECT_EQ(r.options.screenshot, "out/fire.png");
  EXPECT_FALSE(r.options.gui);
}

TEST(ViewerOptions, ValuesAfterAnEqualsSign) {
  const ParseResult r = parse({"--scene=car", "--size=640x480", "--frames=0"});
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.options.scene, "car");
  EXPECT_EQ(r.options.width, 640);
  EXPECT_EQ(r.options.frames, 0);
}

TEST(ViewerOptions, BadValuesAreErrorsThatSayWhy) {
  EXPECT_NE(parse({"--size", "800"}).error.find("WxH"), std::string::npos);
  EXPECT_FALSE(parse({"--size", "8x8"}));  // below 16 pixels
  EXPECT_FALSE(parse({"--size", "800x600px"}));
  EXPECT_FALSE(parse({"--frames", "-1"}));
  EXPECT_FALSE(parse({"--frames", "ten"}));
  EXPECT_NE(parse({"--frames"}).error.find("needs a value"), std::string::npos);
  EXPECT_NE(parse({"--bogus"}).error.find("unknown option"), std::string::npos);
  EXPECT_FALSE(parse({"--no-gui=yes"}));
}

TEST(ViewerOptions, UsageNamesEveryOptionAndKey) {
  const std::string text = usage("a6_viewer");
  for (const char* word : {"--scene", "--size", "--frames", "--screenshot", "--no-gui", "--list",
                           "--side-by-side", "Space", "Shift+S", "Esc"}) {
    EXPECT_NE(text.find(word), std::string::npos) << word;
  }
}

}  // namespace
}  // namespace a6::viewer
