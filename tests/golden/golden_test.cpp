// Golden-image checks: every image of tests/golden/manifest.json, rendered here from the
// student's code and compared with its approved references (docs/rendering.md). No student code
// is linked here (target a6_golden_checks): it is reached through a6::test::student()
// (golden_main_in_process.cpp defines the in-process one; a6_grade its sandboxed probe, calling
// registerGoldenChecks from golden_checks.h).
//
// Each image is one test, GoldenTask<task>.<name> (e.g. GoldenTask4.cloth_shear_f120), so the
// task is in the name. The scene runs through the harness (a SceneRequest, the request
// the grader's probe serves); the snapshot is rendered and compared in this process. A failure
// names the tasks the scene runs, gives a hint, and writes actual / expected / difference PNGs.
//
//   a6_golden_tests [gtest flags] [--manifest=FILE] [--failures=DIR] [--tasks=3,4]
//     --manifest  the manifest (default: the source tree's tests/golden/manifest.json)
//     --failures  where failing images go (default: golden_failures/<program> beside the program)
//     --tasks     only the images whose scene runs one of these tasks
//     --verbose   print how every image compares, passed or not
//
// The last line of output, "A6-GOLDEN passed=P failed=F skipped=S", counts the image tests
// (ctest's wrong-version checks read it); without a readable manifest it is "A6-GOLDEN no
// manifest".
//
// Determinism.* checks that a scene rendered twice from scratch gives the same bytes (registered
// by runGoldenTests only: the grader runs the images alone).
#include "render/golden.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "contexts/gl_context.h"
#include "golden_checks.h"
#include "golden_suite.h"
#include "harness/tasks.h"
#include "render/renderer.h"

namespace a6::paths {
extern const char golden_dir[];  // tests/golden (cmake/A6FastBuild.cmake, a6_configured_path)
}  // namespace a6::paths

namespace a6::test {
namespace {

using golden::GoldenImage;

// What the command line chose.
struct Config {
  std::string manifest = std::string(a6::paths::golden_dir) + "/manifest.json";
  std::string failures;
  bool showPaths = true;  // false in the grader: its folders are not the student's
  std::set<int> tasks;    // empty: every image
  bool verbose = false;   // print every comparison, passed or not
};

Config& config() {
  static Config c;
  return c;
}

// Each scene's run through the student's code, shared by all image tests of the program: the
// frames its images need are gathered when they are registered, so that each scene runs once.
class Scenes {
 public:
  static Scenes& get() {
    static Scenes scenes;
    return scenes;
  }

  /// Frames each scene's images need.
  void need(const std::string& scene, int frame) { frames_[scene].push_back(frame); }

  /// The failed run of `scene` (its fault and error), or null when it ran well or not at all.
  const harness::SceneResult* failedRun(const std::string& scene) const {
    auto it = runs_.find(scene);
    return it == runs_.end() || it->second.ok() ? nullptr : &it->second;
  }

  /// The snapshot of `scene` after `frame` frames, or the harness's error.
  const Snapshot* snapshot(const std::string& scene, int frame, std::string* error) {
    auto it = runs_.find(scene);
    if (it == runs_.end()) {
      harness::SceneRequest request;
      request.scene = scene;
      request.frames = frames_[scene];
      it = runs_.emplace(scene, student().ask(request)).first;
    }
    const harness::SceneResult& run = it->second;
    if (!run.ok()) {
      *error = run.error;
      return nullptr;
    }
    const std::vector<int>& frames = frames_[scene];
    for (std::size_t k = 0; k < frames.size() && k < run.snapshots.size(); ++k) {
      if (frames[k] == frame) return &run.snapshots[k];
    }
    *error = "frame " + std::to_string(frame) + " was not recorded";
    return nullptr;
  }

 private:
  std::map<std::string, std::vector<int>> frames_;
  std::map<std::string, harness::SceneResult> runs_;
};

// One headless context and one renderer, made when the first test needs them.
class Session {
 public:
  static Session& get() {
    static Session session;
    return session;
  }

  /// Why there is no renderer ("" when there is one).
  const std::string& glError() const { return glError_; }
  Renderer& renderer() { return *renderer_; }
  const GLContext& context() const { return *context_.context; }

  /// Fails (A6_REQUIRE_GL=1, as in CI) or skips the running test when there is no GL.
  bool requireGl() {
    if (renderer_) return true;
    const char* require = std::getenv("A6_REQUIRE_GL");
    if (require != nullptr && std::string(require) == "1") {
      ADD_FAILURE() << "A6_REQUIRE_GL=1 but no headless OpenGL context: " << glError_;
    } else {
      GTEST_LOG_(WARNING) << "skipped: no headless OpenGL context (install libosmesa6 or "
                             "Mesa's EGL): "
                          << glError_;
    }
    return false;
  }

