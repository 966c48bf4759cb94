// HOSTILE SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): reach the golden
// images and the hidden tests at compile time.
//
// The file asks the compiler whether it can see tests/golden/manifest.json, a golden PNG or the
// test sources (by absolute path and by climbing up from the submission's folder). A submission
// that could read them could compare itself with the references; this one stands for any such
// cheat by returning the correct force only when one of them is visible, and the starter's zero
// otherwise. (@A6_SOURCE_DIR@ is replaced by the repository's path when the test stages the
// submission.) Expected: nothing is visible to the compiler, so task 1 gets 0.
#include "a6/spring.h"

#if __has_include("@A6_SOURCE_DIR@/tests/golden/manifest.json") || \
    __has_include("@A6_SOURCE_DIR@/tests/golden/pendulum_f0.png") || \
    __has_include("@A6_SOURCE_DIR@/tests/task1_spring_test.cpp") || \
    __has_include("@A6_SOURCE_DIR@/grader/reference/physics.inc") || \
    __has_include("../tests/golden/manifest.json") || \
    __has_include("../../tests/golden/manifest.json") || \
    __has_include("../../../tests/golden/manifest.json") || \
    __has_include("../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../../../../../../tests/golden/manifest.json") || \
    __has_include("../../../../../../../../../../../../tests/golden/manifest.json") || \
    __has_include(<golden/manifest.json>) || __has_include(<reference/physics.inc>)
#define A6_HOSTILE_SEES_SECRETS 1
#endif

namespace a6 {

Vec2 Spring::computeForce() const {
#ifdef A6_HOSTILE_SEES_SECRETS
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
#else
  return Vec2::Zero();
#endif
}

}  // namespace a6
