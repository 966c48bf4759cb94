#include "replay/replays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "harness/tasks.h"
#include "mistakes/mistakes.h"
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

// A particle system's head count against the reference's, where it first differs by a fifth
// (more particles also carry more energy: this says why first); "" when it never does.
// `emitting`: the runs emit at random, so their counts may differ a little; without emission (a
// check's own particles) any difference is a removal's.
std::string population(const replay::Unpacked& mine, const replay::Unpacked& ref,
                       const std::vector<double>& times, bool emitting) {
  for (std::size_t f = 0; f < mine.particles.size() && f < ref.particles.size(); ++f) {
    const double a = static_cast<double>(mine.particles[f].size());
    const double b = static_cast<double>(ref.particles[f].size());
    if (emitting ? std::abs(a - b) < std::max(5.0, 0.2 * b) : a == b) continue;
    const std::string counts = " (" + std::to_string(mine.particles[f].size()) + " against " +
                               std::to_string(ref.particles[f].size()) + " at " +
                               seconds(times[f]) + ")";
    if (a > b) {
      return "Your run keeps more particles than the reference's" + counts +
             ": a particle whose age has reached its lifetime must be removed.";
    }
    return "Your run has fewer particles than the reference's" + counts +
           (emitting ? ": check the emission count per step (rate x dt, its fraction carried "
                       "over) and that each particle lives its whole lifetime."
                     : ": a particle is removed before its age reaches its lifetime (age += dt, "
                       "then remove once age >= lifetime).");
  }
  return "";
}

// What a Box2D scene's plots mean: its motors and joint springs put energy in and take it out,
// so the energy tells no mistake by its shape; where the bodies part does.
std::string readBodies(int parted, const std::vector<double>& times) {
  if (parted < 0) return "Your run follows the reference: the positions agree in every frame.";
  return "Your bodies part from the reference's at " +
         seconds(times[static_cast<std::size_t>(parted)]) +
         ": look at the joints in that frame (their anchors, limits, motors and springs); the "
         "energy plot shows whether your bodies gained or lost energy the reference's did not.";
}

// The error, the energies (when both runs have them), where they part, and the reading.
void measure(ReplayView& v, const replay::Unpacked& mine, const replay::Unpacked& ref) {
  const std::size_t frames = ref.frames.size();
  const bool energies = mine.energy.size() == frames && ref.energy.size() == frames;
  bool byCentroid = ref.drawn;
  for (std::size_t f = 0; f < frames; ++f) {
    v.times.push_back(ref.frames[f] * ref.frameDt);
    v.error.push_back(frameError(mine, ref, f, byCentroid));
    if (!energies) continue;
    v.studentEnergy.push_back(mine.energy[f].total());
    v.referenceEnergy.push_back(ref.energy[f].total());
  }
  const bool bodies = std::all_of(ref.particles.begin(), ref.particles.end(),
                                  [](const std::vector<Vec2>& p) { return p.empty(); });
  v.errorMeasure = byCentroid ? "distance between the particles' centroids"
                   : bodies   ? "RMS distance of the bodies' corners"
                              : "RMS distance of the particles";
  v.threshold = ref.view.height * (byCentroid ? 0.05 : 0.01);
  for (std::size_t f = 0; f < v.error.size() && v.parted < 0; ++f) {
    if (!(v.error[f] <= v.threshold)) v.parted = static_cast<int>(f);
  }
  v.reading = ref.drawn ? population(mine, ref, v.times, !v.trajectory) : "";
  if (v.reading.empty())
    v.reading = bodies ? readBodies(v.parted, v.times)
                       : readPlot(v.studentEnergy, v.referenceEnergy, v.error, v.parted, v.times);
}

// Sets the two packed runs side by side in `v`.
void compareRuns(ReplayView& v, const Json& mine, const Json& ref) {
  v.student = mine.dump(-1, ' ', false, Json::error_handler_t::replace);
  v.reference = ref.dump(-1, ' ', false, Json::error_handler_t::replace);
  const replay::Unpacked theirs = replay::unpack(ref);
  v.frames = theirs.frames;
  measure(v, replay::unpack(mine), theirs);
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
    v.missing = run.result.error;
    return v;
  }
  if (ref->frames != run.frames || run.result.snapshots.size() != run.frames.size()) {
    v.missing =
        "the grader's reference replay of this scene does not match its frames (an "
        "instructor writes them again with a6_render_solution --replays)";
    return v;
  }
  compareRuns(v,
              replay::pack({run.scene, ref->frameDt, ref->gravity, run.frames, run.result.snapshots,
                            run.result.energies}),
              packed);
  return v;
}

// The failed checks' trajectories (tasks 3 and 5) -----------------------------------------------

constexpr std::size_t kTrajectories = 4;       // replayed failed checks at most
constexpr std::size_t kTrajectoryFrames = 61;  // frames of one, at most
constexpr std::size_t kTrajectoryParticles = 2000;

// A view that holds every finite position of `states`, with a margin.
View viewAround(const std::vector<const std::vector<Particle>*>& states) {
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (const std::vector<Particle>* ps : states) {
    for (const Particle& p : *ps) {
      if (std::isfinite(p.x.x()) && std::isfinite(p.x.y()))
        lo = lo.cwiseMin(p.x), hi = hi.cwiseMax(p.x);
    }
  }
  View view;
  if (!(lo.x() <= hi.x())) return view;
  view.center = (lo + hi) / 2;
  view.height = 1.25 * std::max((hi - lo).maxCoeff(), 0.05);
  return view;
}

// A check's run drawn as a replay: its states in `view`, with the environment's obstacles and,
// in the first frame, the springs.
struct TrajectoryRecorder {
  const Environment& env;
  const std::vector<SpringData>& springs;
  View view;
  replay::Recording rec;

