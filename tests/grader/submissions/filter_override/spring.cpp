// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): switching the probe's
// seccomp filter off.
//
// It defines the libseccomp functions a probe would call to install its filter (seccomp_init,
// seccomp_rule_add, seccomp_load, seccomp_export_bpf), each pretending success, so that a probe
// linked against libseccomp after the student's objects would run without a filter. The spring
// is correct, and on every call it tries to open a file. Expected: the probe's filter does not
// depend on any of these (grader/probe/filter.h), so the file cannot be opened ("hostile: open
// refused" in the report, never "hostile: READ") and the submission gets full marks.
#include "a6/spring.h"

#include <cstdio>

extern "C" {
void* seccomp_init(unsigned) { return reinterpret_cast<void*>(1); }
int seccomp_rule_add(void*, unsigned, int, unsigned, ...) { return 0; }
int seccomp_load(void*) { return 0; }
int seccomp_export_bpf(void*, int) { return 0; }
void seccomp_release(void*) {}
}

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
// Before main and on each call would do: the first tells.
const bool kTried = [] {
  FILE* f = std::fopen("/etc/hostname", "rb");
  std::puts(f != nullptr ? "hostile: READ /etc/hostname" : "hostile: open refused");
  if (f != nullptr) std::fclose(f);
  return true;
}();
}  // namespace
