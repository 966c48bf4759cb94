// a6_render: renders scenes headlessly to PNG, composes contact sheets, and re-renders the
// golden images of tests/golden/ from the solution. See docs/rendering.md.
//
//   a6_render --list
//   a6_render --scene cloth_shear --times 0,0.5,1 [--size 512x512] [--out DIR] [--strain]
//   a6_render --scene pendulum,rope --frames 0,30,60 --sheet [--out DIR]
//   a6_render_solution --goldens [--only NAME,...] [--variant SUFFIX]
//   a6_render_solution --replays [--out DIR]
//
// Scenes run through the same harness request as the golden tests (a SceneRequest,
// in-process here), so what this program draws is what the tests compare.
//
// Design note: two binaries. a6_render links the configured student files (A6_STUDENT) so a
// student can look at their own frames; a6_render_solution links the solution, and only a
// binary linked with the solution re-renders references (--goldens refuses otherwise).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "contexts/gl_context.h"
#include "harness/student_code.h"
#include "image/image.h"
#include "render/golden.h"
#include "render/renderer.h"
#include "render/replay.h"
#include "scenes/scene.h"

#ifndef A6_RENDER_STUDENT_SET
#define A6_RENDER_STUDENT_SET "unknown"
#endif
#ifndef A6_RENDER_STUDENT
#define A6_RENDER_STUDENT A6_RENDER_STUDENT_SET
#endif
namespace a6::paths {
extern const char golden_dir[];  // tests/golden (cmake/A6FastBuild.cmake, a6_configured_path)
}  // namespace a6::paths

namespace {

using namespace a6;

struct Options {
  std::vector<std::string> scenes;
  std::vector<int> frames;
  std::vector<double> times;
  bool byTime = false;
  int width = 512, height = 512;
  std::string out = ".";
  bool strain = false;
  HeadlessBackend backend = HeadlessBackend::Auto;
  bool sheet = false;
  std::string sheetPath;  ///< empty: <out>/<scene>_sheet.png, or <out>/sheet.png for several
  int columns = 0;        ///< 0: one row per scene
  bool list = false, help = false;
  bool goldens = false;
  bool replays = false;  ///< write the reference replays (out: --out, default <goldenDir>/replays)
  bool outGiven = false;
  std::string goldenDir = a6::paths::golden_dir;
  std::vector<std::string> only;
  std::string variant;
};

std::string usage() {
  return "usage: a6_render --scene NAME[,NAME...] (--frames N,N,... | --times S,S,...) [options]\n"
         "       a6_render --list\n"
         "       a6_render_solution --goldens [--golden-dir DIR] [--only NAME,...] [--variant S]\n"
         "       a6_render_solution --replays [--golden-dir DIR] [--out DIR]\n"
         "\n"
         "Renders scenes headlessly (OpenGL 3.3 core on OSMesa or EGL) to PNG.\n"
         "  --scene NAMES       scenes to render (comma-separated; --list shows them)\n"
         "  --frames LIST       frames since the scene started, e.g. 0,30,60 (0: as built)\n"
         "  --times LIST        times in seconds, e.g. 0,0.5,1 (rounded to the nearest frame)\n"
         "  --size WxH          image size in pixels (default 512x512)\n"
         "  --out DIR           output folder (default .): <scene>_fNNNN.png\n"
         "  --strain            colour springs by strain (blue compressed, red stretched)\n"
         "  --backend B         auto (default), osmesa or egl\n"
         "  --sheet[=FILE]      one contact sheet of every requested frame, with captions,\n"
         "                      instead of one file per frame (default <out>/<scene>_sheet.png)\n"
         "  --columns N         contact-sheet columns (default: one row per scene)\n"
         "  --list              list the scenes and exit\n"
         "  --goldens           re-render every reference image of the golden manifest\n"
         "                      (needs the solution: use a6_render_solution)\n"
         "  --golden-dir DIR    folder of manifest.json (default: the source tree's tests/golden)\n"
         "  --only NAMES        --goldens: only these images (comma-separated)\n"
         "  --variant SUFFIX    --goldens: write <name>.<SUFFIX>.png as an extra approved\n"
         "                      baseline instead of replacing the primary one\n"
         "  --replays           write the reference replays the grader's report plays beside a\n"
         "                      student's run: <scene>.json for every scene of the manifest, in\n"
         "                      --out (default: <golden-dir>/replays; needs the solution)\n"
         "This binary runs the '" A6_RENDER_STUDENT "' student files.\n";
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty()) out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

bool parseInt(const std::string& text, int lo, int hi, int* out) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < lo || value > hi) return false;
  *out = static_cast<int>(value);
  return true;
}

