// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): #include the
// solution at compile time.
//
// If the compiler can reach the solution's spring.cpp, by its absolute path or by climbing up
// from the submission's folder (../ up to 16 times), this file includes it and gets the
// solution's computeForce; otherwise it falls back to the starter's stub. The probe is compiled
// in the sandbox, which hides the repository. (@A6_SOURCE_DIR@ is replaced by the repository's
// path when the test stages the submission.) Expected: the stub, so task 1 gets 0.
#if __has_include("@A6_SOURCE_DIR@/solution/spring.cpp")
#include "@A6_SOURCE_DIR@/solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../solution/spring.cpp")
#include "../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../solution/spring.cpp")
#include "../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../solution/spring.cpp")
#include "../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../solution/spring.cpp")
#include "../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../solution/spring.cpp")
#include "../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../solution/spring.cpp")
#include "../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../../solution/spring.cpp")
#include "../../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../../../solution/spring.cpp")
#include "../../../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../../../../solution/spring.cpp")
#include "../../../../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../../../../../solution/spring.cpp")
#include "../../../../../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../../../../../../solution/spring.cpp")
#include "../../../../../../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include("../../../../../../../../../../../../solution/spring.cpp")
#include "../../../../../../../../../../../../solution/spring.cpp"
#define A6_HOSTILE_LEAKED 1
#elif __has_include(<solution/spring.cpp>)
#include <solution/spring.cpp>
#define A6_HOSTILE_LEAKED 1
#endif

#ifndef A6_HOSTILE_LEAKED
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const { return Vec2::Zero(); }

}  // namespace a6
#endif
