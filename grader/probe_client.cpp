// The out-of-process StudentCode (see probe_client.h).
#include "probe_client.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

#include "harness/wire.h"

namespace a6::grader {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

namespace {

constexpr int kProbeRequestFd = 3;  // the probe reads requests here
constexpr int kProbeAnswerFd = 4;   // and answers here

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

// The last `lines` lines of `text`, at most `bytes` bytes.
std::string tail(const std::string& text, int lines, std::size_t bytes) {
  std::size_t end = text.find_last_not_of("\r\n");
  if (end == std::string::npos) return "";
  ++end;
  std::size_t begin = end;
  int seen = 0;
  while (begin > 0) {
    if (text[begin - 1] == '\n' && ++seen == lines) break;
    --begin;
  }
  if (end - begin > bytes) begin = end - bytes;
  return text.substr(begin, end - begin);
}

int msUntil(Clock::time_point deadline) {
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return static_cast<int>(std::clamp<long long>(ms + 1, 0, 1000));
}

enum class Io { Ok, Closed, TimedOut, Garbage };

// Writes all of `bytes` to a non-blocking pipe before `deadline`. SIGPIPE is blocked in this
// thread meanwhile (a probe that died must not kill the grader) and a pending one is consumed.
Io sendAll(int fd, const std::string& bytes, Clock::time_point deadline) {
  sigset_t pipeSet, old;
  sigemptyset(&pipeSet);
  sigaddset(&pipeSet, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipeSet, &old);
  Io result = Io::Ok;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (Clock::now() >= deadline) {
        result = Io::TimedOut;
        break;
      }
      pollfd pfd{fd, POLLOUT, 0};
      poll(&pfd, 1, msUntil(deadline));
      continue;
    }
    result = Io::Closed;  // EPIPE: the probe is gone
    break;
  }
  if (result == Io::Closed) {
    const timespec zero{0, 0};
    while (sigtimedwait(&pipeSet, nullptr, &zero) > 0) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return result;
}

// Appends exactly `n` bytes from a non-blocking pipe to `out` before `deadline`.
Io receiveExactly(int fd, std::size_t n, std::string& out, Clock::time_point deadline) {
  char buffer[1 << 16];
  std::size_t got = 0;
  while (got < n) {
    const ssize_t k = ::read(fd, buffer, std::min(sizeof buffer, n - got));
    if (k > 0) {
      out.append(buffer, static_cast<std::size_t>(k));
      got += static_cast<std::size_t>(k);
      continue;
    }
    if (k == 0) return Io::Closed;
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return Io::Closed;
    if (Clock::now() >= deadline) return Io::TimedOut;
    pollfd pfd{fd, POLLIN, 0};
    poll(&pfd, 1, msUntil(deadline));
  }
  return Io::Ok;
}

}  // namespace

struct ProbeClient::Impl {
  fs::path probe, workRoot;
  Limits limits;
  double timeout = 10;
  std::vector<fs::path> hide, reveal;
  int maxStarts = 50;
  uid_t uid = 65534;
  gid_t gid = 65534;

  std::unique_ptr<SandboxedProcess> process;
  int toProbe = -1, fromProbe = -1;
  int starts = 0;
  std::string pastOutput;
  std::vector<std::string> notes;
  mutable std::mutex mutex;

  ~Impl() { shutdown(); }

  void closePipes() {
    if (toProbe >= 0) ::close(toProbe);
    if (fromProbe >= 0) ::close(fromProbe);
    toProbe = fromProbe = -1;
  }

  // Keeps what a stopped probe printed, within the cap, and a marker line saying how it ended.
  void keepOutput(const std::string& text, const std::string& marker) {
    const std::size_t room =
        limits.outputBytes > pastOutput.size() ? limits.outputBytes - pastOutput.size() : 0;
    pastOutput += text.substr(0, room);
    if (!pastOutput.empty() && pastOutput.back() != '\n') pastOutput += '\n';
    pastOutput += marker + '\n';
  }

  // Stops the probe (if any); returns how it ended.
  Exit shutdown(const std::string& why = "stopped by the grader") {
    Exit exit;
    if (!process) return exit;
    closePipes();
    exit = process->stop();
    process.reset();
    keepOutput(exit.output,
               "[a6: probe " + std::to_string(starts) + " " + why + ": " + exit.describe() + "]");
    return exit;
  }

