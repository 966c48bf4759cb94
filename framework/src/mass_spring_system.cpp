// The framework's part of the mass-spring system; step() and advance() are task 3, stepImplicit()
// task 7.
#include "a6/mass_spring_system.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace a6 {

int MassSpringSystem::addParticle(const Particle& p) {
  particles.push_back(p);
  return static_cast<int>(particles.size()) - 1;
}

Spring& MassSpringSystem::addSpring(int i, int j, double ks, double kd, SpringType type,
                                    double restLength) {
  const int n = static_cast<int>(particles.size());
  if (i < 0 || j < 0 || i >= n || j >= n || i == j) {
    throw std::out_of_range("addSpring(" + std::to_string(i) + ", " + std::to_string(j) +
                            "): needs two different particle indices in [0, " + std::to_string(n) +
                            ")");
  }
  Spring s;
  s.p1 = &particles[i];
  s.p2 = &particles[j];
  s.restLength = restLength >= 0 ? restLength : (s.p2->x - s.p1->x).norm();
  s.ks = ks;
  s.kd = kd;
  s.type = type;
  springs.push_back(s);
  return springs.back();
}

Vec2 MassSpringSystem::externalForce(const Particle& p) const {
  if (forceModel_.externalAmong) {
    const ParticlesView all{particles.size(),
                            [this](std::size_t i) -> const Particle& { return particles[i]; }};
    return forceModel_.externalAmong(p, all, env);
  }
  return forceModel_.external ? forceModel_.external(p, env) : a6::externalForce(p, env);
}

Vec2 MassSpringSystem::springForce(const Spring& s) const {
  if (forceModel_.springAmong) return forceModel_.springAmong(s, springs);
  return forceModel_.spring ? forceModel_.spring(s) : s.computeForce();
}

double MassSpringSystem::kineticEnergy() const {
  double e = 0;
  for (const Particle& p : particles) e += 0.5 * p.m * p.v.squaredNorm();
  return e;
}

double MassSpringSystem::springEnergy() const {
  double e = 0;
  for (const Spring& s : springs) {
    const double stretch = (s.p2->x - s.p1->x).norm() - s.restLength;
    e += 0.5 * s.ks * stretch * stretch;
  }
  return e;
}

double MassSpringSystem::gravityEnergy() const {
  double e = 0;
  for (const Particle& p : particles) e -= p.m * env.gravity.dot(p.x);
  return e;
}

int MassSpringSystem::indexOf(const Particle* p) const {
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (&particles[i] == p) return static_cast<int>(i);
  }
  return -1;
}

std::vector<std::array<int, 2>> MassSpringSystem::springEnds() const {
  std::unordered_map<const Particle*, int> index;
  index.reserve(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) index[&particles[i]] = static_cast<int>(i);
  const auto find = [&](const Particle* p) {
    const auto it = index.find(p);
    return it == index.end() ? -1 : it->second;
  };
  std::vector<std::array<int, 2>> ends;
  ends.reserve(springs.size());
  for (const Spring& s : springs) ends.push_back({find(s.p1), find(s.p2)});
  return ends;
}

ImplicitSystem& MassSpringSystem::implicitSystem() {
  implicit_.reset(static_cast<int>(particles.size()));
  return implicit_;
}

void MassSpringSystem::advanceImplicit(double frameDt, int substeps) {
  const int steps = std::max(1, substeps);
  for (int k = 0; k < steps; ++k) stepImplicit(frameDt / steps);
}

}  // namespace a6
