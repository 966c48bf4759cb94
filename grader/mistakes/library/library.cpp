// The library of known mistakes: every task's models, in task order; and the reference's runs
// the replays show beside the student's (the reference steppers in the physics' form).
#include "mistakes/library/models.h"
#include "reference/steppers.h"

namespace a6::grader {

const std::vector<MistakeModel>& mistakeLibrary() {
  static const std::vector<MistakeModel> all = [] {
    std::vector<MistakeModel> models;
    for (auto part : {mistakes::task1Mistakes, mistakes::task2Mistakes, mistakes::task3Mistakes,
                      mistakes::task4Mistakes, mistakes::task5Mistakes, mistakes::task6Mistakes,
                      mistakes::task7Mistakes, mistakes::partByPartMistakes}) {
      for (MistakeModel& m : part()) models.push_back(std::move(m));
    }
    return models;
  }();
  return all;
}

std::optional<harness::SimulateResult> referenceSimulation(const harness::SimulateRequest& r) {
  return reference::simulate(r, reference::StepForm{});
}

std::optional<harness::SimulateResult> referenceImplicitSimulation(
    const harness::SimulateRequest& r) {
  return reference::simulateImplicit(r, reference::ImplicitForm{});
}

std::optional<harness::ParticlesResult> referenceParticleRun(const harness::ParticleRunRequest& r) {
  return reference::runParticles(r, reference::ParticleFlaw::None);
}

}  // namespace a6::grader
