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

}  // namespace

int main(int argc, char** argv) {
  std::string sceneName, screenshot, out;
  int frames = -1, areaW = 0, areaH = 0, tolerance = 2, viewLeft = -1;
  double maxFraction = 0.001;
  bool allowBlankReference = false, lossy = false, otherIntegrator = false;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++k];
    };
    if (a == "--scene")
      sceneName = value();
    else if (a == "--frames")
      frames = std::atoi(value().c_str());
    else if (a == "--screenshot")
      screenshot = value();
    else if (a == "--out")
      out = value();
    else if (a == "--tolerance")
      tolerance = std::atoi(value().c_str());
    else if (a == "--max-fraction")
      maxFraction = std::atof(value().c_str());
    else if (a == "--allow-blank-reference")
      allowBlankReference = true;
    else if (a == "--lossy")
      lossy = true;
    else if (a == "--view-left")
      viewLeft = std::atoi(value().c_str());
    else if (a == "--other-integrator")
      otherIntegrator = true;
    else if (a == "--scene-area") {
      if (!parseSize(value(), &areaW, &areaH)) {
        std::fprintf(stderr, "--scene-area: expected WxH\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  if (sceneName.empty() || screenshot.empty() || frames < 0 || (viewLeft >= 0 && areaW == 0)) {
    std::fprintf(stderr,
                 "usage: %s --scene NAME --frames N --screenshot PATH [--scene-area WxH] "
                 "[--view-left X] [--other-integrator] [--tolerance T] [--max-fraction F] "
                 "[--allow-blank-reference] [--lossy] [--out DIR]\n",
                 argv[0]);
    return 2;
  }

  // The viewer's picture, and its scene area.
  const ImageResult shot = readPng(screenshot);
  if (!shot) {
    std::printf("FAIL: the viewer's screenshot: %s\n", shot.error.c_str());
    return 1;
  }
  const Image& window = shot.image;
  if (areaW == 0) areaW = window.width, areaH = window.height;
  const int left = std::max(viewLeft, 0);
  if (left + areaW > window.width || areaH > window.height) {
    std::printf("FAIL: the screenshot is %dx%d, smaller than the scene area %dx%d\n", window.width,
                window.height, areaW, areaH);
    return 1;
  }
  const Image area = crop(window, left, 0, areaW, areaH);
  std::printf("screenshot %s: %dx%d, scene area %dx%d\n", screenshot.c_str(), window.width,
              window.height, areaW, areaH);

  // The headless reference of the same frame.
  ContextResult context = makeHeadlessContext(areaW, areaH);
  if (!context) {
    std::printf("FAIL: no headless OpenGL context for the reference: %s\n", context.error.c_str());
    return 1;
  }
  Renderer renderer(*context.context);
  if (!renderer.ok()) {
    std::printf("FAIL: %s\n", renderer.error().c_str());
    return 1;
  }
  Image reference;
  try {
    std::unique_ptr<Scene> scene = makeScene(sceneName);
    if (!scene) {
      std::printf("FAIL: unknown scene '%s'\n", sceneName.c_str());
      return 1;
    }
    if (otherIntegrator) {
      SceneParams params = scene->params();
      params.implicit = !params.implicit;
      scene->reset(params);
    }
    for (int k = 0; k < frames; ++k) scene->advanceFrame();
    reference = renderer.render(scene->snapshot(), areaW, areaH, RenderOptions());
  } catch (const std::exception& e) {
    std::printf("FAIL: running %s headless threw: %s\n", sceneName.c_str(), e.what());
    return 1;
  }
  if (reference.empty()) {
    std::printf("FAIL: the headless render: %s\n", renderer.error().c_str());
    return 1;
  }
  std::printf("reference: headless %s (%s), frame %d\n", context.context->backend().c_str(),
              context.context->description().c_str(), frames);
  if (!out.empty()) {
    std::string e = writePng(reference, out + "/reference.png");
    if (e.empty()) e = writePng(differenceImage(area, reference), out + "/difference.png");
    if (!e.empty()) std::printf("note: %s\n", e.c_str());
  }

  bool ok = true;

  // 1. A real picture.
  const Blankness mine = measure(area), theirs = measure(reference);
  std::printf("scene area: %zu colours, %.2f %% not background (reference: %zu colours, %.2f %%)\n",
              mine.colours, 100 * mine.nonBackground, theirs.colours, 100 * theirs.nonBackground);
  if (theirs.blank()) {
    std::printf(
        "%s: the headless reference itself is blank: the student code draws (almost) "
        "nothing in %s at frame %d\n",
        allowBlankReference ? "note" : "FAIL", sceneName.c_str(), frames);
    ok &= allowBlankReference;
  } else if (mine.blank()) {
    std::printf("FAIL: the viewer's scene area is blank\n");
    ok = false;
  }
  // Colours covering at least 0.1 % of the reference must cover at least half as much here.
  const auto want = histogram(reference), have = histogram(area);
  const double pixels = double(areaW) * areaH;
  int missing = 0;
  for (const auto& [colour, count] : want) {
    if (lossy || count < 0.001 * pixels) continue;
    const auto it = have.find(colour);
    const long got = it == have.end() ? 0 : it->second;
    if (got * 2 < count) {
      std::printf("FAIL: colour #%08x covers %ld pixels in the reference, %ld in the screenshot\n",
                  colour, count, got);
      ++missing;
    }
  }
  ok &= missing == 0;

  // 2. The same pixels as the headless renderer.
  const ImageComparison c = compare(area, reference, tolerance);
  std::printf(
      "viewer vs headless: identical %s, max channel difference %d, %lld pixels over %d "
      "(%.4f %%, allowed %.4f %%)\n",
      c.identical ? "yes" : "no", c.maxChannelDiff, static_cast<long long>(c.pixelsOverTolerance),
      tolerance, 100 * c.fractionOverTolerance, 100 * maxFraction);
  if (!c.within(maxFraction)) {
    std::printf("FAIL: the viewer's scene differs from the headless render%s\n",
                out.empty() ? "" : " (see reference.png and difference.png)");
    ok = false;
  }

  // 3. The panel, when there is one.
  if (viewLeft < 0 && areaW < window.width) {
    const Image panel = crop(window, areaW, 0, window.width - areaW, window.height);
    const std::size_t colours = histogram(panel).size();
    std::printf("panel: %dx%d, %zu colours\n", panel.width, panel.height, colours);
    if (colours < 8) {
      std::printf("FAIL: the panel right of the scene is (nearly) a flat colour: no ImGui panel\n");
      ok = false;
    }
  }

  std::printf("%s\n", ok ? "PASS" : "FAIL");
  if (ok) return 0;
  return theirs.blank() ? 3 : 1;
}
