// The reference joints (task 6): what a joint's parameters are, as Box2D holds them, beyond the
// scenes' own constants (scenes/box2d_scenes.h, which the students read too). The mistake
// library's models of task 6 judge the student's joints against these. Graders' material, as
// physics.inc.
#pragma once

namespace a6::grader::reference {

/// The mouse joint of a drag: maxForce = kMouseForcePerKilogram × the body's mass, its spring
/// at kMouseHertz (damping ratio 0.7).
constexpr double kMouseForcePerKilogram = 1000;  ///< N/kg
constexpr double kMouseHertz = 5;

/// b2LinearStiffness: the stiffness, N/m, of a spring of `hertz` between two bodies (a mass of 0:
/// a static body), m ω² with m their reduced mass and ω = 2π hertz.
/// The two bodies' reduced mass, as b2LinearStiffness takes it (a mass of 0: a static body).
inline double reducedMass(double massA, double massB) {
  return massA > 0 && massB > 0 ? massA * massB / (massA + massB) : massA > 0 ? massA : massB;
}

inline double referenceJointStiffness(double massA, double massB, double hertz) {
  const double mass = reducedMass(massA, massB);
  const double omega = 2 * 3.14159265358979323846 * hertz;
  return mass * omega * omega;
}

/// b2LinearStiffness: the damping, N·s/m, of that spring with `ratio`: 2 m ratio ω.
inline double referenceJointDamping(double massA, double massB, double hertz, double ratio) {
  return 2 * reducedMass(massA, massB) * ratio * 2 * 3.14159265358979323846 * hertz;
}

/// The mouse joint's damping ratio.
constexpr double kMouseDampingRatio = 0.7;

}  // namespace a6::grader::reference