 private:
  Session() {
    context_ = makeHeadlessContext(256, 256);
    if (!context_) {
      glError_ = context_.error;
      return;
    }
    renderer_ = std::make_unique<Renderer>(*context_.context);
    if (!renderer_->ok()) {
      glError_ = renderer_->error();
      renderer_.reset();
    }
  }

  ContextResult context_;
  std::unique_ptr<Renderer> renderer_;
  std::string glError_;
};

// The head of every failure message: which image, which tasks.
std::string header(const GoldenImage& image) {
  char time[32];
  std::snprintf(time, sizeof time, "%.3f s", image.time);
  std::ostringstream out;
  out << "Golden image " << image.name << ": scene " << image.scene << " after " << image.frame
      << " frames (" << time << "), " << image.width << "x" << image.height << "\n"
      << "  shows:     " << image.shows << "\n"
      << "  exercises: " << golden::describeTasks(image) << "\n";
  return out.str();
}

// The tasks, other than the image's own, whose code the image's scene runs and whose physics
// checks (Task<N>..., run before the images in the same program) failed.
std::vector<int> failingEarlierTasks(const GoldenImage& image) {
  std::vector<int> out;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int t = 1; t <= courseTasks().count(); ++t) {
    if (t == image.task || !image.exercises(t)) continue;
    for (int k = 0; k < unit.total_test_suite_count(); ++k) {
      const ::testing::TestSuite& suite = *unit.GetTestSuite(k);
      const SuiteOwner owner = courseTasks().ofSuite(suite.name());
      if (owner.task == t && isPhysics(owner.kind) && suite.failed_test_count() > 0) {
        out.push_back(t);
        break;
      }
    }
  }
  return out;
}

// The image's hint, or, when the scene runs another task's code that fails its own checks, that
// task named: its mistake shows in the picture, and this task's file may well be right.
std::string hintFor(const GoldenImage& image) {
  static const char* const code[] = {"spring force",  "forces",          "time stepping",
                                     "cloth builder", "particle system", "joints"};
  const std::vector<int> failing = failingEarlierTasks(image);
  if (failing.empty()) return image.hint;
  std::string names;
  for (std::size_t k = 0; k < failing.size(); ++k) {
    const int t = failing[k];
    names += (k == 0                    ? ""
              : k + 1 == failing.size() ? " and "
                                        : ", ") +
             std::string("your ") + code[t - 1] + " (task " + std::to_string(t) + ")";
  }
  return "this scene also runs " + names + ", which " +
         (failing.size() == 1 ? "fails its" : "fail their") + " checks: fix that first";
}

// The hint for a scene the student's code did not finish: another task's failing code named, as
// hintFor does, but never this image's own hint (it explains a wrong picture, not a crash).
std::string failedRunHint(const GoldenImage& image) {
  return failingEarlierTasks(image).empty() ? "" : "\n  hint: " + hintFor(image);
}

class GoldenImageTest : public ::testing::Test {
 public:
  GoldenImageTest(GoldenImage image, std::string folder)
      : image_(std::move(image)), folder_(std::move(folder)) {}

  void TestBody() override {
    Session& session = Session::get();
    if (!session.requireGl()) {
      if (!HasFailure()) GTEST_SKIP() << "no headless OpenGL context: " << session.glError();
      return;
    }
    // The student's code runs the scene (in-process here; in the grader's probe there).
    std::string error;
    const Snapshot* snapshot = Scenes::get().snapshot(image_.scene, image_.frame, &error);
    ASSERT_NE(snapshot, nullptr) << header(image_) << "  the student code failed: " << error
                                 << failedRunHint(image_);
    // This process draws and compares.
    const Image actual = session.renderer().render(*snapshot, image_.width, image_.height);
    ASSERT_FALSE(actual.empty()) << header(image_) << "  " << session.renderer().error();
    const golden::Verdict verdict = golden::compareWithBaselines(actual, image_, folder_);
    if (config().verbose) {
      std::printf("%s (%s):\n%s", image_.name.c_str(), golden::toString(image_.compare),
                  golden::describeChecks(image_, verdict).c_str());
    }
    if (verdict.passed) {
      golden::removeFailureImages(image_, config().failures);
      return;
    }

    const golden::FailureFiles files =
        golden::writeFailureImages(image_, actual, verdict.expected, config().failures);
    // For reports that show the images side by side (a6_grade): the files that were written.
    if (files.error.empty()) {
      RecordProperty("student_image", files.actual);
      if (!verdict.expected.empty()) {
        RecordProperty("reference_image", files.expected);
        RecordProperty("difference_image", files.difference);
      }
    }
    std::ostringstream message;
    message << header(image_) << "  differs from every approved reference (compare: "
            << golden::toString(image_.compare) << ", exact first, then tolerance "
            << image_.tolerance.perChannel << " per channel):\n"
            << golden::describeChecks(image_, verdict) << "  hint: " << hintFor(image_) << "\n";
    if (files.error.empty() && !config().showPaths) {
      message << "  the images (yours, the reference, the difference) are in the report\n";
    } else if (files.error.empty()) {
      message << "  images in " << config().failures << ":\n"
              << "    actual:     " << files.actual << "\n"
              << "    expected:   " << (verdict.expected.empty() ? "(none)" : files.expected)
              << "\n"
              << "    difference: " << (verdict.expected.empty() ? "(none)" : files.difference)
              << "\n";
    } else if (config().showPaths) {
      message << "  could not write the images: " << files.error << "\n";
    }
    const std::string here = session.context().description();
    if (!image_.renderer.empty() && here != image_.renderer) {
      message << "  note: rendered here with " << here << "; the reference with " << image_.renderer
              << ". Another renderer may move edge pixels: see docs/rendering.md "
                 "(approved variants).\n";
    }
    ADD_FAILURE() << message.str();
  }

