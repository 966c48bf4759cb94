// The viewer's command line, parsed by hand (CLI11 is not a Debian 12 dependency we take on for
// a handful of options).
//
//   a6_viewer [--scene NAME] [--size WxH] [--frames N] [--screenshot PATH] [--no-gui]
//             [--paused] [--side-by-side] [--no-vsync] [--list] [--help]
#pragma once

#include <string>
#include <vector>

namespace a6::viewer {

struct Options {
  std::string scene = "cloth_shear";  ///< registry name of the scene to start with
  int width = 800, height = 600;      ///< size of the scene area, pixels (the panel is extra)
  int frames = -1;                    ///< >= 0: run this many frames, save a screenshot, exit
  std::string screenshot;             ///< where --frames saves (default <scene>_frame<N>.png)
  bool gui = true;                    ///< false: no ImGui panel (the window shows the scene only)
  bool paused = false;                ///< start paused
  bool sideBySide = false;            ///< both integrators at once, in scenes that have the switch
  bool vsync = true;
  bool list = false;  ///< print the scene names and exit
  bool help = false;  ///< print the usage and exit
};

/// What parsing gave: the options, or an error message saying what was wrong.
struct ParseResult {
  Options options;
  std::string error;  ///< empty on success
  explicit operator bool() const { return error.empty(); }
};

/// Parses argv[1..] (without the program name). Unknown options and bad values are errors.
ParseResult parseOptions(const std::vector<std::string>& args);

/// The usage text (options, keys), for --help and after an error.
std::string usage(const std::string& program);

}  // namespace a6::viewer
