// The mistakes stage: the student's answers to the public checks (checks/transcript.h) beside
// a library of known mistakes, each a model of what a common wrong version answers on the same
// inputs (grader/mistakes/library/, written from tests/wrong/; graders' material only: a student
// release has no library, and then names nothing).
//
// Takes the transcript and the tasks whose physics checks failed; gives at most one mistake per
// such task. A catalogue mistake is named only when the student's answers are like it wherever
// it differs from the reference (never like the reference there, nor like neither): so a correct
// solution, however written, is never told it made one, and a mistake that matches another on
// some inputs is not named for it where they part. A part-by-part one (MistakeModel::partByPart)
// only when, besides, it alone of its task's fits every answer.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "checks/transcript.h"
#include "mistakes/named.h"

namespace a6::grader {

/// How a student's answer to one request compares with a mistake and with the reference.
enum class Likeness {
  Uninformative,  ///< the mistake answers as the reference does here: this request tells nothing
  Mistake,        ///< the student answers as the mistake does (and the reference does not)
  Reference,      ///< the student answers as the reference does (and the mistake does not)
  Neither,        ///< the student answers as neither does
};

struct MistakeModel {
  std::string id;  ///< the name of its wrong version under tests/wrong/ (a catalogue model)
  int task = 0;
  std::string text;  ///< NamedMistake::text
  /// One likeness per request of the transcript that the model can answer.
  std::function<std::vector<Likeness>(const Transcript&)> judge;
  /// A combination of a function's parts, each in the physics' form or a wrong one (library/
  /// parts.cpp, task2.cpp): named only when it fits every answer where it differs from the physics
  /// and no other such model of its task does; it then takes the place of a catalogue model's name.
  bool partByPart = false;
};

/// The library of known mistakes (empty where the library is not built: a student release).
const std::vector<MistakeModel>& mistakeLibrary();

/// The reference's answer to a simulation the checks of task 3 asked for (the reference
/// stepper with the reference forces: the library's, library/steppers.h), for the report's
/// replays; empty without the library, or for a request it cannot answer (the student's own
/// forces).
std::optional<harness::SimulateResult> referenceSimulation(const harness::SimulateRequest& r);

/// The reference's answer to an implicit simulation the checks of task 7 asked for (the reference
/// implicit step with the reference forces), for the first divergence; empty without the library,
/// or for a request it cannot answer.
std::optional<harness::SimulateResult> referenceImplicitSimulation(
    const harness::SimulateRequest& r);

/// The reference's answer to a run of particles already alive that the checks of task 5 asked
/// for (no emission, the reference forces; the library's, library/steppers.h), for the report's
/// replays; empty without the library, or for a request it cannot answer.
std::optional<harness::ParticlesResult> referenceParticleRun(const harness::ParticleRunRequest& r);

/// The mistake each failing task's answers match best, if any, in task order.
std::vector<NamedMistake> nameMistakes(const Transcript& transcript,
                                       const std::vector<MistakeModel>& library,
                                       const std::set<int>& failingTasks);

}  // namespace a6::grader
