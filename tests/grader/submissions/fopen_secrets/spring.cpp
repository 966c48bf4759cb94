// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): read the solution
// and the golden images at run time.
//
// Before main (before the probe's seccomp filter) and on its first call, the file tries to open
// the solution's spring.cpp, the golden manifest and a golden PNG, by absolute path and by
// climbing up from its working directory. A submission that could read them could copy the
// answers; this one stands for any such cheat by returning the correct force only if one of them
// could be read, and the starter's zero otherwise. It prints what it could read (the report shows
// it). (@A6_SOURCE_DIR@ is replaced by the repository's path when the test stages the
// submission.) Expected: nothing can be read, so task 1 gets 0.
#include "a6/spring.h"

#include <cstdio>
#include <string>
#include <vector>

namespace {

bool gLeaked = false;

bool readable(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return false;
  char buffer[16];
  const bool got = std::fread(buffer, 1, sizeof buffer, f) > 0;
  std::fclose(f);
  return got;
}

bool tryAll(bool report) {
  std::vector<std::string> paths = {"@A6_SOURCE_DIR@/solution/spring.cpp",
                                    "@A6_SOURCE_DIR@/tests/golden/manifest.json",
                                    "@A6_SOURCE_DIR@/tests/golden/pendulum_f0.png",
                                    "@A6_SOURCE_DIR@/tests/task1_spring_test.cpp"};
  std::string up = ".";
  for (int k = 0; k < 16; ++k) {
    up += "/..";
    paths.push_back(up + "/solution/spring.cpp");
    paths.push_back(up + "/tests/golden/manifest.json");
  }
  bool any = false;
  for (const std::string& p : paths) {
    const bool ok = readable(p);
    if (report) std::printf("hostile: %s %s\n", ok ? "READ" : "could not read", p.c_str());
    any = any || ok;
  }
  std::fflush(stdout);
  return any;
}

const int kTried = (gLeaked = tryAll(true), 0);

}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  static const bool leakedLater = tryAll(false);  // after the filter; once (it is slow)
  if (!gLeaked && !leakedLater) return Vec2::Zero();
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