  // Starts a probe when none runs; returns an error, or "".
  std::string ensureStarted() {
    if (process) return "";
    if (starts >= maxStarts) {
      return "the probe was started " + std::to_string(starts) +
             " times (it crashed or ran out of time each time); the remaining requests were not "
             "run";
    }
    ++starts;
    std::error_code ec;
    fs::create_directories(workRoot, ec);
    int request[2], answer[2];
    if (pipe2(request, O_CLOEXEC) != 0) return std::string("pipe: ") + std::strerror(errno);
    if (pipe2(answer, O_CLOEXEC) != 0) {
      ::close(request[0]);
      ::close(request[1]);
      return std::string("pipe: ") + std::strerror(errno);
    }
    SandboxSpec spec;
    spec.argv = {fs::absolute(probe).string()};
    spec.workDir = workRoot / ("probe-" + std::to_string(starts));
    spec.removeWorkDir = true;
    spec.limits = limits;
    spec.mapFds = {{request[0], kProbeRequestFd}, {answer[1], kProbeAnswerFd}};
    spec.hide = hide;
    spec.reveal = reveal;
    spec.uid = uid;
    spec.gid = gid;
    process = std::make_unique<SandboxedProcess>(spec);
    ::close(request[0]);
    ::close(answer[1]);
    for (const std::string& note : process->notes()) {
      if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(note);
    }
    if (!process->error().empty()) {
      const std::string error = process->error();
      ::close(request[1]);
      ::close(answer[0]);
      process.reset();
      return "could not start the probe: " + error;
    }
    toProbe = request[1];
    fromProbe = answer[0];
    fcntl(toProbe, F_SETFL, fcntl(toProbe, F_GETFL) | O_NONBLOCK);
    fcntl(fromProbe, F_SETFL, fcntl(fromProbe, F_GETFL) | O_NONBLOCK);
    return "";
  }

  // The probe's answer pipe must be silent between requests; anything there means it wrote
  // on its own (or died): start afresh.
  void checkQuiet() {
    if (!process) return;
    pollfd pfd{fromProbe, POLLIN, 0};
    if (poll(&pfd, 1, 0) <= 0) return;
    shutdown((pfd.revents & POLLIN) != 0 ? "wrote to its answer pipe between requests"
                                         : "ended between requests");
  }

  // Why the probe stopped answering: it died (how, and its last words), or it closed fd 4.
  std::string crashReport() {
    // Give a dying probe a moment to finish dying, so its signal is what we report.
    const auto until = Clock::now() + std::chrono::milliseconds(300);
    bool alive = process->alive();
    while (alive && Clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      alive = process->alive();
    }
    const Exit exit = shutdown(alive ? "closed its answer pipe" : "crashed");
    std::string text = alive ? "the probe closed its answer pipe without answering, so it was "
                               "stopped"
                             : "the probe crashed: " + exit.describe();
    if (!alive && exit.kind == Exit::Kind::Signaled && exit.code == SIGXCPU) {
      text += " (the limit is " + seconds(limits.cpuSeconds) + " s of CPU time per probe)";
    }
    const std::string last = tail(exit.output, 10, 2000);
    if (!last.empty()) text += "\nthe last lines it printed:\n" + last;
    return text;
  }

  template <typename Result>
  Result call(const std::function<json()>& encode, Result (*decode)(const json&)) {
    std::lock_guard<std::mutex> lock(mutex);
    Result failed;
    std::string bytes;
    try {
      bytes = wire::frame(encode());
    } catch (const std::exception& e) {
      failed.error = std::string("the grader could not encode the request: ") + e.what();
      return failed;
    }
    checkQuiet();
    if (std::string error = ensureStarted(); !error.empty()) {
      failed.error = error;
      return failed;
    }
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(timeout));
    auto timedOut = [&] {
      shutdown("ran out of time");
      failed.error = "your code took longer than " + seconds(timeout) +
                     " s on this request (the time limit), so it was stopped";
      return failed;
    };
    auto garbage = [&](const std::string& what) {
      shutdown("sent garbage");
      failed.error = "garbage from the probe: " + what;
      return failed;
    };