 private:
  GoldenImage image_;
  std::string folder_;
};

// A failing test that reports why the manifest could not be used.
class ManifestError : public ::testing::Test {
 public:
  explicit ManifestError(std::string error) : error_(std::move(error)) {}
  void TestBody() override { FAIL() << error_; }

 private:
  std::string error_;
};

// One test per image of `manifest` (of the tasks asked for), in its task's suite of `kind`.
void registerImages(const golden::Manifest& manifest, SuiteKind kind) {
  for (const GoldenImage& image : manifest.images) {
    bool wanted = config().tasks.empty();
    for (int task : config().tasks) wanted = wanted || image.exercises(task);
    if (!wanted) continue;
    Scenes::get().need(image.scene, image.frame);
    const std::string suite = courseTasks().suite(image.task, kind);
    const std::string folder = manifest.folder;
    ::testing::RegisterTest(
        suite.c_str(), image.name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
        [image, folder]() -> ::testing::Test* { return new GoldenImageTest(image, folder); });
  }
}

// Registers the images of the manifest at `path` in their tasks' suites of `kind` (false: it could
// not be read, and one failing test, Manifest.<errorTest>, says why).
bool registerManifest(const std::string& path, SuiteKind kind, const char* errorTest) {
  golden::ManifestResult read = golden::readManifest(path);
  if (!read) {
    const std::string error = read.error;
    ::testing::RegisterTest("Manifest", errorTest, nullptr, nullptr, __FILE__, __LINE__,
                            [error]() -> ::testing::Test* { return new ManifestError(error); });
    return false;
  }
  registerImages(read.manifest, kind);
  return true;
}

}  // namespace

// Registers one test per manifest image (false: the manifest could not be read, and one
// failing test, Manifest.Reads, says why), then the hidden images (graders only: a student
// release has no hidden/ folder) beside it, as GoldenTask<N>Hidden.<name>.
std::vector<ImagedScene> imagedScenes() {
  std::vector<ImagedScene> scenes;
  const golden::ManifestResult read = golden::readManifest(config().manifest);
  if (!read) return scenes;
  for (const GoldenImage& image : read.manifest.images) {
    auto same = [&](const ImagedScene& s) { return s.scene == image.scene; };
    auto found = std::find_if(scenes.begin(), scenes.end(), same);
    if (found == scenes.end()) {
      scenes.push_back({image.scene, image.frame, image.task, {}});
      if (const harness::SceneResult* failed = Scenes::get().failedRun(image.scene))
        scenes.back().imagesRun.fail(failed->fault, failed->error);
    } else {
      found->lastFrame = std::max(found->lastFrame, image.frame);
    }
  }
  return scenes;
}

std::string replayFolder() {
  return (std::filesystem::path(config().manifest).parent_path() / "replays").string();
}

bool registerGoldenChecks(const std::string& failuresDir, ImagePaths paths) {
  config().failures = std::filesystem::absolute(failuresDir).lexically_normal().string();
  config().showPaths = paths == ImagePaths::Shown;
  if (!registerManifest(config().manifest, SuiteKind::Golden, "Reads")) return false;
  const std::filesystem::path hidden =
      std::filesystem::path(config().manifest).parent_path() / "hidden" / "manifest.json";
  return !std::filesystem::exists(hidden) ||
         registerManifest(hidden.string(), SuiteKind::GoldenHidden, "ReadsHidden");
}

