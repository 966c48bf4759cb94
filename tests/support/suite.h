// What every test file of the physics suite shares: the student's code under test, tolerances
// relative to the scale of each comparison's inputs, and failure messages that name the task, the
// input, the expected and actual value, and a hint.
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

/// The shortest text that reads back as the same double: 1e-12, 0.1, 9.81.
std::string num(double value);
std::string str(const Vec2& v);
std::string str(const Particle& p);

/// Appended to a failure: what the student should look at. Nothing when the student's code
/// gave no answer in this check (a hint is written for a wrong answer, not for a crash or a
/// time-out; watched_student.h).
std::string hint(const std::string& text);
/// Marks the running check: the student's code gave no answer to one of its requests.
void noteCodeFailed();
/// Whether noteCodeFailed was called during the running check.
bool codeFailedInThisCheck();
/// A failure's message for people: GoogleTest's "Failed" line (ADD_FAILURE's) left out.
std::string messageOf(const ::testing::TestPartResult& part);

/// True when every component is finite.
inline bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// --- Tolerances ------------------------------------------------------------------------------
// Every comparison's tolerance is `relative` times the scale of its own inputs (a spring force's
// ks·max(l, l0) + kd·|Δv|, a cloth's size, a scene's extent), so a correct solution computed with
// float intermediates (about 1e-7 of the scale) passes with a wide margin, and a mistake (a term
// of the physics wrong: off by its own size) fails by a wide margin too. docs/instructor.md
// ("Tolerances and margins") gives the margins the wrong versions keep.

/// One computation from the inputs (a force, one step).
constexpr double kOneComputation = 1e-5;
/// A value after many steps: float rounding accumulates with each one.
constexpr double kManySteps = 1e-4;

struct Tolerance {
  double scale = 1;     ///< the size of the inputs the value comes from, in its units
  double relative = 0;  ///< the allowed error, as a fraction of scale
  /// True when the expected value is exact, so any difference is rounding (the float note of
  /// the grader's report reads these); false for a model's error (statistics, discretisation).
  bool exact = true;
  double absolute() const { return scale * relative; }
};

/// `relative` of `scale`: the expected value is exact, the difference can only be rounding.
inline Tolerance relativeTo(double scale, double relative = kOneComputation) {
  return Tolerance{std::abs(scale), relative, true};
}
/// An allowed error `absolute` that is a model's own (a period measured from a discrete orbit,
/// a sample mean): no rounding, no float note. `scale` names what it is a fraction of.
inline Tolerance modelError(double absolute, double scale) {
  return Tolerance{std::abs(scale), scale != 0 ? std::abs(absolute / scale) : 0, false};
}

/// |actual - expected| <= tol, componentwise; the message names both values and the task.
::testing::AssertionResult vecNear(const char* actualExpr, const char* expectedExpr,
                                   const char* tolExpr, const Vec2& actual, const Vec2& expected,
                                   const Tolerance& tol);
/// |actual - expected| <= tol; the message names both values and the task.
::testing::AssertionResult scalarNear(const char* actualExpr, const char* expectedExpr,
                                      const char* tolExpr, double actual, double expected,
                                      const Tolerance& tol);

/// A check over many inputs reports the first that fails and how many more did, not one
/// message each:
///   ManyInputs inputs("directions");
///   for (...) inputs.expectNear(actual, expected, tol, input(r));
///   inputs.report(hint("..."));   // or let it go out of scope
/// A unit, for messages: values are printed with it ("(-10, 0) N").
struct Unit {
  const char* name;
};
inline constexpr Unit kNewton{"N"}, kMetre{"m"}, kMetrePerSecond{"m/s"}, kMomentum{"kg·m/s"},
    kAngularMomentum{"kg·m²/s"};

class ManyInputs {
 public:
  /// The failure is reported at the line that made this object (the check's own line).
  explicit ManyInputs(std::string what, const char* file = __builtin_FILE(),
                      int line = __builtin_LINE())
      : what_(std::move(what)), file_(file), line_(line) {}
  /// With the unit of the compared values, for the message (kNewton, ...).
  ManyInputs(std::string what, Unit unit, const char* file = __builtin_FILE(),
             int line = __builtin_LINE())
      : what_(std::move(what)), unit_(unit.name), file_(file), line_(line) {}
  ManyInputs(const ManyInputs&) = delete;
  ManyInputs& operator=(const ManyInputs&) = delete;
  ~ManyInputs() { report(""); }

  /// Compares one input's value; `input` says which input it was (shown for the first failure).
  bool expectNear(const Vec2& actual, const Vec2& expected, const Tolerance& tol,
                  const std::string& input);
  bool expectNear(double actual, double expected, const Tolerance& tol, const std::string& input);
  /// Records an input that failed for another reason (with its own message).
  void fail(const std::string& message);
  int failed() const { return failed_; }
  /// Adds one GoogleTest failure for all the failed inputs, if any, with `hint` appended.
  void report(const std::string& hint);

 private:
  bool record(const ::testing::AssertionResult& result, const std::string& input);
  std::string what_;
  std::string unit_;
  const char* file_;
  int line_;
  std::string first_;
  int total_ = 0, failed_ = 0;
  bool reported_ = false;
};

}  // namespace a6::test

/// EXPECT_VEC_NEAR(actual, expected, relativeTo(scale)) << "input: ..." << hint("...");
#define EXPECT_VEC_NEAR(actual, expected, tol) \
  EXPECT_PRED_FORMAT3(::a6::test::vecNear, actual, expected, tol)
#define ASSERT_VEC_NEAR(actual, expected, tol) \
  ASSERT_PRED_FORMAT3(::a6::test::vecNear, actual, expected, tol)
#define EXPECT_CLOSE(actual, expected, tol) \
  EXPECT_PRED_FORMAT3(::a6::test::scalarNear, actual, expected, tol)
#define ASSERT_CLOSE(actual, expected, tol) \
  ASSERT_PRED_FORMAT3(::a6::test::scalarNear, actual, expected, tol)

/// Stops the test (FAIL returns) when the student's code reported an error (an exception, or in
/// the grader a crash or timeout), with that error in the message and none of GoogleTest's
/// "Value of:" lines (the student reads it). The switch keeps an `else` after it from binding to
/// the macro's own `if`, as GoogleTest's macros do.
#define A6_ASSERT_RAN(result) A6_RAN_(result, FAIL())
/// The same, and the test goes on.
#define A6_EXPECT_RAN(result) A6_RAN_(result, ADD_FAILURE())
#define A6_RAN_(result, failure) \
  switch (0)                     \
  case 0:                        \
  default:                       \
    if ((result).ok()) {         \
    } else                       \
      failure << ::a6::test::currentTask() << ": your code failed: " << (result).error
