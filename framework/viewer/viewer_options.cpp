#include "viewer/viewer_options.h"

#include <cstdlib>

namespace a6::viewer {
namespace {

// A whole decimal number in [lo, hi], or false.
bool parseInt(const std::string& text, int lo, int hi, int* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (*end != '\0' || value < lo || value > hi) return false;
  *out = static_cast<int>(value);
  return true;
}

// "WxH" with both sides in [16, 8192].
bool parseSize(const std::string& text, int* width, int* height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return false;
  return parseInt(text.substr(0, x), 16, 8192, width) &&
         parseInt(text.substr(x + 1), 16, 8192, height);
}

// The switches (options without a value), and what each sets.
struct Switch {
  const char* name;
  bool Options::*field;
  bool value;
};
constexpr Switch kSwitches[] = {{"--no-gui", &Options::gui, false},
                                {"--paused", &Options::paused, true},
                                {"--side-by-side", &Options::sideBySide, true},
                                {"--no-vsync", &Options::vsync, false},
                                {"--list", &Options::list, true}};

const Switch* findSwitch(const std::string& name) {
  for (const Switch& s : kSwitches) {
    if (name == s.name) return &s;
  }
  return nullptr;
}

bool takesValue(const std::string& name) {
  return name == "--scene" || name == "--size" || name == "--frames" || name == "--screenshot";
}

// An option that takes a value: sets it; returns what is wrong with the value, or nothing.
std::string setValue(const std::string& name, const std::string& value, Options& o) {
  if (name == "--scene") {
    o.scene = value;
  } else if (name == "--size") {
    if (!parseSize(value, &o.width, &o.height)) {
      return "--size " + value + ": expected WxH, e.g. 800x600 (16 to 8192 pixels a side)";
    }
  } else if (name == "--frames") {
    if (!parseInt(value, 0, 1000000, &o.frames)) {
      return "--frames " + value + ": expected a whole number of frames, 0 or more";
    }
  } else if (name == "--screenshot") {
    o.screenshot = value;
  }
  return "";
}

}  // namespace

ParseResult parseOptions(const std::vector<std::string>& args) {
  ParseResult result;
  Options& o = result.options;
  for (std::size_t k = 0; k < args.size(); ++k) {
    // --name=value or --name value.
    std::string name = args[k], value;
    bool inlineValue = false;
    if (const std::size_t eq = name.find('=');
        name.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inlineValue = true;
    }

    if (name == "--help" || name == "-h") {
      o.help = true;
    } else if (const Switch* s = findSwitch(name)) {
      if (inlineValue) {
        result.error = name + " takes no value";
        return result;
      }
      o.*(s->field) = s->value;
    } else if (takesValue(name)) {
      if (!inlineValue && k + 1 >= args.size()) {
        result.error = name + " needs a value";
        return result;
      }
      if (!inlineValue) value = args[++k];
      result.error = setValue(name, value, o);
      if (!result.error.empty()) return result;
    } else {
      result.error = "unknown option '" + args[k] + "'";
      return result;
    }
  }
  return result;
}

std::string usage(const std::string& program) {
  return "Usage: " + program + R"( [options]

Shows a scene of Assignment 6 running on the student files this viewer was built with.

Options:
  --scene NAME       the scene to start with (default cloth_shear; --list shows them all)
  --size WxH         size of the scene area in pixels (default 800x600); the control panel
                     adds its width to the window unless --no-gui
  --frames N         run N frames (no real-time pacing), save a screenshot and exit
  --screenshot PATH  where --frames saves its PNG (default <scene>_frame<N>.png)
  --no-gui           no control panel: the window shows the scene only (then a --frames
                     screenshot equals the headless render of the same frame)
  --paused           start paused
  --side-by-side     in a scene with an integrator switch (task 7): the scene twice, with
                     symplectic Euler on the left and implicit Euler on the right
  --no-vsync         do not wait for the display between frames
  --list             print the scene names and exit
  --help             this text

Keys (when the panel is not typing):
  Space      pause / run            N or Right  one frame (pauses)
  R          reset the scene        D           reset to the scene's defaults
  S          save the scene as PNG  Shift+S     save the whole window (panel too) as PNG
  [ and ]    previous / next scene  H or Tab    hide / show the panel
  Esc or Q   quit
Mouse: left-drag a particle, an obstacle disc, the emitter or a Box2D body.
)";
}

}  // namespace a6::viewer
