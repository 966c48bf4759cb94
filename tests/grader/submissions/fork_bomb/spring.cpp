// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a fork bomb.
//
// A correct spring, but before main every process forks as fast as it can for two seconds
// (children do the same), then every child exits and the first process goes on to serve. The
// sandbox's process limit stops the bomb at a few processes. Expected: full marks (the bomb
// only costs time), the machine is unaffected, and no process of the submission is left over.
#include "a6/spring.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace {

int bomb() {
  const pid_t first = ::getpid();
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  long forks = 0, refused = 0;
  while (std::chrono::steady_clock::now() < end) {
    const pid_t child = ::fork();
    if (child > 0) ++forks;
    if (child < 0) ++refused;
  }
  if (::getpid() != first) std::_Exit(0);
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {
  }
  std::printf("hostile: fork bomb over: %ld forks, %ld refused\n", forks, refused);
  return 0;
}

const int kBombed = bomb();

}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
