#include "checks/runs.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "harness/tasks.h"
#include "render/replay.h"

namespace a6::grader {
namespace {

// Frames per request: an answer stays well under the probe's 4 MiB (a frame of the largest
// scene is about 100 KB as JSON).
constexpr std::size_t kFramesPerRequest = 16;

// The scene run at `frames`, in requests of kFramesPerRequest frames (only the first keeps
// its springs).
harness::SceneResult runInParts(harness::StudentCode& student, const std::string& scene,
                                const std::vector<int>& frames) {
  harness::SceneResult all;
  for (std::size_t from = 0; from < frames.size(); from += kFramesPerRequest) {
    harness::SceneRequest request;
    request.scene = scene;
    request.lean = true;
    const std::size_t to = std::min(frames.size(), from + kFramesPerRequest);
    request.frames.assign(frames.begin() + static_cast<std::ptrdiff_t>(from),
                          frames.begin() + static_cast<std::ptrdiff_t>(to));
    harness::SceneResult part = student.ask(request);
    if (!part.ok() || part.snapshots.size() != request.frames.size()) {
      if (part.ok()) part.fail(harness::Fault::Garbage, "the replay's answer lacks frames");
      return part;
    }
    if (from > 0) part.snapshots.front().springs.clear();
    for (Snapshot& s : part.snapshots) all.snapshots.push_back(std::move(s));
    if (part.energies.size() == request.frames.size())
      all.energies.insert(all.energies.end(), part.energies.begin(), part.energies.end());
  }
  return all;
}

// The step counts a trajectory of `steps` steps is sampled at: about kTrajectorySamples, evenly,
// the last one `steps` itself.
std::vector<int> sampleSteps(int steps) {
  std::vector<int> out;
  for (int k = 1; k <= kTrajectorySamples; ++k) {
    const int s = static_cast<int>(static_cast<long long>(steps) * k / kTrajectorySamples);
    if (s >= 1 && (out.empty() || s > out.back())) out.push_back(s);
  }
  return out;
}

// The longest run of `check` fit to replay (see runs.h; a check that runs 1, 2, ... steps shows
// most in its last).
const harness::ParticleRunRequest* replayableRun(const Transcript& t, const std::string& check) {
  const harness::ParticleRunRequest* longest = nullptr;
  for (const auto& x : t.of<harness::ParticleRunRequest>()) {
    const harness::ParticleRunRequest& r = x.request;
    if (x.check == check && r.emitter.rate == 0 && r.referenceForces && !r.initial.empty() &&
        r.initial.size() <= kParticlesPerTrajectory && r.steps >= 1 && r.steps <= 100000 &&
        (longest == nullptr || r.steps > longest->steps))
      longest = &r;
  }
  return longest;
}

}  // namespace

std::vector<ParticleTrajectory> runParticleTrajectories(BudgetedStudent& student,
                                                        const Transcript& transcript,
                                                        const std::vector<std::string>& failed) {
  std::vector<ParticleTrajectory> out;
  for (const std::string& check : failed) {
    if (out.size() >= kParticleTrajectories ||
        !courseTasks().isPhysicsCheckOf(check, "particle_system.cpp"))
      continue;
    const harness::ParticleRunRequest* request = replayableRun(transcript, check);
    if (request == nullptr) continue;
    ParticleTrajectory t{check, *request, sampleSteps(request->steps), {}};
    student.startTest(kReplaySeconds);
    for (int steps : t.steps) {
      harness::ParticleRunRequest r = *request;
      r.steps = steps;
      harness::ParticlesResult result = student.ask(r);
      if (!result.ok()) break;
      t.runs.push_back(std::move(result));
    }
    if (t.runs.size() == t.steps.size()) out.push_back(std::move(t));
  }
  return out;
}

Transcript askDesigned(BudgetedStudent& student, const std::vector<Designed>& designed) {
  Transcript measured;
  if (designed.empty()) return measured;
  student.startTest(kMeasureSeconds);
  std::map<std::string, int> failures;  // per task (the label's "t<N>."): each failure may have
                                        // cost a probe start and its time; two end that task's
  for (const Designed& d : designed) {
    const std::string task = d.label.substr(0, d.label.find('.'));
    if (failures[task] >= 2) continue;
    harness::Answer answer = student.ask(d.request);
    if (!harness::outcomeOf(answer).ok()) {
      ++failures[task];
      continue;
    }
    measured.exchanges.push_back({d.label, d.request, std::move(answer)});
  }
  return measured;
}

std::vector<SceneRun> runReplays(BudgetedStudent& student,
                                 const std::vector<a6::test::ImagedScene>& scenes) {
  std::vector<SceneRun> runs;
  const auto start = std::chrono::steady_clock::now();
  for (const a6::test::ImagedScene& s : scenes) {
    SceneRun run;
    run.scene = s.scene;
    run.task = s.task;
    run.frames = replay::replayFrames(std::max(s.lastFrame, 60));
    const double left =
        kReplaysSeconds -
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!s.imagesRun.ok()) {
      // It would fail again, and take its time again.
      run.result.fail(s.imagesRun.fault,
                      "the run of this scene for its images failed, so it was not run again "
                      "for a replay: " +
                          s.imagesRun.error);
    } else if (left < 1) {
      run.result.fail(harness::Fault::NotRun, "the replays' time ran out before this scene");
    } else {
      student.startTest(std::min(kReplaySeconds, left));
      run.result = runInParts(student, s.scene, run.frames);
      if (!run.result.ok())
        run.result.error =
            "your code failed while the scene ran again for this replay: " + run.result.error;
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace a6::grader
