// Which force functions the time steppers call.
//
// Design note: grading one task at a time.
// The steppers of tasks 3 and 5 need forces, which tasks 1 and 2 compute. If step() called
// those functions directly, one sign error in task 1 would also fail every test of task 3.
// So the systems reach the forces through this small model: by default it calls your own
// Spring::computeForce and externalForce; the graders' tests may swap in reference models so
// that a bug in one task costs that task only. Call MassSpringSystem::springForce /
// externalForce (and ParticleSystem::externalForce) from your steppers and you get this for free.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "a6/forces.h"
#include "a6/spring.h"

namespace a6 {

/// The particles of a system, whichever container holds them.
struct ParticlesView {
  std::size_t count = 0;
  std::function<const Particle&(std::size_t)> at;
};

struct ForceModel {
  /// Replaces externalForce(p, env) when set.
  std::function<Vec2(const Particle&, const Environment&)> external;
  /// Replaces spring.computeForce() when set.
  std::function<Vec2(const Spring&)> spring;
  /// For a model that is cheaper asked about many forces at once than one at a time (the
  /// graders' reference models, which are in another process): the force of `s`, one of the
  /// system's `springs`. The systems use it, when set, for their own springs.
  std::function<Vec2(const Spring& s, const std::vector<Spring>& springs)> springAmong;
  /// Likewise: the external force on `p`, one of the system's particles `all`.
  std::function<Vec2(const Particle& p, const ParticlesView& all, const Environment& env)>
      externalAmong;
};

}  // namespace a6
