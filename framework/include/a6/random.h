// The framework's seeded random generator: the same seed gives the same numbers on every
// machine (it does not depend on the standard library's distributions).
#pragma once

#include <cstdint>

#include "a6/particle.h"

namespace a6 {

class Random {
 public:
  explicit Random(std::uint64_t seed = 1);
  /// Uniform in [0, 1).
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi);
  /// Uniform over the disc of the given radius around the origin.
  Vec2 inDisc(double radius);

 private:
  std::uint64_t next();
  std::uint64_t state_[4];
};

}  // namespace a6
