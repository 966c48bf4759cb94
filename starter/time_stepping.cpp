// Task 3 — time stepping
// Slides: "Time stepping", "Instability".
//
// One step of dt seconds, as on the slide:
//
//     1. initialise each force:       p.f = externalForce(p)         (gravity, drag, ...)
//     2. add every spring's force:    f = springForce(s);  s.p2->f += f;  s.p1->f -= f;
//     3. integrate every particle that is not pinned, VELOCITY FIRST (symplectic Euler):
//            v += f / m dt
//            x += v dt                                                 (with the new v)
//
// Use the system's externalForce(p) and springForce(s) helpers (a6/mass_spring_system.h):
// they call your task 1 and task 2 code, and let the graders test this task on its own.
// Pinned particles never move.
//
// advance(frameDt, n) takes exactly n substeps of frameDt / n. Stiff springs need small steps:
// a mass on a spring of stiffness k is stable only while sqrt(k/m) dt < 2 (slide
// "Instability"); the stiff cloth scene explodes with 1 substep and holds with 10.
//
// Done when: `ctest -R Task3` passes (tests named Task3TimeStepping.*): one step against hand-
// computed values, free fall, the oscillator's period, bounded energy, momentum conservation,
// pinning, terminal velocity, and substeps.
#include "a6/mass_spring_system.h"

namespace a6 {

void MassSpringSystem::step(double dt) {
  // TODO(task 3): the three parts above.
}

void MassSpringSystem::advance(double frameDt, int substeps) {
  // TODO(task 3): call step(frameDt / substeps) substeps times.
}

}  // namespace a6
