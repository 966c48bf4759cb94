// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): writing files.
//
// A correct spring that tries to leave a file named a6_hostile_was_here wherever it can: its
// working directory, every folder above it (the grader's output folder, the build tree, the
// repository, /), the repository's solution/ and tests/golden/, /tmp, /var/tmp, /dev/shm, /root,
// /autograder/results; before main (before the probe's seccomp filter) and on its first call.
// (@A6_SOURCE_DIR@ is replaced by the repository's path when the test stages the submission.)
// Expected: full marks, and afterwards no such file exists anywhere outside the probe's own
// working directory (which is removed).
#include "a6/spring.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

const char* const kName = "a6_hostile_was_here";

bool plant(const std::string& dir) {
  const std::string path = dir + "/" + kName;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (fd < 0) return false;
  const char text[] = "written by a hostile submission\n";
  ssize_t ignored = ::write(fd, text, sizeof text - 1);
  (void)ignored;
  ::close(fd);
  return true;
}

void plantEverywhere(bool report) {
  std::string up = ".";
  std::vector<std::string> dirs = {"."};
  for (int k = 0; k < 16; ++k) {
    up += "/..";
    dirs.push_back(up);
  }
  for (const char* d :
       {"@A6_SOURCE_DIR@", "@A6_SOURCE_DIR@/solution", "@A6_SOURCE_DIR@/tests/golden", "/tmp",
        "/var/tmp", "/dev/shm", "/root", "/autograder/results", "/"}) {
    dirs.emplace_back(d);
  }
  for (const std::string& d : dirs) {
    const bool ok = plant(d);
    if (report)
      std::printf("hostile: %s %s/%s\n", ok ? "WROTE" : "could not write", d.c_str(), kName);
  }
  std::fflush(stdout);
}

const int kPlanted = (plantEverywhere(true), 0);

}  // namespace

namespace a6 {

Vec2 Spring::computeForce() const {
  static const bool planted = (plantEverywhere(false), true);  // after the filter; once
  (void)planted;
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