bool parseDouble(const std::string& text, double* out) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value < 0) return false;
  *out = value;
  return true;
}

// An option without a value (--sheet's is optional): sets it and returns true; false when
// `name` is none of them.
bool parseFlag(const std::string& name, const std::string& value, bool hasValue, Options& o) {
  if (name == "--help" || name == "-h") {
    o.help = true;
  } else if (name == "--list") {
    o.list = true;
  } else if (name == "--strain") {
    o.strain = true;
  } else if (name == "--goldens") {
    o.goldens = true;
  } else if (name == "--replays") {
    o.replays = true;
  } else if (name == "--sheet") {
    o.sheet = true;
    if (hasValue) o.sheetPath = value;
  } else {
    return false;
  }
  return true;
}

std::string parseFrames(const std::string& value, Options& o) {
  o.frames.clear();
  for (const std::string& item : split(value)) {
    int frame = 0;
    if (!parseInt(item, 0, 36000, &frame)) {
      return "--frames: '" + item + "' is not a frame number in [0, 36000]";
    }
    o.frames.push_back(frame);
  }
  o.byTime = false;
  return "";
}

std::string parseTimes(const std::string& value, Options& o) {
  o.times.clear();
  for (const std::string& item : split(value)) {
    double t = 0;
    if (!parseDouble(item, &t)) return "--times: '" + item + "' is not a time >= 0 in seconds";
    o.times.push_back(t);
  }
  o.byTime = true;
  return "";
}

std::string parseVariant(const std::string& value, Options& o) {
  o.variant = value;
  const bool plain = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (!plain) return "--variant " + value + ": use letters, digits, '_' and '-' only";
  return "";
}

// An option with a value: sets it; returns what is wrong, empty when nothing is.
std::string parseValue(const std::string& name, const std::string& value, Options& o) {
  if (name == "--scene") {
    o.scenes = split(value);
  } else if (name == "--frames") {
    return parseFrames(value, o);
  } else if (name == "--times") {
    return parseTimes(value, o);
  } else if (name == "--size") {
    const std::size_t x = value.find('x');
    if (x == std::string::npos || !parseInt(value.substr(0, x), 16, 8192, &o.width) ||
        !parseInt(value.substr(x + 1), 16, 8192, &o.height)) {
      return "--size " + value + ": expected WxH, e.g. 512x512 (16 to 8192 pixels a side)";
    }
  } else if (name == "--out") {
    o.out = value;
    o.outGiven = true;
  } else if (name == "--backend") {
    if (!parseHeadlessBackend(value, &o.backend)) {
      return "--backend " + value + ": expected auto, osmesa or egl";
    }
  } else if (name == "--columns") {
    if (!parseInt(value, 1, 64, &o.columns)) return "--columns " + value + ": expected 1 to 64";
  } else if (name == "--golden-dir") {
    o.goldenDir = value;
  } else if (name == "--only") {
    o.only = split(value);
  } else if (name == "--variant") {
    return parseVariant(value, o);
  } else {
    return "unknown option " + name;
  }
  return "";
}

// Parses argv; returns an error message, empty on success.
std::string parse(int argc, char** argv, Options& o) {
  for (int k = 1; k < argc; ++k) {
    // --name=value, --name value, or a flag.
    std::string name = argv[k], value;
    bool hasValue = false;
    if (const std::size_t eq = name.find('=');
        name.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      hasValue = true;
    }
    if (parseFlag(name, value, hasValue, o)) continue;
    if (!hasValue) {
      if (k + 1 >= argc) return name + " needs a value";
      value = argv[++k];
    }
    if (std::string error = parseValue(name, value, o); !error.empty()) return error;
  }
  // What to do: a flag that needs nothing more, or scenes and their frames.
  if (o.help || o.list || o.goldens || o.replays) return "";
  if (o.scenes.empty()) return "say which scene to render: --scene NAME (--list shows them)";
  if (o.frames.empty() && o.times.empty())
    return "say which frames: --frames 0,30 or --times 0,0.5";
  return "";
}

