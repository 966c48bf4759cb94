#include "suite.h"

#include <cstdio>
#include <limits>

#include "comparisons.h"
#include "harness/tasks.h"
#include "quantities.h"

namespace a6::test {

std::string currentTask() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string suite = info != nullptr ? info->test_suite_name() : "";
  const int task = courseTasks().ofSuite(suite).task;
  if (task == 0) return "Task ?";
  return "Task " + std::to_string(task) + " (" + courseTasks().file(task) + ")";
}

std::string num(double value) {
  if (value == 0) return "0";  // never "-0"
  // Seven significant digits: more than any tolerance needs to show a difference, and none of
  // the binary noise (5.199999999999999, 0.00035000000000000005).
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.7g", value);
  std::string text = buffer;
  // 2e-05 -> 2e-5, 1e+30 -> 1e30.
  if (const std::size_t e = text.find('e'); e != std::string::npos) {
    std::string exponent = text.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent = exponent.substr(exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    text = text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  return text;
}

std::string str(const Vec2& v) { return "(" + num(v.x()) + ", " + num(v.y()) + ")"; }

std::string str(const Particle& p) {
  std::string out = "{x=" + str(p.x) + ", v=" + str(p.v) + ", m=" + num(p.m);
  if (p.pinned) out += ", pinned";
  return out + "}";
}

namespace {

bool startsWith(const std::string& text, const std::string& head) {
  return text.rfind(head, 0) == 0;
}

// GoogleTest's words for a failed EXPECT_TRUE(expression) left out ("Value of: expression",
// "Actual: false", "Expected: true"), keeping the message an AssertionResult carried in the
// parentheses, and what follows.
std::string withoutValueOf(const std::string& message) {
  static const std::string kFalse = "\n  Actual: false", kTrue = "\nExpected: true";
  const std::size_t actual = message.find(kFalse);
  const std::size_t expected = message.rfind(kTrue);
  if (actual == std::string::npos || expected == std::string::npos || expected < actual)
    return message;
  std::string carried = message.substr(actual + kFalse.size(), expected - actual - kFalse.size());
  if (startsWith(carried, " (") && carried.back() == ')')
    carried = carried.substr(2, carried.size() - 3);
  std::string rest = message.substr(expected + kTrue.size());
  if (startsWith(rest, "\n")) rest = rest.substr(1);
  if (carried.empty() && rest.empty()) return message;  // nothing of the check's own to keep
  return carried.empty() ? rest : rest.empty() ? carried : carried + "\n" + rest;
}

}  // namespace

std::string messageOf(const ::testing::TestPartResult& part) {
  std::string message = part.message();
  if (startsWith(message, "Failed\n")) return message.substr(7);
  if (startsWith(message, "Value of: ")) return withoutValueOf(message);
  // A pointer checked against null ("Expected: (snapshot) != (nullptr), actual: NULL vs
  // (nullptr)"), then the check's own words: only those say anything. Other comparisons keep
  // their line, whose numbers matter.
  const std::size_t line = message.find('\n');
  if (startsWith(message, "Expected: (") && line != std::string::npos &&
      message.rfind(" != (nullptr), actual: ", line) != std::string::npos)
    return message.substr(line + 1);
  return message;
}

namespace {

ComparisonLog gLog;

// The log of the running check, emptied when a new check starts.
ComparisonLog& currentLog() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (gLog.check != info) gLog = ComparisonLog{info};
  return gLog;
}

}  // namespace

std::string hint(const std::string& text) {
  return codeFailedInThisCheck() ? "" : "\n  hint: " + text;
}

void noteCodeFailed() { currentLog().codeFailed = true; }

bool codeFailedInThisCheck() { return currentLog().codeFailed; }

namespace {

// |difference| / tolerance: 0 for equal values, infinite for a non-finite value.
double ratioOf(double difference, const Tolerance& tol) {
  if (!std::isfinite(difference)) return std::numeric_limits<double>::infinity();
  if (difference == 0) return 0;
  const double allowed = tol.absolute();
  return allowed > 0 ? std::abs(difference) / allowed : std::numeric_limits<double>::infinity();
}

// Records one comparison whose largest component difference is `difference`; true if it passed.
bool recordComparison(double difference, const Tolerance& tol) {
  ComparisonLog& log = currentLog();
  const double ratio = ratioOf(difference, tol);
  const bool passed = ratio <= 1;
  if (passed && tol.exact) {
    log.largestPassingRatio = std::max(log.largestPassingRatio, ratio);
    if (tol.scale > 0) log.agreement = std::max(log.agreement, std::abs(difference) / tol.scale);
  } else if (!passed) {
    log.largestFailingRatio = std::max(log.largestFailingRatio, ratio);
  }
  return passed;
}

// " N", or "" for a quantity without a unit.
std::string unitText(const std::string& unit) { return unit.empty() ? "" : " " + unit; }

std::string toleranceText(const Tolerance& tol, const std::string& unit) {
  return "(tolerance " + num(tol.absolute()) + unitText(unit) + (tol.exact ? ": " : ", ") +
         num(tol.relative) + " of " + num(tol.scale) + unitText(unit) + ")";
}

// A comparison in a check whose code gave no answer (a crash, a time-out): the value is the
// result's default, not the student's, so it is not shown. The check's margin is infinite, as for
// any failure that is not a number (comparisons.h).
::testing::AssertionResult notCompared(const std::string& what) {
  currentLog().largestFailingRatio = std::numeric_limits<double>::infinity();
  return ::testing::AssertionFailure()
         << currentTask() << ": " << what << ": not compared (your code gave no answer: see above)";
}

// `what`: the compared quantity in words; `unit`: its unit, or "".
::testing::AssertionResult compareVec(const std::string& what, const std::string& unit,
                                      const Vec2& actual, const Vec2& expected,
                                      const Tolerance& tol) {
  if (codeFailedInThisCheck()) return notCompared(what);
  const Vec2 diff = actual - expected;
  const double largest =
      finite(actual) ? diff.cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
  if (recordComparison(largest, tol)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << currentTask() << ": " << what << "\n  expected: " << str(expected) << unitText(unit)
         << "\n  actual:   " << str(actual) << unitText(unit) << "\n  " << toleranceText(tol, unit);
}

::testing::AssertionResult compareScalar(const std::string& what, const std::string& unit,
                                         double actual, double expected, const Tolerance& tol) {
  if (codeFailedInThisCheck()) return notCompared(what);
  const double diff =
      std::isfinite(actual) ? actual - expected : std::numeric_limits<double>::infinity();
  if (recordComparison(std::abs(diff), tol)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << currentTask() << ": " << what << "\n  expected: " << num(expected) << unitText(unit)
         << "\n  actual:   " << num(actual) << unitText(unit) << "\n  " << toleranceText(tol, unit);
}

}  // namespace

::testing::AssertionResult vecNear(const char* actualExpr, const char*, const char*,
                                   const Vec2& actual, const Vec2& expected, const Tolerance& tol) {
  const Quantity q = quantityOf(actualExpr);
  ::testing::AssertionResult result = compareVec(q.words, q.unit, actual, expected, tol);
  if (!result) ++currentLog().reportedFailures;
  return result;
}

::testing::AssertionResult scalarNear(const char* actualExpr, const char*, const char*,
                                      double actual, double expected, const Tolerance& tol) {
  const Quantity q = quantityOf(actualExpr);
  ::testing::AssertionResult result = compareScalar(q.words, q.unit, actual, expected, tol);
  if (!result) ++currentLog().reportedFailures;
  return result;
}

bool ManyInputs::record(const ::testing::AssertionResult& result, const std::string& input) {
  ++total_;
  if (result) return true;
  if (failed_++ == 0) {
    const std::size_t text = input.find_first_not_of(" ");
    first_ = std::string(result.message()) + (input.rfind('\n', 0) == 0 ? "" : "\n  ") +
             (text == std::string::npos ? input : input.substr(text));
  }
  return false;
}

bool ManyInputs::expectNear(const Vec2& actual, const Vec2& expected, const Tolerance& tol,
                            const std::string& input) {
  return record(compareVec(what_, unit_, actual, expected, tol), input);
}

bool ManyInputs::expectNear(double actual, double expected, const Tolerance& tol,
                            const std::string& input) {
  return record(compareScalar(what_, unit_, actual, expected, tol), input);
}

void ManyInputs::fail(const std::string& message) {
  ++total_;
  if (failed_++ == 0) first_ = currentTask() + ": " + message;
  // Not a number: the check's margin is infinite (comparisons.h).
  currentLog().largestFailingRatio = std::numeric_limits<double>::infinity();
}

void ManyInputs::report(const std::string& hintText) {
  if (reported_ || failed_ == 0) return;
  reported_ = true;
  ++currentLog().reportedFailures;
  std::string more;
  if (failed_ > 1) {
    more = "\n  (" + std::to_string(failed_ - 1) + " more of the " + std::to_string(total_) + " " +
           what_ + " failed too; this is the first)";
  }
  ADD_FAILURE_AT(file_, line_) << first_ << more << hintText;
}

ComparisonLog comparisonsOf(const ::testing::TestInfo& check) {
  return gLog.check == &check ? gLog : ComparisonLog{&check};
}

double marginOf(const ::testing::TestInfo& check) {
  const ComparisonLog log = comparisonsOf(check);
  const ::testing::TestResult& result = *check.result();
  int failures = 0;
  for (int k = 0; k < result.total_part_count(); ++k) {
    if (result.GetTestPartResult(k).failed()) ++failures;
  }
  if (failures == 0) return 0;
  if (failures > log.reportedFailures) return std::numeric_limits<double>::infinity();
  return log.largestFailingRatio;
}

}  // namespace a6::test
