// Where the library of known mistakes is not built (a student release has no
// grader/mistakes/library/): nothing is ever named.
#include "mistakes/measure.h"
#include "mistakes/mistakes.h"

namespace a6::grader {

const std::vector<MistakeModel>& mistakeLibrary() {
  static const std::vector<MistakeModel> none;
  return none;
}

std::optional<harness::SimulateResult> referenceSimulation(const harness::SimulateRequest&) {
  return std::nullopt;
}

std::optional<harness::SimulateResult> referenceImplicitSimulation(
    const harness::SimulateRequest&) {
  return std::nullopt;
}

std::optional<harness::ParticlesResult> referenceParticleRun(const harness::ParticleRunRequest&) {
  return std::nullopt;
}

const std::vector<Designed>& designedInputs() {
  static const std::vector<Designed> none;
  return none;
}

std::vector<NamedMistake> diagnose(const Transcript&, const std::set<int>&) { return {}; }

}  // namespace a6::grader