  TrajectoryRecorder(const Environment& e, const std::vector<SpringData>& sp, const View& v,
                     double frameDt)
      : env(e), springs(sp), view(v) {
    rec.scene = "trajectory";
    rec.frameDt = frameDt;
    rec.gravity = env.gravity;
  }
  void frame(int number, const std::vector<Particle>& particles) {
    Snapshot s;
    s.particles = particles;
    s.view = view;
    s.particleRadius = view.height / 150;
    s.planes = env.planes;
    s.circles = env.circles;
    if (rec.frames.empty()) s.springs = springs;
    rec.frames.push_back(number);
    rec.snapshots.push_back(std::move(s));
  }
};

// The request's initial state, then about kTrajectoryFrames of the recorded ones, as a run.
replay::Recording trajectory(const harness::SimulateRequest& r, const harness::SimulateResult& run,
                             const View& view) {
  TrajectoryRecorder out(r.env, r.springs, view, r.frameDt);
  out.frame(0, r.particles);
  const std::size_t n = run.states.size(),
                    every = (n + kTrajectoryFrames - 2) / (kTrajectoryFrames - 1);
  for (std::size_t k = 0; k < n; ++k) {
    if (k % std::max<std::size_t>(every, 1) == 0 || k + 1 == n)
      out.frame(run.recordedFrames[k], run.states[k]);
  }
  return std::move(out.rec);
}

// The two runs compared as a trajectory replay of `check`; none when they never differ.
std::optional<ReplayView> trajectoryView(const std::string& check, int task,
                                         const replay::Recording& mine,
                                         const replay::Recording& ref, const View& view) {
  ReplayView v;
  v.scene = check;
  v.task = task;
  v.trajectory = true;
  compareRuns(v, replay::pack(mine), replay::pack(ref));
  const auto most = std::max_element(v.error.begin(), v.error.end());
  if (most != v.error.end() && !(*most <= 1e-9 * view.height)) return v;
  return std::nullopt;
}

// The first exchange of `check` the reference can answer and the student's run differs from.
std::optional<ReplayView> trajectoryOf(const Transcript& t, const std::string& check) {
  for (const auto& x : t.of<harness::SimulateRequest>()) {
    if (x.check != check || x.request.particles.size() > kTrajectoryParticles) continue;
    const std::optional<harness::SimulateResult> ref = referenceSimulation(x.request);
    if (!ref || ref->states.size() != x.result.states.size() ||
        ref->recordedFrames != x.result.recordedFrames || ref->states.empty())
      continue;
    std::vector<const std::vector<Particle>*> states{&x.request.particles};
    for (const auto& state : ref->states) states.push_back(&state);
    const View view = viewAround(states);
    if (auto v = trajectoryView(check, 3, trajectory(x.request, x.result, view),
                                trajectory(x.request, *ref, view), view))
      return v;
  }
  return std::nullopt;
}

// A task-5 check's particles after each sampled step count, the student's and the reference's.
std::optional<ReplayView> particleTrajectoryOf(const ParticleTrajectory& t) {
  std::vector<harness::ParticlesResult> refs;
  for (int steps : t.steps) {
    harness::ParticleRunRequest r = t.request;
    r.steps = steps;
    std::optional<harness::ParticlesResult> ref = referenceParticleRun(r);
    if (!ref) return std::nullopt;
    refs.push_back(std::move(*ref));
  }
  std::vector<const std::vector<Particle>*> states{&t.request.initial};
  for (const auto& ref : refs) states.push_back(&ref.particles);
  const View view = viewAround(states);
  const std::vector<SpringData> none;
  TrajectoryRecorder mine(t.request.env, none, view, t.request.dt),
      theirs(t.request.env, none, view, t.request.dt);
  mine.frame(0, t.request.initial);
  theirs.frame(0, t.request.initial);
  for (std::size_t k = 0; k < t.steps.size() && k < t.runs.size(); ++k) {
    mine.frame(t.steps[k], t.runs[k].particles);
    theirs.frame(t.steps[k], refs[k].particles);
  }
  return trajectoryView(t.check, 5, mine.rec, theirs.rec, view);
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
    if (gain > 0.1 * scale) {
      return "Your energy grows where the reference's does not: the position is updated before "
             "the velocity (explicit Euler), a damping or drag term has the wrong sign, or a "
             "force pushes where it should pull.";
    }
    if (gain < -0.1 * scale) {
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

std::vector<ReplayView> trajectoryReplays(const Transcript& transcript,
                                          const std::vector<std::string>& failedChecks) {
  std::vector<ReplayView> views;
  for (const std::string& check : failedChecks) {
    if (views.size() >= kTrajectories ||
        !courseTasks().isPhysicsCheckOf(check, "time_stepping.cpp"))
      continue;
    if (std::optional<ReplayView> v = trajectoryOf(transcript, check))
      views.push_back(std::move(*v));
  }
  return views;
}

std::vector<ReplayView> particleTrajectoryReplays(const std::vector<ParticleTrajectory>& runs) {
  std::vector<ReplayView> views;
  for (const ParticleTrajectory& t : runs) {
    if (std::optional<ReplayView> v = particleTrajectoryOf(t)) views.push_back(std::move(*v));
  }
  return views;
}

std::vector<ReplayView> buildReplays(const std::vector<SceneRun>& runs,
                                     const std::filesystem::path& referenceDir) {
  std::vector<ReplayView> views;
  for (const SceneRun& run : runs) views.push_back(viewOf(run, referenceDir));
  return views;
}

}  // namespace a6::grader