std::string sceneList() {
  std::string text;
  for (const std::string& name : sceneNames()) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// A headless context and a renderer, or an error saying what to install.
struct Gl {
  ContextResult context;
  std::unique_ptr<Renderer> renderer;
  std::string error;
};

Gl makeGl(HeadlessBackend backend, int width, int height) {
  Gl gl;
  gl.context = makeHeadlessContext(width, height, backend);
  if (!gl.context) {
    gl.error = "a6_render needs a headless OpenGL 3.3 core context (backend " +
               std::string(toString(backend)) + "; built with: " + availableHeadlessBackends() +
               ").\n" + gl.context.error +
               "\nOn Debian 12: apt install libosmesa6 (OSMesa) or libegl1 libegl-mesa0 "
               "(EGL), or run scripts/install-deps.sh.";
    return gl;
  }
  gl.renderer = std::make_unique<Renderer>(*gl.context.context);
  if (!gl.renderer->ok()) gl.error = gl.renderer->error();
  return gl;
}

// Runs `scene` with the linked student files and records the snapshots after `frames`.
harness::SceneResult runScene(const std::string& scene, const std::vector<int>& frames) {
  harness::SceneRequest request;
  request.scene = scene;
  request.frames = frames;
  return harness::makeInProcess()->ask(request);
}

std::string frameFile(const std::string& scene, int frame) {
  char text[32];
  std::snprintf(text, sizeof text, "_f%04d.png", frame);
  return scene + text;
}

std::string caption(const std::string& scene, int frame, double dt) {
  char text[96];
  // Short: the sheet's font is 12 px a letter, so a 256 px cell holds 21 (the frame goes first).
  std::snprintf(text, sizeof text, "%s %.2fs f%d", scene.c_str(), frame * dt, frame);
  return text;
}

// The frames of `scene` to render: --frames as given, or --times at the nearest whole frame.
std::vector<int> framesToRender(const Options& o, const std::string& scene, double dt) {
  if (!o.byTime) return o.frames;
  std::vector<int> frames;
  for (double t : o.times) {
    const int frame = static_cast<int>(std::lround(t / dt));
    if (std::abs(frame * dt - t) > 1e-9) {
      std::printf("  %s: %g s is not a whole frame of %g s: frame %d (%.4f s)\n", scene.c_str(), t,
                  dt, frame, frame * dt);
    }
    frames.push_back(frame);
  }
  return frames;
}

// The contact sheet's cells so far: each frame's image and caption.
struct Sheet {
  std::vector<Image> images;
  std::vector<std::string> labels;
};

enum class SceneOutcome { Rendered, CodeFailed, RenderFailed };

// Runs `scene` and writes its frames as PNG files, or adds them to the sheet (--sheet).
SceneOutcome renderScene(const Options& o, Gl& gl, const std::string& scene, Sheet& sheet) {
  const double dt = defaultParams(scene).dt;
  const std::vector<int> frames = framesToRender(o, scene, dt);
  const harness::SceneResult result = runScene(scene, frames);
  if (!result.ok()) {
    std::fprintf(stderr, "a6_render: %s: the student code failed: %s\n", scene.c_str(),
                 result.error.c_str());
    return SceneOutcome::CodeFailed;
  }
  RenderOptions options;
  options.colorSpringsByStrain = o.strain;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Image image = gl.renderer->render(result.snapshots[k], o.width, o.height, options);
    if (image.empty()) {
      std::fprintf(stderr, "a6_render: %s\n", gl.renderer->error().c_str());
      return SceneOutcome::RenderFailed;
    }
    if (o.sheet) {
      sheet.images.push_back(image);
      sheet.labels.push_back(caption(scene, frames[k], dt));
      continue;
    }
    const std::string path = (std::filesystem::path(o.out) / frameFile(scene, frames[k])).string();
    if (std::string error = writePng(image, path); !error.empty()) {
      std::fprintf(stderr, "a6_render: %s\n", error.c_str());
      return SceneOutcome::RenderFailed;
    }
    std::printf("  %s  (%s, frame %d, t = %.3f s)\n", path.c_str(), scene.c_str(), frames[k],
                frames[k] * dt);
  }
  return SceneOutcome::Rendered;
}

// Composes the contact sheet (a row per scene unless --columns) and writes it.
bool writeSheet(const Options& o, const Sheet& sheet) {
  const int perScene = static_cast<int>(o.byTime ? o.times.size() : o.frames.size());
  const int columns = o.columns > 0 ? o.columns : std::max(perScene, 1);
  std::string path = o.sheetPath;
  if (path.empty()) {
    path = (std::filesystem::path(o.out) /
            (o.scenes.size() == 1 ? o.scenes[0] + "_sheet.png" : std::string("sheet.png")))
               .string();
  }
  if (std::string error = writePng(contactSheet(sheet.images, columns, sheet.labels), path);
      !error.empty()) {
    std::fprintf(stderr, "a6_render: %s\n", error.c_str());
    return false;
  }
  std::printf("  %s  (contact sheet, %zu frames)\n", path.c_str(), sheet.images.size());
  return true;
}

