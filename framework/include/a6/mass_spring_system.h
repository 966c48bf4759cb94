// Task 3: the mass-spring system and its time stepping (slides "Time stepping", "Instability").
#pragma once

#include <array>
#include <deque>
#include <vector>

#include "a6/force_model.h"
#include "a6/forces.h"
#include "a6/implicit.h"
#include "a6/spring.h"

namespace a6 {

/// Particles, the springs between them, and their environment.
///
/// Plain, public data in the spirit of the slides. `particles` is a std::deque so that a
/// Particle* (held by springs) stays valid while particles are added at the back; never erase
/// particles from a mass-spring system.
class MassSpringSystem {
 public:
  std::deque<Particle> particles;
  std::vector<Spring> springs;
  Environment env;

  /// Appends a particle; returns its index.
  int addParticle(const Particle& p);
  /// Appends a spring between particles i and j (indices into `particles`). A negative
  /// restLength means "the current distance between the two particles".
  Spring& addSpring(int i, int j, double ks, double kd, SpringType type = SpringType::Other,
                    double restLength = -1);

  /// TASK 3 (time_stepping.cpp). One symplectic Euler step of dt seconds:
  ///   1. initialise each particle's force f with its external force,
  ///   2. add every spring's force to both of its particles (p2 gets +f, p1 gets -f),
  ///   3. for every particle that is not pinned: v += f/m dt, then x += v dt.
  void step(double dt);
  /// TASK 3 (time_stepping.cpp). Advances by frameDt seconds in exactly `substeps` calls of
  /// step(frameDt / substeps). substeps >= 1.
  void advance(double frameDt, int substeps);

  /// TASK 7 (implicit.cpp, extra credit). One linearised backward Euler step of dt seconds
  /// (a6/implicit.h): the forces as in step(), then A Δv = b with
  ///   A = M - dt ∂f/∂v - dt² ∂f/∂x,   b = dt (f + dt ∂f/∂x v),
  /// assembled from every spring's springJacobians() and solved with implicitSystem(); pinned
  /// particles are fixed (Δv = 0); then, for every particle that is not pinned, v += Δv and
  /// x += v dt (with the new v). External forces stay explicit (their Jacobians are left out).
  void stepImplicit(double dt);
  /// Advances by frameDt seconds in `substeps` calls of stepImplicit(frameDt / substeps) (the
  /// framework's, like advance() for step()). substeps >= 1.
  void advanceImplicit(double frameDt, int substeps);
  /// This system's ImplicitSystem (a6/implicit.h) for one implicit step, emptied and sized to
  /// `particles`: the same object at every step, so that the solver keeps the matrix's shape
  /// and ordering from the step before (the same springs, the same shape).
  ImplicitSystem& implicitSystem();

  /// The external force on p (gravity, buoyancy, drag, collisions): your externalForce(p, env)
  /// unless a test has swapped in a reference model (see force_model.h). N, world frame.
  Vec2 externalForce(const Particle& p) const;
  /// The force of spring s on its p2: your s.computeForce() unless swapped. N, world frame.
  Vec2 springForce(const Spring& s) const;
  void setForceModel(ForceModel model) { forceModel_ = std::move(model); }

  /// Energies for plots and tests, J. Potential energy of gravity is measured from y = 0.
  double kineticEnergy() const;
  double springEnergy() const;
  double gravityEnergy() const;
  /// The index of a particle of this system, or -1.
  int indexOf(const Particle* p) const;
  /// The indices of every spring's p1 and p2 in `particles`, in the order of `springs` (-1 for
  /// a particle that is not in this system): what task 7's assembly needs, in O(n) for all.
  std::vector<std::array<int, 2>> springEnds() const;

 private:
  ForceModel forceModel_;
  ImplicitSystem implicit_;
};

}  // namespace a6