    Io io = sendAll(toProbe, bytes, deadline);
    if (io == Io::TimedOut) return timedOut();
    if (io == Io::Closed) {
      failed.error = crashReport();
      return failed;
    }
    std::string header, body;
    io = receiveExactly(fromProbe, 4, header, deadline);
    if (io == Io::Ok) {
      const std::uint32_t n =
          wire::frameLength(reinterpret_cast<const unsigned char*>(header.data()));
      if (n > wire::kMaxFrameBytes) {
        return garbage("an answer of " + std::to_string(n) +
                       " bytes announced, over the limit of " +
                       std::to_string(wire::kMaxFrameBytes));
      }
      body.reserve(std::min<std::size_t>(n, 1u << 20));
      io = receiveExactly(fromProbe, n, body, deadline);
    }
    if (io == Io::TimedOut) return timedOut();
    if (io == Io::Closed) {
      failed.error = crashReport();
      return failed;
    }
    try {
      return decode(wire::parse(body));
    } catch (const std::exception& e) {
      return garbage(e.what());
    }
  }
};

ProbeClient::ProbeClient(fs::path probe, fs::path workRoot, Limits limits)
    : impl_(std::make_unique<Impl>()) {
  impl_->probe = std::move(probe);
  impl_->workRoot = std::move(workRoot);
  impl_->limits = limits;
  impl_->timeout = limits.wallSeconds;
}

ProbeClient::~ProbeClient() = default;

void ProbeClient::setRequestTimeout(double seconds) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  if (seconds > 0) impl_->timeout = seconds;
}

void ProbeClient::setHidden(std::vector<fs::path> hide, std::vector<fs::path> reveal) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->hide = std::move(hide);
  impl_->reveal = std::move(reveal);
}

void ProbeClient::setUser(uid_t uid, gid_t gid) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->uid = uid;
  impl_->gid = gid;
}

void ProbeClient::setMaxStarts(int starts) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->maxStarts = starts;
}

harness::SpringForceResult ProbeClient::springForce(const harness::SpringForceRequest& r) {
  return impl_->call<harness::SpringForceResult>([&] { return wire::encodeSpringForce(r); },
                                                 wire::decodeSpringForce);
}
harness::ForcesResult ProbeClient::forces(const harness::ForcesRequest& r) {
  return impl_->call<harness::ForcesResult>([&] { return wire::encodeForces(r); },
                                            wire::decodeForces);
}
harness::SimulateResult ProbeClient::simulate(const harness::SimulateRequest& r) {
  return impl_->call<harness::SimulateResult>([&] { return wire::encodeSimulate(r); },
                                              wire::decodeSimulate);
}
harness::ClothResult ProbeClient::buildCloth(const ClothSpec& s) {
  return impl_->call<harness::ClothResult>([&] { return wire::encodeBuildCloth(s); },
                                           wire::decodeBuildCloth);
}
harness::ParticlesResult ProbeClient::emit(const harness::EmitRequest& r) {
  return impl_->call<harness::ParticlesResult>([&] { return wire::encodeEmit(r); },
                                               wire::decodeParticles);
}
harness::ParticlesResult ProbeClient::runParticles(const harness::ParticleRunRequest& r) {
  return impl_->call<harness::ParticlesResult>([&] { return wire::encodeRunParticles(r); },
                                               wire::decodeParticles);
}
harness::Box2DResult ProbeClient::runBox2D(const harness::Box2DRequest& r) {
  return impl_->call<harness::Box2DResult>([&] { return wire::encodeRunBox2D(r); },
                                           wire::decodeRunBox2D);
}
harness::SceneResult ProbeClient::runScene(const harness::SceneRequest& r) {
  return impl_->call<harness::SceneResult>([&] { return wire::encodeRunScene(r); },
                                           wire::decodeRunScene);
}

std::string ProbeClient::output() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  std::string text = impl_->pastOutput;
  if (impl_->process) {
    const std::size_t cap = impl_->limits.outputBytes;
    text += impl_->process->output().substr(0, cap > text.size() ? cap - text.size() : 0);
  }
  return text;
}

int ProbeClient::starts() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->starts;
}

std::vector<std::string> ProbeClient::notes() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->notes;
}

void ProbeClient::stop() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->shutdown();
}

}  // namespace a6::grader
