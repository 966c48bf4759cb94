// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a child that tries to
// outlive the grader.
//
// A correct spring, but before main the probe forks a child that leaves the probe's session and
// process group (setsid), ignores SIGHUP and SIGTERM and sleeps for ten minutes, holding the
// probe's stdout. Expected: full marks, a6_grade does not wait for the child, and the child is
// gone when a6_grade ends.
#include "a6/spring.h"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace {

int escape() {
  const pid_t child = ::fork();
  if (child == 0) {
    ::setsid();
    ::signal(SIGHUP, SIG_IGN);
    ::signal(SIGTERM, SIG_IGN);
    std::puts("hostile: the escaped child is sleeping");
    std::fflush(stdout);
    ::sleep(600);
    std::_Exit(0);
  }
  std::printf("hostile: forked %d\n", static_cast<int>(child));
  return 0;
}

const int kEscaped = escape();

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
