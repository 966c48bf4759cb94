// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a step that asks for
// forces without end.
//
// In the checks of task 3 the forces come from the grader, one round trip per state
// (framework/harness/force_channel.h), and each answer earns the check a small allowance of
// wall-clock time. This step asks for them forever. Expected: every such check stops at its
// time limit plus the allowance, counted once; the grading as a whole stays within the build
// budget plus --time-budget plus the grader's own work; only task 3 (and what runs its step)
// loses points.
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  for (volatile long round = 0;; round = round + 1) {
    for (Particle& p : particles) p.f = externalForce(p);
    for (const Spring& s : springs) s.p1->f += springForce(s) * dt;
  }
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  for (int k = 0; k < substeps; ++k) step(frameDt / substeps);
}

}  // namespace a6
