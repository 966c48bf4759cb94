// Benchmark: headless frames per second at 512x512, and where a frame's time goes, for a
// mass-spring scene (cloth_shear) and a Box2D scene (car), with the solution's files.
//
// One frame is what a6_render and the golden tests do per picture:
//   simulate   Scene::advanceFrame()          the student's code (cloth: 10 substeps)
//   snapshot   Scene::snapshot()              the scene as plain data
//   draw       Renderer::render(snapshot)     triangles on the CPU, GL draw, glReadPixels
// Each part is timed on its own with a steady clock; the benchmark's time is their sum (manual
// time), so fps = 1 / (simulate + snapshot + draw). The counters give each part in ms per frame
// and the share of the frame spent simulating (sim_share) and drawing (draw_share, snapshot
// included). geometry_ms is the CPU half of draw (buildGeometry: the snapshot's triangles),
// timed apart from the frame on the same snapshot; the rest of draw is OpenGL (upload,
// rasterisation, glReadPixels). The label is the GL renderer.
//
// Run it from a Release build (see tests/bench/README.md):
//   a6_render_bench --benchmark_out=render.json --benchmark_out_format=json
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "contexts/gl_context.h"
#include "render/geometry.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace {

constexpr int kSize = 512;  // pixels, square
// The car leaves its 60 m of terrain after about ten seconds: start the scene again before
// (outside the timed parts).
constexpr int kResetEvery = 480;

// One headless context and renderer for the whole run.
struct Gl {
  a6::ContextResult context;
  std::unique_ptr<a6::Renderer> renderer;
  std::string error;
};

Gl& gl() {
  static Gl g = [] {
    Gl out;
    out.context = a6::makeHeadlessContext(kSize, kSize);
    if (!out.context) {
      out.error = out.context.error;
      return out;
    }
    out.renderer = std::make_unique<a6::Renderer>(*out.context.context);
    if (!out.renderer->ok()) out.error = out.renderer->error();
    return out;
  }();
  return g;
}

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

void BM_HeadlessFrame(benchmark::State& state, const std::string& sceneName) {
  Gl& g = gl();
  if (!g.error.empty()) {
    state.SkipWithError(("no headless OpenGL: " + g.error).c_str());
    return;
  }
  std::unique_ptr<a6::Scene> scene = a6::makeScene(sceneName);
  if (!scene) {
    state.SkipWithError(("unknown scene " + sceneName).c_str());
    return;
  }
  using Clock = std::chrono::steady_clock;
  double simulate = 0, snapshot = 0, draw = 0, geometry = 0;
  std::int64_t frames = 0;
  for (auto _ : state) {
    if (scene->frame() >= kResetEvery) scene->reset(scene->params());
    const Clock::time_point t0 = Clock::now();
    scene->advanceFrame();
    const Clock::time_point t1 = Clock::now();
    const a6::Snapshot picture = scene->snapshot();
    const Clock::time_point t2 = Clock::now();
    const a6::Image image = g.renderer->render(picture, kSize, kSize);
    const Clock::time_point t3 = Clock::now();
    benchmark::DoNotOptimize(image.pixels.data());
    if (image.empty()) {
      state.SkipWithError(g.renderer->error().c_str());
      return;
    }
    // The CPU half of draw, again, outside the frame's time.
    const Clock::time_point g0 = Clock::now();
    const std::vector<a6::Vertex> triangles =
        a6::buildGeometry(picture, kSize, kSize, a6::RenderOptions());
    geometry += seconds(Clock::now() - g0);
    benchmark::DoNotOptimize(triangles.data());
    simulate += seconds(t1 - t0);
    snapshot += seconds(t2 - t1);
    draw += seconds(t3 - t2);
    ++frames;
    state.SetIterationTime(seconds(t3 - t0));
  }
  const double total = simulate + snapshot + draw;
  if (frames == 0 || total <= 0) return;
  state.counters["fps"] = frames / total;
  state.counters["simulate_ms"] = 1e3 * simulate / frames;
  state.counters["snapshot_ms"] = 1e3 * snapshot / frames;
  state.counters["draw_ms"] = 1e3 * draw / frames;
  state.counters["geometry_ms"] = 1e3 * geometry / frames;
  state.counters["sim_share"] = simulate / total;
  state.counters["draw_share"] = (snapshot + draw) / total;
  state.SetLabel(g.context.context->description());
}

// Five repetitions of at least a second each: the JSON keeps every repetition (on a shared
// machine the fastest is the best estimate of an undisturbed frame) and their mean, median and
// spread.
BENCHMARK_CAPTURE(BM_HeadlessFrame, cloth_shear, std::string("cloth_shear"))
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->Repetitions(5);
BENCHMARK_CAPTURE(BM_HeadlessFrame, car, std::string("car"))
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->Repetitions(5);

}  // namespace

BENCHMARK_MAIN();
