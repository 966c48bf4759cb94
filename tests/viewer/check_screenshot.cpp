// Checks a screenshot saved by `a6_viewer --frames N` against the headless renderer:
//
//   a6_viewer_check --scene NAME --frames N --screenshot PATH [--scene-area WxH]
//                   [--view-left X] [--other-integrator] [--tolerance T] [--max-fraction F]
//                   [--allow-blank-reference] [--lossy] [--out DIR]
//
// 1. The scene area (the whole screenshot, or its top-left WxH with the panel to the right of
//    it) is a real picture: several distinct colours, not all background, and every colour
//    that covers a noticeable part of the reference present in about the same amount.
// 2. It matches the headless render of the same scene at the same frame (makeScene, N x
//    advanceFrame, snapshot, Renderer::render at the same size, default RenderOptions): every
//    channel within T of it on all but a fraction F of the pixels.
// 3. With --scene-area, the panel (what lies right of the scene area) is there: not a flat
//    colour.
// --view-left X: the scene area starts X pixels from the left (a view of --side-by-side), and
// there is no panel check. --other-integrator: the reference runs the scene with the other
// integrator (SceneParams::implicit flipped), as the viewer's twin does side by side.
// --lossy: the screenshot went through a lossy codec (the browser desktop's VNC sends JPEG), so
// the exact-colour count of 1 is skipped and 2 is read with the tolerance and fraction given.
// Prints the measured difference. With --out, writes reference.png and difference.png there.
// Exit code: 0 pass, 1 fail, 2 bad arguments, 3 fail with a blank headless reference (the code
// under test draws nothing there: no other screenshot can pass, so a caller need not try again).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <unordered_set>

#include "contexts/gl_context.h"
#include "image/image.h"
#include "render/palette.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace {

using namespace a6;

std::uint32_t key(Rgba c) {
  return (std::uint32_t(c.r) << 24) | (std::uint32_t(c.g) << 16) | (std::uint32_t(c.b) << 8) | c.a;
}

// Pixel counts by colour.
std::map<std::uint32_t, long> histogram(const Image& image) {
  std::map<std::uint32_t, long> counts;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) ++counts[key(image.at(x, y))];
  }
  return counts;
}

// The w x h pixels at (x, y).
Image crop(const Image& image, int x0, int y0, int w, int h) {
  Image out(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) out.set(x, y, image.at(x0 + x, y0 + y));
  }
  return out;
}

struct Blankness {
  std::size_t colours = 0;
  double nonBackground = 0;  // fraction of pixels
  bool blank() const { return colours < 3 || nonBackground < 0.002; }
};

Blankness measure(const Image& image) {
  const auto counts = histogram(image);
  Blankness b;
  b.colours = counts.size();
  const auto bg = counts.find(key(palette::kBackground));
  const long background = bg == counts.end() ? 0 : bg->second;
  b.nonBackground = 1.0 - static_cast<double>(background) / (double(image.width) * image.height);
  return b;
}

bool parseSize(const std::string& text, int* w, int* h) {
  return std::sscanf(text.c_str(), "%dx%d", w, h) == 2 && *w > 0 && *h > 0;
}

struct Args {
  std::string sceneName, screenshot, out;
  int frames = -1, areaW = 0, areaH = 0, tolerance = 2, viewLeft = -1;
  double maxFraction = 0.001;
  bool allowBlankReference = false, lossy = false, otherIntegrator = false;
};

