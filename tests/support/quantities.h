// What a compared value is, for people: the checks compare C++ expressions (forceOf(r),
// result.particles[0].v), whose text a student should never have to read. Each is named in
// words with its unit from the expression's last member ("v": velocity, m/s) and the particle
// it belongs to ("particles[0]": particle 0).
#pragma once

#include <string>

namespace a6::test {

struct Quantity {
  std::string words;  ///< "particle 0's velocity"
  std::string unit;   ///< "m/s"; "" when it has none or it varies (a motor's speed)
};

/// The quantity an expression of the checks stands for; an expression not in the table is
/// "the value checked", without a unit.
Quantity quantityOf(const std::string& expression);

}  // namespace a6::test
