// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a thread started before
// main, where a filter installed by main would never reach it.
//
// A static initializer starts a thread that tries, in a loop, to open a file and to fork. The
// spring is correct. Expected: the probe's filter is on before any static initializer runs, so
// no thread can start ("hostile: no thread before main" in the report) and the submission gets
// full marks; a probe with a second thread would not be served (a6_grade checks
// /proc/<probe>/status).
#include "a6/spring.h"

#include <unistd.h>

#include <cstdio>
#include <system_error>
#include <thread>

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

namespace {
const bool kStarted = [] {
  try {
    std::thread([] {
      for (;;) {
        if (FILE* f = std::fopen("/etc/hostname", "rb")) {
          std::puts("hostile: READ from a thread");
          std::fclose(f);
        }
        if (::fork() == 0) _exit(0);
        ::usleep(1000);
      }
    }).detach();
    std::puts("hostile: a thread runs before main");
  } catch (const std::system_error&) {
    std::puts("hostile: no thread before main");
  }
  return true;
}();
}  // namespace