// Reads the command line into `a`: 0, or the exit code 2 (what was wrong on stderr).
int parseArgs(int argc, char** argv, Args& a) {
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", arg.c_str());
        std::exit(2);
      }
      return argv[++k];
    };
    if (arg == "--scene")
      a.sceneName = value();
    else if (arg == "--frames")
      a.frames = std::atoi(value().c_str());
    else if (arg == "--screenshot")
      a.screenshot = value();
    else if (arg == "--out")
      a.out = value();
    else if (arg == "--tolerance")
      a.tolerance = std::atoi(value().c_str());
    else if (arg == "--max-fraction")
      a.maxFraction = std::atof(value().c_str());
    else if (arg == "--allow-blank-reference")
      a.allowBlankReference = true;
    else if (arg == "--lossy")
      a.lossy = true;
    else if (arg == "--view-left")
      a.viewLeft = std::atoi(value().c_str());
    else if (arg == "--other-integrator")
      a.otherIntegrator = true;
    else if (arg == "--scene-area") {
      if (!parseSize(value(), &a.areaW, &a.areaH)) {
        std::fprintf(stderr, "--scene-area: expected WxH\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "unknown argument '%s'\n", arg.c_str());
      return 2;
    }
  }
  if (a.sceneName.empty() || a.screenshot.empty() || a.frames < 0 ||
      (a.viewLeft >= 0 && a.areaW == 0)) {
    std::fprintf(stderr,
                 "usage: %s --scene NAME --frames N --screenshot PATH [--scene-area WxH] "
                 "[--view-left X] [--other-integrator] [--tolerance T] [--max-fraction F] "
                 "[--allow-blank-reference] [--lossy] [--out DIR]\n",
                 argv[0]);
    return 2;
  }
  return 0;
}

// The viewer's picture, and its scene area (the whole window when --scene-area is not given).
bool readScreenshot(Args& a, Image& window, Image& area) {
  const ImageResult shot = readPng(a.screenshot);
  if (!shot) {
    std::printf("FAIL: the viewer's screenshot: %s\n", shot.error.c_str());
    return false;
  }
  window = shot.image;
  if (a.areaW == 0) a.areaW = window.width, a.areaH = window.height;
  const int left = std::max(a.viewLeft, 0);
  if (left + a.areaW > window.width || a.areaH > window.height) {
    std::printf("FAIL: the screenshot is %dx%d, smaller than the scene area %dx%d\n", window.width,
                window.height, a.areaW, a.areaH);
    return false;
  }
  area = crop(window, left, 0, a.areaW, a.areaH);
  std::printf("screenshot %s: %dx%d, scene area %dx%d\n", a.screenshot.c_str(), window.width,
              window.height, a.areaW, a.areaH);
  return true;
}

// Runs the scene to the frame (with the other integrator for --other-integrator) and renders it.
bool renderFrame(const Args& a, Renderer& renderer, Image& reference) {
  try {
    std::unique_ptr<Scene> scene = makeScene(a.sceneName);
    if (!scene) {
      std::printf("FAIL: unknown scene '%s'\n", a.sceneName.c_str());
      return false;
    }
    if (a.otherIntegrator) {
      SceneParams params = scene->params();
      params.implicit = !params.implicit;
      scene->reset(params);
    }
    for (int k = 0; k < a.frames; ++k) scene->advanceFrame();
    reference = renderer.render(scene->snapshot(), a.areaW, a.areaH, RenderOptions());
  } catch (const std::exception& e) {
    std::printf("FAIL: running %s headless threw: %s\n", a.sceneName.c_str(), e.what());
    return false;
  }
  return true;
}

// The headless reference of the same frame.
bool renderReference(const Args& a, Image& reference) {
  ContextResult context = makeHeadlessContext(a.areaW, a.areaH);
  if (!context) {
    std::printf("FAIL: no headless OpenGL context for the reference: %s\n", context.error.c_str());
    return false;
  }
  Renderer renderer(*context.context);
  if (!renderer.ok()) {
    std::printf("FAIL: %s\n", renderer.error().c_str());
    return false;
  }
  if (!renderFrame(a, renderer, reference)) return false;
  if (reference.empty()) {
    std::printf("FAIL: the headless render: %s\n", renderer.error().c_str());
    return false;
  }
  std::printf("reference: headless %s (%s), frame %d\n", context.context->backend().c_str(),
              context.context->description().c_str(), a.frames);
  return true;
}

