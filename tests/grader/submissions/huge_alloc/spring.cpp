// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a huge allocation.
//
// computeForce asks for 8 GiB and fills it. Expected: the probe's memory limit refuses it
// (std::bad_alloc), task 1's checks fail with that reason, the grader and the machine are
// unaffected, every other task keeps its points.
#include "a6/spring.h"

#include <cstddef>
#include <vector>

namespace a6 {

Vec2 Spring::computeForce() const {
  std::vector<char> hog(std::size_t{8} << 30, 1);
  return Vec2(static_cast<double>(hog[12345]), 0);
}

}  // namespace a6
