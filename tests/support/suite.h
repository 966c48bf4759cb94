// What every test file of the physics suite shares: the student's code under test, and
// failure messages that name the task, the input, the expected and actual value, and a hint.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "harness/student_code.h"

namespace a6::test {

/// The student's code under test (in-process for students, a probe for the grader).
harness::StudentCode& student();

/// "Task 3 (time_stepping.cpp)" for the running test, from its suite name "Task3...".
std::string currentTask();

std::string str(const Vec2& v);
std::string str(const Particle& p);

/// Appended to a failure: what the student should look at.
std::string hint(const std::string& text);

/// True when every component is finite.
inline bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

/// |actual - expected| <= tol, componentwise; the message names both values and the task.
::testing::AssertionResult vecNear(const char* actualExpr, const char* expectedExpr,
                                   const char* tolExpr, const Vec2& actual, const Vec2& expected,
                                   double tol);
/// |actual - expected| <= tol; the message names both values and the task.
::testing::AssertionResult scalarNear(const char* actualExpr, const char* expectedExpr,
                                      const char* tolExpr, double actual, double expected,
                                      double tol);

}  // namespace a6::test

/// EXPECT_VEC_NEAR(actual, expected, tol) << "input: ..." << a6::test::hint("...");
#define EXPECT_VEC_NEAR(actual, expected, tol) \
  EXPECT_PRED_FORMAT3(::a6::test::vecNear, actual, expected, tol)
#define ASSERT_VEC_NEAR(actual, expected, tol) \
  ASSERT_PRED_FORMAT3(::a6::test::vecNear, actual, expected, tol)
#define EXPECT_CLOSE(actual, expected, tol) \
  EXPECT_PRED_FORMAT3(::a6::test::scalarNear, actual, expected, tol)
#define ASSERT_CLOSE(actual, expected, tol) \
  ASSERT_PRED_FORMAT3(::a6::test::scalarNear, actual, expected, tol)

/// Stops the test when the student's code reported an error (an exception, or in the grader a
/// crash or timeout), with that error in the message.
#define A6_ASSERT_RAN(result) \
  ASSERT_TRUE((result).ok()) << ::a6::test::currentTask() << ": your code failed: " << (result).error
