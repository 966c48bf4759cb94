// The golden tests' main for the in-process build: the student's seven files are linked into this
// binary.
#include <memory>

#include "golden_suite.h"

namespace {
std::unique_ptr<a6::harness::StudentCode> gStudent;
}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gStudent; }
}  // namespace a6::test

int main(int argc, char** argv) {
  gStudent = a6::harness::makeInProcess();
  return a6::test::runGoldenTests(argc, argv);
}
