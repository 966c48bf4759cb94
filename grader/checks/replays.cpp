#include "checks/replays.h"

#include <algorithm>

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
    harness::SceneResult part = student.runScene(request);
    if (!part.ok() || part.snapshots.size() != request.frames.size()) {
      if (part.ok()) part.fail(harness::Fault::Garbage, "the replay's answer lacks frames");
      return part;
    }
    if (from > 0) part.snapshots.front().springs.clear();
    for (Snapshot& s : part.snapshots) all.snapshots.push_back(std::move(s));
  }
  return all;
}

}  // namespace

std::vector<SceneRun> runReplays(BudgetedStudent& student,
                                 const std::vector<a6::test::ImagedScene>& scenes) {
  std::vector<SceneRun> runs;
  for (const a6::test::ImagedScene& s : scenes) {
    SceneRun run;
    run.scene = s.scene;
    run.task = s.task;
    run.frames = replay::replayFrames(std::max(s.lastFrame, 60));
    student.startTest(kReplaySeconds);
    run.result = runInParts(student, s.scene, run.frames);
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace a6::grader