int renderScenes(const Options& o) {
  // Every scene known, and a GL context, before anything runs.
  for (const std::string& scene : o.scenes) {
    if (!sceneInfo(scene)) {
      std::fprintf(stderr, "a6_render: unknown scene '%s'. Scenes: %s\n", scene.c_str(),
                   sceneList().c_str());
      return 2;
    }
  }
  Gl gl = makeGl(o.backend, o.width, o.height);
  if (!gl.error.empty()) {
    std::fprintf(stderr, "%s\n", gl.error.c_str());
    return 1;
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  std::printf("a6_render: %s student files, %s: %s\n", A6_RENDER_STUDENT,
              gl.context.context->backend().c_str(), gl.context.context->description().c_str());

  // A scene whose code fails is skipped (and the exit code says so); a failed render stops all.
  Sheet sheet;
  int failures = 0;
  for (const std::string& scene : o.scenes) {
    const SceneOutcome outcome = renderScene(o, gl, scene, sheet);
    if (outcome == SceneOutcome::RenderFailed) return 1;
    if (outcome == SceneOutcome::CodeFailed) ++failures;
  }
  if (o.sheet && !sheet.images.empty() && !writeSheet(o, sheet)) return 1;
  return failures ? 1 : 0;
}

// Whether --only picked `image` (no --only: every image).
bool selected(const Options& o, const golden::GoldenImage& image) {
  return o.only.empty() || std::find(o.only.begin(), o.only.end(), image.name) != o.only.end();
}

// Every --only name is an image of the manifest, and every image's scene is known: 0, or the
// exit code.
int checkGoldenRequest(const Options& o, const golden::Manifest& manifest,
                       const std::string& manifestPath) {
  for (const std::string& name : o.only) {
    if (!manifest.find(name)) {
      std::fprintf(stderr, "a6_render: --only %s: no such image in %s\n", name.c_str(),
                   manifestPath.c_str());
      return 2;
    }
  }
  for (const golden::GoldenImage& image : manifest.images) {
    if (!sceneInfo(image.scene)) {
      std::fprintf(stderr, "a6_render: %s: image %s: unknown scene '%s'. Scenes: %s\n",
                   manifestPath.c_str(), image.name.c_str(), image.scene.c_str(),
                   sceneList().c_str());
      return 1;
    }
  }
  return 0;
}

// The selected images' scenes, run once each, recording every frame their images need.
struct GoldenRuns {
  std::map<std::string, std::vector<int>> framesOf;
  std::map<std::string, harness::SceneResult> runs;
};

bool runGoldenScenes(const Options& o, const golden::Manifest& manifest, GoldenRuns& g) {
  for (const golden::GoldenImage& image : manifest.images) {
    if (selected(o, image)) g.framesOf[image.scene].push_back(image.frame);
  }
  for (const auto& [scene, frames] : g.framesOf) {
    g.runs[scene] = runScene(scene, frames);
    if (!g.runs[scene].ok()) {
      std::fprintf(stderr, "a6_render: %s: %s\n", scene.c_str(), g.runs[scene].error.c_str());
      return false;
    }
  }
  return true;
}

// Renders `image` from its scene's run and writes it: over its primary baseline (the manifest
// entry then names this renderer), or as the --variant baseline.
bool writeGolden(const Options& o, Gl& gl, const GoldenRuns& g, const std::string& description,
                 golden::GoldenImage& image) {
  const std::vector<int>& frames = g.framesOf.at(image.scene);
  const std::size_t k = std::find(frames.begin(), frames.end(), image.frame) - frames.begin();
  const Image picture =
      gl.renderer->render(g.runs.at(image.scene).snapshots[k], image.width, image.height);
  if (picture.empty()) {
    std::fprintf(stderr, "a6_render: %s: %s\n", image.name.c_str(), gl.renderer->error().c_str());
    return false;
  }
  std::string file = image.baselines.front();
  if (!o.variant.empty()) {
    file = image.name + "." + o.variant + ".png";
    if (std::find(image.baselines.begin(), image.baselines.end(), file) == image.baselines.end())
      image.baselines.push_back(file);
  } else {
    image.renderer = description;
    image.studentFiles = "solution";
  }
  image.time = image.frame * defaultParams(image.scene).dt;
  const std::string path = (std::filesystem::path(o.goldenDir) / file).string();
  if (std::string error = writePng(picture, path); !error.empty()) {
    std::fprintf(stderr, "a6_render: %s\n", error.c_str());
    return false;
  }
  std::printf("  %-28s %s frame %d (%.3f s), %dx%d\n", file.c_str(), image.scene.c_str(),
              image.frame, image.time, image.width, image.height);
  return true;
}

// Re-renders the reference images of the manifest with the linked (solution) files.
int renderGoldens(const Options& o) {
  if (std::string(A6_RENDER_STUDENT_SET) != "solution") {
    std::fprintf(stderr,
                 "a6_render --goldens: this binary runs the '%s' student files; reference images "
                 "come from the solution only. Run a6_render_solution --goldens instead.\n",
                 A6_RENDER_STUDENT);
    return 2;
  }
  // The manifest, checked against the request, and a GL context.
  const std::string manifestPath = (std::filesystem::path(o.goldenDir) / "manifest.json").string();
  golden::ManifestResult read = golden::readManifest(manifestPath);
  if (!read) {
    std::fprintf(stderr, "a6_render: %s\n", read.error.c_str());
    return 1;
  }
  golden::Manifest& manifest = read.manifest;
  if (const int code = checkGoldenRequest(o, manifest, manifestPath); code != 0) return code;
  Gl gl = makeGl(o.backend, 256, 256);
  if (!gl.error.empty()) {
    std::fprintf(stderr, "%s\n", gl.error.c_str());
    return 1;
  }
  const std::string description = gl.context.context->description();
  std::printf("a6_render --goldens: solution files, %s: %s\n",
              gl.context.context->backend().c_str(), description.c_str());

  // The runs, the images, then the manifest that describes them.
  GoldenRuns runs;
  if (!runGoldenScenes(o, manifest, runs)) return 1;
  int written = 0;
  for (golden::GoldenImage& image : manifest.images) {
    if (!selected(o, image)) continue;
    if (!writeGolden(o, gl, runs, description, image)) return 1;
    ++written;
  }
  if (std::string error = golden::writeManifest(manifest, manifestPath); !error.empty()) {
    std::fprintf(stderr, "a6_render: %s\n", error.c_str());
    return 1;
  }
  std::printf("a6_render: %d reference image(s) written; %s updated\n", written,
              manifestPath.c_str());
  return 0;
}

// The reference replays (render/replay.h): every scene of the golden manifest, run with the
// solution from frame 0 to its last image's frame (at least 60), about 60 frames of it packed
// into <dir>/<scene>.json. The grader plays a student's run beside them in its report.
int writeReplays(const Options& o) {
  if (std::string(A6_RENDER_STUDENT_SET) != "solution") {
    std::fprintf(stderr,
                 "a6_render --replays: reference replays come from the solution only: run "
                 "a6_render_solution --replays\n");
    return 2;
  }
  const std::string manifestPath = (std::filesystem::path(o.goldenDir) / "manifest.json").string();
  const golden::ManifestResult read = golden::readManifest(manifestPath);
  if (!read) {
    std::fprintf(stderr, "a6_render: %s\n", read.error.c_str());
    return 1;
  }
  std::map<std::string, int> last;
  for (const golden::GoldenImage& image : read.manifest.images)
    last[image.scene] = std::max({last[image.scene], image.frame, 60});
  const std::filesystem::path dir =
      o.outGiven ? std::filesystem::path(o.out) : std::filesystem::path(o.goldenDir) / "replays";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (const auto& [scene, frame] : last) {
    harness::SceneRequest request;
    request.scene = scene;
    request.frames = replay::replayFrames(frame);
    request.lean = true;
    const harness::SceneResult result = harness::makeInProcess()->ask(request);
    if (!result.ok()) {
      std::fprintf(stderr, "a6_render: %s: %s\n", scene.c_str(), result.error.c_str());
      return 1;
    }
    const SceneParams params = defaultParams(scene);
    const replay::Recording recording{scene,          params.dt,        Vec2(0, -params.gravity),
                                      request.frames, result.snapshots, result.energies};
    const std::string text = replay::pack(recording).dump() + "\n";
    const std::filesystem::path file = dir / (scene + ".json");
    std::ofstream(file, std::ios::binary) << text;
    std::printf("  %s  (%zu frames to frame %d, %zu bytes)\n", file.c_str(), request.frames.size(),
                frame, text.size());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::string error = parse(argc, argv, options); !error.empty()) {
    std::fprintf(stderr, "a6_render: %s\n\n%s", error.c_str(), usage().c_str());
    return 2;
  }
  if (options.help) {
    std::printf("%s", usage().c_str());
    return 0;
  }
  if (options.list) {
    for (const std::string& name : sceneNames()) {
      const SceneInfo* info = sceneInfo(name);
      std::printf("%-18s task %d  %s\n", name.c_str(), info->task, info->title.c_str());
    }
    return 0;
  }
  if (options.replays) return writeReplays(options);
  return options.goldens ? renderGoldens(options) : renderScenes(options);
}
