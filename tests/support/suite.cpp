#include "suite.h"

#include <charconv>
#include <limits>

#include "comparisons.h"

namespace a6::test {

std::string currentTask() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string suite = info != nullptr ? info->test_suite_name() : "";
  static const char* const files[] = {"spring.cpp", "forces.cpp",          "time_stepping.cpp",
                                      "cloth.cpp",  "particle_system.cpp", "joints.cpp"};
  if (suite.size() >= 5 && suite.compare(0, 4, "Task") == 0 && suite[4] >= '1' && suite[4] <= '6') {
    return std::string("Task ") + suite[4] + " (" + files[suite[4] - '1'] + ")";
  }
  return "Task ?";
}

std::string num(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string str(const Vec2& v) { return "(" + num(v.x()) + ", " + num(v.y()) + ")"; }

std::string str(const Particle& p) {
  std::string out = "{x=" + str(p.x) + ", v=" + str(p.v) + ", m=" + num(p.m);
  if (p.pinned) out += ", pinned";
  return out + "}";
}

std::string hint(const std::string& text) { return "\n  hint: " + text; }

namespace {

ComparisonLog gLog;

// The log of the running check, emptied when a new check starts.
ComparisonLog& currentLog() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (gLog.check != info) gLog = ComparisonLog{info};
  return gLog;
}

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

std::string toleranceText(const Tolerance& tol) {
  return "(tolerance " + num(tol.absolute()) + (tol.exact ? ": " : ", ") + num(tol.relative) +
         " of " + num(tol.scale) + ")";
}

::testing::AssertionResult compareVec(const char* what, const Vec2& actual, const Vec2& expected,
                                      const Tolerance& tol) {
  const Vec2 diff = actual - expected;
  const double largest =
      finite(actual) ? diff.cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
  if (recordComparison(largest, tol)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << currentTask() << ": " << what << "\n  expected: " << str(expected)
         << "\n  actual:   " << str(actual) << "\n  " << toleranceText(tol);
}

::testing::AssertionResult compareScalar(const char* what, double actual, double expected,
                                         const Tolerance& tol) {
  const double diff =
      std::isfinite(actual) ? actual - expected : std::numeric_limits<double>::infinity();
  if (recordComparison(std::abs(diff), tol)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << currentTask() << ": " << what << "\n  expected: " << num(expected)
         << "\n  actual:   " << num(actual) << "\n  " << toleranceText(tol);
}

}  // namespace

::testing::AssertionResult vecNear(const char* actualExpr, const char*, const char*,
                                   const Vec2& actual, const Vec2& expected, const Tolerance& tol) {
  ::testing::AssertionResult result = compareVec(actualExpr, actual, expected, tol);
  if (!result) ++currentLog().reportedFailures;
  return result;
}

::testing::AssertionResult scalarNear(const char* actualExpr, const char*, const char*,
                                      double actual, double expected, const Tolerance& tol) {
  ::testing::AssertionResult result = compareScalar(actualExpr, actual, expected, tol);
  if (!result) ++currentLog().reportedFailures;
  return result;
}

bool ManyInputs::record(const ::testing::AssertionResult& result, const std::string& input) {
  ++total_;
  if (result) return true;
  if (failed_++ == 0) {
    first_ = std::string(result.message()) + (input.rfind('\n', 0) == 0 ? "" : "\n  ") + input;
  }
  return false;
}

bool ManyInputs::expectNear(const Vec2& actual, const Vec2& expected, const Tolerance& tol,
                            const std::string& input) {
  return record(compareVec(what_.c_str(), actual, expected, tol), input);
}

bool ManyInputs::expectNear(double actual, double expected, const Tolerance& tol,
                            const std::string& input) {
  return record(compareScalar(what_.c_str(), actual, expected, tol), input);
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
