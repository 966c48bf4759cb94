// The probe: the seven student files, the framework and this main, linked into one executable
// that the grader starts in its sandbox. It reads requests on fd 3 and answers on fd 4, each a
// length-prefixed MessagePack message (framework/harness/wire.h), until fd 3 ends.
//
// Design note: what protects the protocol.
// Requests and answers travel only on fds 3 and 4; the student's stdout and stderr (fds 1, 2)
// are a pipe the grader drains and caps, and stdin is /dev/null. Whatever the student prints
// can never be read as an answer. Student code that writes to fd 4 itself only produces an
// answer the grader cannot decode, which fails that request ("garbage from the probe").
//
// Design note: the seccomp filter (grader/probe/filter.h) is installed from the executable's
// .preinit_array, before any constructor runs: the student's static initialisers already run
// under it, on every thread. It is built and installed without libc or libseccomp, so a
// submission cannot define a function that replaces the installation.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

#include "a6/a6.h"
#include "filter.h"
#include "harness/force_channel.h"
#include "harness/student_code.h"
#include "harness/wire.h"
#include "scenes/scene.h"

namespace {
#ifdef A6_REMOTE_FORCES
// Only in the second probe (a6_probe_main_models), which serves the requests that ask for the
// reference forces: its force model asks the grader, which holds the models, on fds 5 and 6
// (harness/force_channel.h). Without those fds (a release's grader, which has no models to
// give) the student's own forces are used. Neither probe holds a reference model.
a6::ForceModel forceModels() {
  return a6::harness::forcechannel::available() ? a6::harness::forcechannel::remoteModel()
                                                : a6::ForceModel{};
}
#else
a6::ForceModel forceModels() { return {}; }
#endif

constexpr int kRequestFd = 3;
constexpr int kAnswerFd = 4;

}  // namespace

int main() {
  // The grader's pipes must be there; anyone else starting the probe gets told what it is.
  struct stat st;
  if (fstat(kRequestFd, &st) != 0 || fstat(kAnswerFd, &st) != 0) {
    std::fprintf(stderr,
                 "a6 probe: fds 3 and 4 are not open. This program answers the grader's "
                 "requests and is started by it (a6_grade); it is not meant to be run by hand.\n");
    return 2;
  }
  // Output reaches the grader line by line, so a crash report shows the last lines printed.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  // A pipe the grader closed (fd 4, or the force pipes 5 and 6) fails a write; it ends nothing.
  std::signal(SIGPIPE, SIG_IGN);

  // The filter is on already (filter.h); the harness and the scene list.
  std::unique_ptr<a6::harness::StudentCode> code = a6::harness::makeInProcess(forceModels());
  (void)a6::sceneNames();

  for (;;) {
    std::string body;
    try {
      if (!a6::wire::readFrame(kRequestFd, body)) return 0;  // the grader is done
    } catch (const std::exception& e) {
      std::fprintf(stderr, "a6 probe: bad request stream: %s\n", e.what());
      return 4;
    }
    std::string answer;
    try {
      nlohmann::json reply;
      try {
        reply = a6::wire::serve(*code, a6::wire::fromBytes(body));
      } catch (const a6::wire::Malformed& e) {
        reply = {
            {"error", std::string("the grader sent a request the probe cannot read: ") + e.what()}};
      }
      body.clear();
      body.shrink_to_fit();
      answer = a6::wire::frame(reply);
    } catch (const std::exception& e) {
      // Too large to send, or out of memory while encoding: say so in a small answer.
      answer = a6::wire::frame(
          {{"error", std::string("the probe could not send its result: ") + e.what()}});
    }
    std::fflush(stdout);
    std::fflush(stderr);
    if (!a6::wire::writeAll(kAnswerFd, answer)) return 5;
  }
}
