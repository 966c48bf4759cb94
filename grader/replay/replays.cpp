#include "replay/replays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "render/replay.h"

namespace a6::grader {
namespace {

using Json = nlohmann::json;

constexpr std::uintmax_t kReferenceCap = 16u << 20;  // bytes of one reference replay

std::string seconds(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f s", t);
  return text;
}

// The reference run of `scene`, or why there is none (in `why`).
std::optional<replay::Unpacked> readReference(const std::filesystem::path& file, Json& packed,
                                              std::string& why) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec || size > kReferenceCap) {
    why =
        "the grader has no reference replay of this scene (an instructor writes them with "
        "a6_render_solution --replays)";
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  packed = Json::parse(in, nullptr, false);
  try {
    if (packed.is_discarded()) throw std::runtime_error("not JSON");
    return replay::unpack(packed);
  } catch (const std::exception& e) {
    why = std::string("the grader's reference replay of this scene cannot be read: ") + e.what();
    return std::nullopt;
  }
}

double rms(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  return a.empty() ? 0 : std::sqrt(sum / static_cast<double>(a.size()));
}

Vec2 centroid(const std::vector<Vec2>& points) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : points) sum += p;
  return points.empty() ? sum : Vec2(sum / static_cast<double>(points.size()));
}

// The error of one frame, both runs as packed (so both clipped alike to the view's range):
// particles by index when both have as many (a mass-spring system), else their centroids (a
// particle system draws at random); the shapes' points by index (Box2D's bodies).
double frameError(const replay::Unpacked& mine, const replay::Unpacked& ref, std::size_t f,
                  bool& byCentroid) {
  const std::vector<Vec2>&a = mine.particles[f], &b = ref.particles[f];
  if (!a.empty() || !b.empty()) {
    if (a.size() == b.size() && !ref.drawn) return rms(a, b);
    byCentroid = true;
    // One run has no particle at all: as far off as the whole view.
    if (a.empty() || b.empty()) return ref.view.height;
    return (centroid(a) - centroid(b)).norm();
  }
  const std::vector<Vec2>&p = mine.shapePoints[f], &q = ref.shapePoints[f];
  return p.size() == q.size() ? rms(p, q) : NAN;
}

void measure(ReplayView& v, const SceneRun& run, const replay::Unpacked& mine,
             const replay::Unpacked& ref) {
  const std::vector<SpringData>& springs = run.result.snapshots.front().springs;
  bool byCentroid = ref.drawn;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    v.times.push_back(run.frames[f] * ref.frameDt);
    v.error.push_back(frameError(mine, ref, f, byCentroid));
    const replay::Energy e = replay::energyOf(run.result.snapshots[f], springs, ref.gravity);
    if (e.known && ref.energy.size() == run.frames.size()) {
      v.studentEnergy.push_back(e.total());
      v.referenceEnergy.push_back(ref.energy[f].total());
    }
  }
  if (v.studentEnergy.size() != run.frames.size())
    v.studentEnergy.clear(), v.referenceEnergy.clear();
  v.errorMeasure = byCentroid ? "distance between the particles' centroids"
                   : run.result.snapshots.front().particles.empty()
                       ? "RMS distance of the bodies' corners"
                       : "RMS distance of the particles";
  v.threshold = ref.view.height * (byCentroid ? 0.05 : 0.01);
  for (std::size_t f = 0; f < v.error.size() && v.parted < 0; ++f) {
    if (!(v.error[f] <= v.threshold)) v.parted = static_cast<int>(f);
  }
  v.reading = readPlot(v.studentEnergy, v.referenceEnergy, v.error, v.parted, v.times);
}

ReplayView viewOf(const SceneRun& run, const std::filesystem::path& referenceDir) {
  ReplayView v;
  v.scene = run.scene;
  v.task = run.task;
  v.frames = run.frames;
  Json packed;
  const std::optional<replay::Unpacked> ref =
      readReference(referenceDir / (run.scene + ".json"), packed, v.missing);
  if (!ref) return v;
  if (!run.result.ok()) {
    v.missing = "your code failed while the scene ran again for this replay: " + run.result.error;
    return v;
  }
  if (ref->frames != run.frames || run.result.snapshots.size() != run.frames.size()) {
    v.missing =
        "the grader's reference replay of this scene does not match its frames (an "
        "instructor writes them again with a6_render_solution --replays)";
    return v;
  }
  v.reference = packed.dump();
  const Json mine =
      replay::pack({run.scene, ref->frameDt, ref->gravity, run.frames, run.result.snapshots});
  v.student = mine.dump(-1, ' ', false, Json::error_handler_t::replace);
  measure(v, run, replay::unpack(mine), *ref);
  return v;
}

}  // namespace

std::string readPlot(const std::vector<double>& student, const std::vector<double>& reference,
                     const std::vector<double>& error, int parted,
                     const std::vector<double>& times) {
  const auto notFinite =
      std::find_if(error.begin(), error.end(), [](double e) { return !std::isfinite(e); });
  if (notFinite != error.end()) {
    return "Your run stops being finite (NaN or infinity) at " +
           seconds(times[static_cast<std::size_t>(notFinite - error.begin())]) +
           ": a division by a zero length (coincident particles), or a step that blew up.";
  }
  const std::string from = parted >= 0 ? seconds(times[static_cast<std::size_t>(parted)]) : "";
  if (student.size() >= 2 && student.size() == reference.size()) {
    const auto [lo, hi] = std::minmax_element(reference.begin(), reference.end());
    const double scale = std::max(*hi - *lo, 1e-9 + 1e-3 * std::abs(reference.front()));
    const double gain = (student.back() - student.front()) - (reference.back() - reference.front());
    if (gain > 0.5 * scale) {
      return "Your energy grows where the reference's does not: the position is updated before "
             "the velocity (explicit Euler), a damping or drag term has the wrong sign, or a "
             "force pushes where it should pull.";
    }
    if (gain < -0.5 * scale) {
      return "Your energy drains faster than the reference's: too much damping (on the full "
             "relative velocity v2 - v1 instead of its part along the spring), or a force that "
             "is too strong.";
    }
  }
  if (parted < 0) return "Your run follows the reference: the positions agree in every frame.";
  if (student.empty()) {
    return "Your bodies part from the reference's at " + from +
           ": look at the joints in that frame (their anchors, limits, motors and springs).";
  }
  return "The energy follows the reference's, but the positions part at " + from +
         ": forces of the right size in the wrong place, such as a spring between the wrong "
         "particles, a missing or doubled spring, or the wrong particles pinned.";
}

std::vector<ReplayView> buildReplays(const std::vector<SceneRun>& runs,
                                     const std::filesystem::path& referenceDir) {
  std::vector<ReplayView> views;
  for (const SceneRun& run : runs) views.push_back(viewOf(run, referenceDir));
  return views;
}

}  // namespace a6::grader