namespace {

// Determinism: a fresh run of a scene, rendered, twice -------------------------------------------

Image renderFresh(const std::string& scene, int frame, std::string* error) {
  Session& session = Session::get();
  harness::SceneRequest request;
  request.scene = scene;
  request.frames = {frame};
  const harness::SceneResult run = student().ask(request);
  if (!run.ok()) {
    *error = run.error;
    return Image();
  }
  Image image = session.renderer().render(run.snapshots[0], 256, 256);
  if (image.empty()) *error = session.renderer().error();
  return image;
}

void expectSameBytesTwice(const std::string& scene, int frame) {
  if (!Session::get().requireGl()) {
    if (!::testing::Test::HasFailure()) GTEST_SKIP() << Session::get().glError();
    return;
  }
  std::string error;
  const Image first = renderFresh(scene, frame, &error);
  ASSERT_FALSE(first.empty()) << scene << ": " << error;
  const Image second = renderFresh(scene, frame, &error);
  ASSERT_FALSE(second.empty()) << scene << ": " << error;
  const ImageComparison c = compare(second, first, 0);
  EXPECT_TRUE(c.identical) << scene << " after " << frame << " frames, built and run twice, "
                           << "rendered twice: " << c.pixelsOverTolerance
                           << " pixels differ (largest channel difference " << c.maxChannelDiff
                           << "). A scene must be a pure function of its defaults: look for "
                              "uninitialised memory, an unseeded random generator, or state "
                              "kept between runs (a static).";
}

class DeterminismTest : public ::testing::Test {
 public:
  DeterminismTest(std::string scene, int frame) : scene_(std::move(scene)), frame_(frame) {}
  void TestBody() override { expectSameBytesTwice(scene_, frame_); }

 private:
  std::string scene_;
  int frame_;
};

// Registered here, not with TEST(): a6_grade links this file and runs the images only.
void registerDeterminismTests() {
  const struct {
    const char* name;
    const char* scene;
    int frame;
  } cases[] = {{"ClothRendersTheSameBytesTwice", "cloth_shear", 60},
               {"FireRendersTheSameBytesTwice", "fire", 120},
               {"Box2DCarRendersTheSameBytesTwice", "car", 60}};
  for (const auto& c : cases) {
    const std::string scene = c.scene;
    const int frame = c.frame;
    ::testing::RegisterTest(
        "Determinism", c.name, nullptr, nullptr, __FILE__, __LINE__,
        [scene, frame]() -> ::testing::Test* { return new DeterminismTest(scene, frame); });
  }
}

// The command line ---------------------------------------------------------------------------

std::set<int> parseTasks(const std::string& text) {
  std::set<int> tasks;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const int t = std::atoi(item.c_str());
    if (courseTasks().find(t) != nullptr) tasks.insert(t);
  }
  return tasks;
}

}  // namespace

int runGoldenTests(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  namespace fs = std::filesystem;
  const fs::path program = fs::absolute(argv[0]).lexically_normal();
  std::string failures = (program.parent_path() / "golden_failures" / program.filename()).string();
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    auto value = [&](const char* flag) -> const char* {
      const std::string prefix = std::string(flag) + "=";
      return arg.rfind(prefix, 0) == 0 ? argv[k] + prefix.size() : nullptr;
    };
    if (const char* v = value("--manifest")) {
      config().manifest = v;
    } else if (const char* v = value("--failures")) {
      failures = fs::absolute(v).lexically_normal().string();
    } else if (const char* v = value("--tasks")) {
      config().tasks = parseTasks(v);
    } else if (arg == "--verbose") {
      config().verbose = true;
    } else {
      std::fprintf(
          stderr,
          "%s: unknown option %s (--manifest=FILE, --failures=DIR, --tasks=N,N, --verbose)\n",
          argv[0], arg.c_str());
      return 2;
    }
  }
  registerDeterminismTests();
  const bool manifestRead = registerGoldenChecks(failures);
  const int status = RUN_ALL_TESTS();
  if (!manifestRead) {
    std::printf("A6-GOLDEN no manifest\n");
    return 1;
  }

  // The summary line of the image tests.
  int passed = 0, failed = 0, skipped = 0;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int s = 0; s < unit.total_test_suite_count(); ++s) {
    const ::testing::TestSuite& suite = *unit.GetTestSuite(s);
    const SuiteOwner owner = courseTasks().ofSuite(suite.name());
    if (owner.task == 0 ||
        (owner.kind != SuiteKind::Golden && owner.kind != SuiteKind::GoldenHidden))
      continue;
    for (int t = 0; t < suite.total_test_count(); ++t) {
      const ::testing::TestInfo& info = *suite.GetTestInfo(t);
      if (!info.should_run()) continue;
      if (info.result()->Skipped()) {
        ++skipped;
      } else if (info.result()->Failed()) {
        ++failed;
      } else {
        ++passed;
      }
    }
  }
  std::printf("A6-GOLDEN passed=%d failed=%d skipped=%d\n", passed, failed, skipped);
  return status;
}

}  // namespace a6::test
