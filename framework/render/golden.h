// Golden images: the manifest (tests/golden/manifest.json) and how a rendered frame is compared
// with its approved references. Used by the golden-image tests, by `a6_render --goldens` (which
// re-renders the references) and by the grader; no GL and no student code here.
//
// Design notes
// - One image = one scene at one frame, at one resolution, drawn with the default RenderOptions.
//   The manifest says which tasks the scene runs (so a failure names them), how to compare, and
//   which baseline files are approved: the primary one first, then extra approved variants (the
//   same frame from another renderer, say).
// - Compare exactly first (decoded pixels, so PNG encoders do not matter), then with the
//   tolerance: a pixel is "over" when some channel differs by more than perChannel; the image
//   passes when at most maxFraction of its pixels are over. Any baseline that passes is enough.
// - "density" is for scenes that draw random numbers (the fire): a correct emitter that draws them
//   in another order places every particle elsewhere, so single pixels mean nothing. Both images
//   are averaged over block x block pixel squares first; the tolerance then applies to those
//   block means (perChannel on the mean colour, maxFraction of the blocks).
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace a6::golden {

enum class CompareMode { Pixels, Density };

/// "pixels" / "density"; parseCompareMode returns false for anything else.
const char* toString(CompareMode mode);
bool parseCompareMode(const std::string& text, CompareMode* mode);

struct Tolerance {
  int perChannel = 0;      ///< 0..255: a channel may differ by this much and not count
  double maxFraction = 0;  ///< 0..1: the share of pixels (density: of blocks) allowed over it
  int block = 16;          ///< density only: side of the averaging blocks, pixels
};

/// One reference image, as the manifest lists it.
struct GoldenImage {
  std::string name;               ///< unique, also the test's name, e.g. "cloth_shear_f60"
  std::string scene;              ///< a name from sceneNames()
  int frame = 0;                  ///< frames since the scene started (0: as built)
  double time = 0;                ///< s, frame times the scene's frame dt (for people to read)
  int width = 256, height = 256;  ///< pixels
  CompareMode compare = CompareMode::Pixels;
  Tolerance tolerance;
  int task = 0;              ///< the task the image is filed under (GoldenTask<task>.<name>)
  std::vector<int> tasks;    ///< every task whose code produced the image
  std::string shows;         ///< one line: what the picture shows
  std::string hint;          ///< what to check when it differs
  std::string studentFiles;  ///< which seven files rendered the baselines ("solution")
  std::string renderer;      ///< GL_RENDERER and GL_VERSION the primary baseline came from
  std::vector<std::string> baselines;  ///< approved PNGs, relative to the manifest's folder;
                                       ///< the first is the primary one (re-rendered by
                                       ///< a6_render --goldens)

  bool exercises(int t) const;
};

struct Manifest {
  std::string folder;  ///< the folder of manifest.json: baselines are relative to it
  std::vector<GoldenImage> images;

  /// The image called `name`, nullptr if none.
  const GoldenImage* find(const std::string& name) const;
};

/// A manifest, or why there is none.
struct ManifestResult {
  Manifest manifest;
  std::string error;  ///< empty on success
  explicit operator bool() const { return error.empty(); }
};

/// Reads and checks a manifest (unique names, sizes > 0, at least one baseline, tolerances in
/// range). The error names the file and the entry.
ManifestResult readManifest(const std::string& path);
/// Writes `manifest` as JSON (2-space indent, keys in the documented order). Empty on success.
[[nodiscard]] std::string writeManifest(const Manifest& manifest, const std::string& path);

/// "task 4 (cloth.cpp)" for the image's own task, with "on top of task 1 (spring.cpp), ..." for
/// the others it runs.
std::string describeTasks(const GoldenImage& image);

/// The mean colour of every block x block square (the last row and column of blocks may be
/// smaller), as an image of ceil(w / block) x ceil(h / block) pixels.
Image blockAverage(const Image& image, int block);

/// How `actual` compares with one baseline.
struct BaselineCheck {
  std::string file;        ///< as listed in the manifest
  std::string error;       ///< the baseline could not be read (missing file, wrong size)
  ImageComparison result;  ///< pixels, or block means in density mode
  bool passed = false;     ///< identical, or within the tolerance
};

struct Verdict {
  bool passed = false;
  bool identical = false;             ///< some baseline matched every decoded byte
  int matched = -1;                   ///< the baseline that passed, or -1
  int closest = -1;                   ///< the readable baseline with the fewest pixels over, or -1
  std::vector<BaselineCheck> checks;  ///< one per baseline, in manifest order
  Image expected;                     ///< the matched baseline, else the closest (may be empty)
};

/// Compares `actual` with every baseline of `image` (files in `folder`): exactly, then with
/// the tolerance of its compare mode.
Verdict compareWithBaselines(const Image& actual, const GoldenImage& image,
                             const std::string& folder);

/// One line per baseline: "cloth_shear_f60.png: 2.31% of pixels over 16 (limit 0.40%), largest
/// channel difference 255".
std::string describeChecks(const GoldenImage& image, const Verdict& verdict);

/// The three files written when an image fails.
struct FailureFiles {
  std::string actual, expected, difference;  ///< paths
  std::string error;                         ///< empty when all three were written
};

/// Writes <folder>/<name>.actual.png, <name>.expected.png and <name>.diff.png (|actual -
/// expected| amplified 8x, any difference at least 64; in density mode the difference of the
/// block means, scaled back to full size). Creates `folder` if needed.
FailureFiles writeFailureImages(const GoldenImage& image, const Image& actual,
                                const Image& expected, const std::string& folder);
/// Removes what writeFailureImages wrote for `image` in `folder` (an earlier run's failure, now
/// passing), if anything.
void removeFailureImages(const GoldenImage& image, const std::string& folder);

}  // namespace a6::golden
