// The golden tests' main for the in-process build: the student's six files are linked into this
// binary.
#include <memory>

#include "golden_suite.h"

int main(int argc, char** argv) {
  const std::unique_ptr<a6::harness::StudentCode> student = a6::harness::makeInProcess();
  return a6::test::runGoldenTests(argc, argv, *student);
}
