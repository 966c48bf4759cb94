// The physics suite run as the grader runs it: in this process, with a6::test::student() a
// ProbeClient that sends every request to a sandboxed probe (grader/probe/probe_client.h). No
// student code is linked into this binary.
//   a6_suite_via_probe --probe PATH [GoogleTest flags]     (or A6_PROBE=PATH in the environment)
// At the end it prints the per-task summary (tests/support/summary.h) and how many probes it
// started, so tests/check_run.cmake can check it like the in-process binaries.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "probe/probe_client.h"
#include "sandbox_user.h"
#include "suite.h"
#include "summary.h"
#include "watched_student.h"

namespace {
#include A6_FORCE_MODELS  // the reference forces the probe asks for (harness/force_channel.h)
std::unique_ptr<a6::grader::ProbeClient> gProbe;
std::unique_ptr<a6::test::WatchedStudent> gWatched;
}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gWatched; }
}  // namespace a6::test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  std::string probe;
  if (const char* env = std::getenv("A6_PROBE")) probe = env;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--probe") == 0 && k + 1 < argc) probe = argv[++k];
  }
  if (probe.empty()) {
    std::fprintf(stderr, "usage: %s --probe PATH [GoogleTest flags] (or A6_PROBE=PATH)\n", argv[0]);
    return 2;
  }
  char work[] = "/tmp/a6-suite-via-probe-XXXXXX";
  if (mkdtemp(work) == nullptr) {
    std::perror("mkdtemp");
    return 2;
  }
  chmod(work, 0755);  // the probe may run as another user
  gProbe = std::make_unique<a6::grader::ProbeClient>(
      std::filesystem::absolute(probe), std::filesystem::path(work) / "run", a6::grader::Limits{});
  gProbe->setUser(a6::test::sandboxUid(), 65534);  // ours alone: other tests run beside us
  gProbe->serveForces(referenceForceModel());
  gWatched = std::make_unique<a6::test::WatchedStudent>(*gProbe);
  ::testing::UnitTest::GetInstance()->listeners().Append(new a6::test::TaskSummary);
  const int status = RUN_ALL_TESTS();
  std::printf("A6-PROBE starts=%d\n", gProbe->starts());
  for (const std::string& note : gProbe->notes()) std::printf("A6-PROBE note: %s\n", note.c_str());
  gWatched.reset();
  gProbe.reset();
  std::error_code ec;
  std::filesystem::remove_all(work, ec);
  return status;
}