// --out: the reference and the difference, to look at.
void writeImages(const std::string& out, const Image& area, const Image& reference) {
  std::string e = writePng(reference, out + "/reference.png");
  if (e.empty()) e = writePng(differenceImage(area, reference), out + "/difference.png");
  if (!e.empty()) std::printf("note: %s\n", e.c_str());
}

// 1. A real picture.
bool checkRealPicture(const Args& a, const Image& area, const Image& reference) {
  bool ok = true;
  const Blankness mine = measure(area), theirs = measure(reference);
  std::printf("scene area: %zu colours, %.2f %% not background (reference: %zu colours, %.2f %%)\n",
              mine.colours, 100 * mine.nonBackground, theirs.colours, 100 * theirs.nonBackground);
  if (theirs.blank()) {
    std::printf(
        "%s: the headless reference itself is blank: the student code draws (almost) "
        "nothing in %s at frame %d\n",
        a.allowBlankReference ? "note" : "FAIL", a.sceneName.c_str(), a.frames);
    ok &= a.allowBlankReference;
  } else if (mine.blank()) {
    std::printf("FAIL: the viewer's scene area is blank\n");
    ok = false;
  }
  // Colours covering at least 0.1 % of the reference must cover at least half as much here.
  const auto want = histogram(reference), have = histogram(area);
  const double pixels = double(a.areaW) * a.areaH;
  int missing = 0;
  for (const auto& [colour, count] : want) {
    if (a.lossy || count < 0.001 * pixels) continue;
    const auto it = have.find(colour);
    const long got = it == have.end() ? 0 : it->second;
    if (got * 2 < count) {
      std::printf("FAIL: colour #%08x covers %ld pixels in the reference, %ld in the screenshot\n",
                  colour, count, got);
      ++missing;
    }
  }
  ok &= missing == 0;
  return ok;
}

// 2. The same pixels as the headless renderer.
bool checkSamePixels(const Args& a, const Image& area, const Image& reference) {
  const ImageComparison c = compare(area, reference, a.tolerance);
  std::printf(
      "viewer vs headless: identical %s, max channel difference %d, %lld pixels over %d "
      "(%.4f %%, allowed %.4f %%)\n",
      c.identical ? "yes" : "no", c.maxChannelDiff, static_cast<long long>(c.pixelsOverTolerance),
      a.tolerance, 100 * c.fractionOverTolerance, 100 * a.maxFraction);
  if (!c.within(a.maxFraction)) {
    std::printf("FAIL: the viewer's scene differs from the headless render%s\n",
                a.out.empty() ? "" : " (see reference.png and difference.png)");
    return false;
  }
  return true;
}

// 3. The panel, when there is one.
bool checkPanel(const Args& a, const Image& window) {
  if (a.viewLeft >= 0 || a.areaW >= window.width) return true;
  const Image panel = crop(window, a.areaW, 0, window.width - a.areaW, window.height);
  const std::size_t colours = histogram(panel).size();
  std::printf("panel: %dx%d, %zu colours\n", panel.width, panel.height, colours);
  if (colours < 8) {
    std::printf("FAIL: the panel right of the scene is (nearly) a flat colour: no ImGui panel\n");
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  if (const int code = parseArgs(argc, argv, a); code != 0) return code;
  Image window, area, reference;
  if (!readScreenshot(a, window, area) || !renderReference(a, reference)) return 1;
  if (!a.out.empty()) writeImages(a.out, area, reference);

  // The three checks, each printing what it measured.
  bool ok = checkRealPicture(a, area, reference);
  ok &= checkSamePixels(a, area, reference);
  ok &= checkPanel(a, window);

  std::printf("%s\n", ok ? "PASS" : "FAIL");
  if (ok) return 0;
  return measure(reference).blank() ? 3 : 1;
}
