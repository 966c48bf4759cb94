// The golden-image checks as a library (target a6_golden_checks: no student code, no
// a6_framework): one GoogleTest test per image of tests/golden/manifest.json, named
// GoldenTask<task>.<name>. Each runs its scene through a6::test::student() (in-process in the
// student's golden binaries, the sandboxed probe in a6_grade) and renders and compares the
// returned snapshot in THIS process; the manifest and the reference PNGs are read from the
// source tree by absolute path (A6_GOLDEN_DIR), never by the student's code.
#pragma once

#include <string>
#include <vector>

#include "harness/student_code.h"

namespace a6::test {

/// The student's code the checks run (defined by the program: golden_main_in_process.cpp, or
/// the grader's main).
harness::StudentCode& student();

/// Registers the image checks with GoogleTest (::testing::RegisterTest; call after
/// InitGoogleTest and before RUN_ALL_TESTS). A failing check writes <name>.actual.png,
/// <name>.expected.png and <name>.diff.png into `failuresDir` (created when needed) and records
/// them as the test properties student_image, reference_image and difference_image. Nothing
/// runs, and no GL context is made, until the tests do. Without a readable manifest, one failing
/// test (GoldenTask0.ManifestReads) says why; returns false then.
/// `paths`: whether failure messages name the image files (a student's own run) or only say that
/// the report shows them (the grader: its folders mean nothing to a student).
enum class ImagePaths { Shown, InTheReportOnly };
bool registerGoldenChecks(const std::string& failuresDir, ImagePaths paths = ImagePaths::Shown);

/// A scene the public images check, and the last frame one of them shows.
struct ImagedScene {
  std::string scene;
  int lastFrame = 0;
  int task = 0;  ///< the task its images are filed under (the first image's)
  /// How the images' run of the scene ended, when it failed (it ran out of time, crashed, ...);
  /// ok when it ran well or has not run.
  harness::SceneResult imagesRun;
};
/// The scenes of the public manifest, in the manifest's order (empty without a manifest).
std::vector<ImagedScene> imagedScenes();
/// The folder of the reference replays (render/replay.h), beside the manifest: graders'
/// material, read by the grader's process only.
std::string replayFolder();

}  // namespace a6::test
