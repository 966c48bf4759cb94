#include "suite.h"

#include <iomanip>

namespace a6::test {

std::string currentTask() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string suite = info != nullptr ? info->test_suite_name() : "";
  static const char* const files[] = {"spring.cpp", "forces.cpp", "time_stepping.cpp",
                                      "cloth.cpp", "particle_system.cpp", "joints.cpp"};
  if (suite.size() >= 5 && suite.compare(0, 4, "Task") == 0 && suite[4] >= '1' && suite[4] <= '6') {
    return std::string("Task ") + suite[4] + " (" + files[suite[4] - '1'] + ")";
  }
  return "Task ?";
}

std::string str(const Vec2& v) {
  std::ostringstream out;
  out << std::setprecision(10) << "(" << v.x() << ", " << v.y() << ")";
  return out.str();
}

std::string str(const Particle& p) {
  std::ostringstream out;
  out << std::setprecision(10) << "{x=" << str(p.x) << ", v=" << str(p.v) << ", m=" << p.m;
  if (p.pinned) out << ", pinned";
  out << "}";
  return out.str();
}

std::string hint(const std::string& text) { return "\n  hint: " + text; }

::testing::AssertionResult vecNear(const char* actualExpr, const char*, const char*,
                                   const Vec2& actual, const Vec2& expected, double tol) {
  const Vec2 diff = actual - expected;
  if (finite(actual) && std::abs(diff.x()) <= tol && std::abs(diff.y()) <= tol) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << currentTask() << ": " << actualExpr << "\n  expected: " << str(expected)
         << "\n  actual:   " << str(actual) << "\n  (tolerance " << tol << " per component)\n  ";
}

::testing::AssertionResult scalarNear(const char* actualExpr, const char*, const char*,
                                      double actual, double expected, double tol) {
  if (std::isfinite(actual) && std::abs(actual - expected) <= tol) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << std::setprecision(10) << currentTask() << ": " << actualExpr
         << "\n  expected: " << expected << "\n  actual:   " << actual << "\n  (tolerance "
         << tol << ")\n  ";
}

}  // namespace a6::test
