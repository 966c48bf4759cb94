// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): an exception with a
// message of nearly 4 MiB.
//
// computeForce throws, with a message that goes on for 4 MiB less 64 KiB of bytes that are not
// UTF-8 (each becomes a 3-byte U+FFFD once made valid): with the words around it in a scene's
// error, the largest answer a probe can send, so every answer is decoded, and the message kept for
// every failed request of every check. Expected: task 1's checks fail with the message's start,
// cut, every other task keeps its points, and a6_grade's memory stays under 300 MB.
#include "a6/spring.h"

#include <stdexcept>
#include <string>

namespace a6 {

Vec2 Spring::computeForce() const {
  throw std::runtime_error("hostile: thrown from computeForce" +
                           std::string((std::size_t{4} << 20) - (std::size_t{64} << 10), '\xff'));
}

}  // namespace a6
