// The out-of-process StudentCode (see probe_client.h).
#include "probe/probe_client.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

#include "harness/force_channel.h"
#include "harness/wire.h"
#include "sandbox/process.h"

namespace a6::grader {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;
using process::secondsAfter;

namespace {

using harness::Fault;
using harness::Outcome;

Outcome failure(Fault fault, std::string words) {
  Outcome o;
  o.fail(fault, reworded(std::move(words)));
  return o;
}

constexpr int kProbeRequestFd = 3;  // the probe reads requests here
constexpr int kProbeAnswerFd = 4;   // and answers here
// The longest answer accepted, bytes: about twice the longest the solution gives (1.97 MB of
// MessagePack, a scene's states; 3.2 MB as JSON text), so that a6_grade's memory stays bounded
// whatever a probe sends.
constexpr std::size_t kMaxAnswerBytes = std::size_t{4} << 20;
// What a probe may write in its work folder, bytes (a tmpfs of this size, as root).
constexpr std::size_t kWorkDirBytes = std::size_t{16} << 20;
// Answers nest a few levels (an object of arrays of states of vectors); deeper is garbage.
constexpr int kMaxAnswerDepth = 12;
// The size of the document an answer decodes to, in nodes of 16 bytes (what nlohmann::json
// allocates, roughly: a number, true, false or null is one node; a string adds its own object,
// 4; an array adds a vector, 2; a map adds a tree, 4; each key a tree node with its string, 6),
// at most: about twice the most of the solution's answers (1,104,040, a scene's states). One
// byte of MessagePack may be a whole map, so this count, not the bytes, bounds a6_grade's
// memory (at most about 115 MB more: an array of 2 million nils, the costliest found).
constexpr std::size_t kMaxAnswerNodes = std::size_t{1} << 21;

// Checks an answer's nesting and size before it is decoded into a document (whose nodes take
// many times the message's bytes): a pass over the bytes that keeps nothing.
class ShapeCheck final : public json::json_sax_t {
 public:
  bool null() override { return counted(1); }
  bool boolean(bool) override { return counted(1); }
  bool number_integer(number_integer_t) override { return counted(1); }
  bool number_unsigned(number_unsigned_t) override { return counted(1); }
  bool number_float(number_float_t, const string_t&) override { return counted(1); }
  bool string(string_t&) override { return counted(4); }
  bool binary(binary_t&) override { return counted(4); }
  bool start_object(std::size_t) override { return deeper() && counted(4); }
  bool key(string_t&) override { return counted(6); }
  bool end_object() override { return --depth_ >= 0; }
  bool start_array(std::size_t) override { return deeper() && counted(2); }
  bool end_array() override { return --depth_ >= 0; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

  // Why the answer is refused before decoding, or "".
  std::string refusal() const {
    if (tooDeep_)
      return "an answer nested deeper than " + std::to_string(kMaxAnswerDepth) + " levels";
    if (tooLarge_) {
      return "an answer larger than " + std::to_string(kMaxAnswerNodes) +
             " document nodes once decoded";
    }
    return "";
  }

 private:
  bool counted(std::size_t nodes) {
    nodes_ += nodes;
    tooLarge_ = nodes_ > kMaxAnswerNodes;
    return !tooLarge_;
  }
  bool deeper() {
    tooDeep_ = ++depth_ > kMaxAnswerDepth;
    return !tooDeep_;
  }
  int depth_ = 0;
  std::size_t nodes_ = 0;
  bool tooDeep_ = false;
  bool tooLarge_ = false;
};

// Decodes an answer whose nesting and size are within bounds; throws otherwise (wire::Malformed
// for bytes that are not MessagePack).
json decodeAnswerBytes(const std::string& body) {
  ShapeCheck check;
  if (!json::sax_parse(body, &check, json::input_format_t::msgpack)) {
    if (const std::string why = check.refusal(); !why.empty()) throw std::runtime_error(why);
  }
  return wire::fromBytes(body);  // "not MessagePack: ..." for what the check could not read
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

// A request's deadline: the end of its time window (the request's own, or the check's), plus the
// allowance for the forces the grader answered within that window (forceWaitAllowance), counted
// once from the window's start; never past `hardEnd` (the end of the time all checks together
// may take).
struct Deadline {
  Clock::time_point base;
  double limit = 0;                                   // s
  const std::atomic<std::size_t>* answers = nullptr;  // the grader's force answers so far
  std::size_t answersAtStart = 0;
  Clock::time_point hardEnd = Clock::time_point::max();

  Clock::time_point at() const {
    return std::min(secondsAfter(base, forceWaitAllowance(*answers - answersAtStart, limit)),
                    hardEnd);
  }
};

enum class Io { Ok, Closed, TimedOut };

// Writes all of `bytes` to a non-blocking pipe before `deadline`. SIGPIPE is blocked in this
// thread meanwhile (a probe that died must not kill the grader) and a pending one is consumed.
Io sendAll(int fd, const std::string& bytes, const Deadline& deadline) {
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
      if (Clock::now() >= deadline.at()) {
        result = Io::TimedOut;
        break;
      }
      pollfd pfd{fd, POLLOUT, 0};
      poll(&pfd, 1, msUntil(deadline.at()));
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
Io receiveExactly(int fd, std::size_t n, std::string& out, const Deadline& deadline) {
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
    if (Clock::now() >= deadline.at()) return Io::TimedOut;
    pollfd pfd{fd, POLLIN, 0};
    poll(&pfd, 1, msUntil(deadline.at()));
  }
  return Io::Ok;
}

// A close-on-exec pipe whose ends close when it goes, unless taken.
struct OwnedPipe {
  int fd[2] = {-1, -1};
  OwnedPipe() = default;
  OwnedPipe(const OwnedPipe&) = delete;
  OwnedPipe& operator=(const OwnedPipe&) = delete;
  ~OwnedPipe() {
    close(0);
    close(1);
  }
  bool open() { return pipe2(fd, O_CLOEXEC) == 0; }
  void close(int end) {
    if (fd[end] >= 0) ::close(fd[end]);
    fd[end] = -1;
  }
  int take(int end) { return std::exchange(fd[end], -1); }
};

// The reference forces for one probe (harness/force_channel.h): two pipes the probe asks on (its
// fds 5 and 6) and a thread of the grader that answers them; stopped and joined when destroyed,
// whatever the probe does (a stop pipe wakes the thread).
class ForceServer {
 public:
  ~ForceServer() {
    stop_.close(1);  // the thread sees the stop pipe end; the other ends close after the join
    if (thread_.joinable()) thread_.join();
  }

  /// The pipes; false (with `error`) when they cannot be made.
  bool open(std::string& error) {
    if (requests_.open() && answers_.open() && stop_.open()) return true;
    error = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  /// The probe's ends, as SandboxSpec::mapFds.
  std::vector<std::pair<int, int>> probeFds() const {
    return {{requests_.fd[1], harness::forcechannel::kRequestFd},
            {answers_.fd[0], harness::forcechannel::kAnswerFd}};
  }
  /// Once the probe has its ends: closes ours of them and starts answering with `models`.
  /// False when no thread could be started.
  bool start(const ForceModel& models, std::atomic<std::size_t>* answers) {
    requests_.close(1);
    answers_.close(0);
    try {
      thread_ = std::thread([this, models, answers] {
        harness::forcechannel::serve(requests_.fd[0], answers_.fd[1], stop_.fd[0], models, answers);
        requests_.close(0);  // a probe still waiting for an answer reads the end, not nothing
        answers_.close(1);
      });
    } catch (const std::system_error&) {
      return false;
    }
    return true;
  }

 private:
  OwnedPipe requests_, answers_, stop_;
  std::thread thread_;
};

}  // namespace

struct ProbeClient::Impl {
  fs::path probe, workRoot;
  Limits limits;
  double timeout = 10;  // a request's own limit, when no check window is set
  // The running check's window (startCheck): every request of the check ends by its end.
  bool inCheck = false;
  Clock::time_point checkStart, checkHardEnd;
  double checkLimit = 0;
  std::size_t answersAtCheckStart = 0;
  std::vector<fs::path> hide, reveal;
  int maxStarts = 50;
  uid_t uid = 65534;
  gid_t gid = 65534;

  ForceModel forceModels;  // answered on the probe's fds 5 and 6 when set (serveForces)
  std::atomic<std::size_t> forceAnswers{0};  // over all the probes started

  std::unique_ptr<SandboxedProcess> process;
  std::unique_ptr<ForceServer> forceServer;  // of the running probe, when forceModels is set
  int toProbe = -1, fromProbe = -1;
  int starts = 0;
  ProbeIncidents incidents;
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
    forceServer.reset();
    keepOutput(exit.output,
               "[a6: probe " + std::to_string(starts) + " " + why + ": " + exit.describe() + "]");
    return exit;
  }

  // The sandbox of the next probe: it reads requests on `requestFd` and answers on `answerFd`.
  SandboxSpec probeSpec(int requestFd, int answerFd) const {
    SandboxSpec spec;
    spec.argv = {fs::absolute(probe).string()};
    spec.workDir = workRoot / ("probe-" + std::to_string(starts));
    spec.removeWorkDir = true;
    spec.workDirTmpfsBytes = kWorkDirBytes;
    spec.limits = limits;
    spec.mapFds = {{requestFd, kProbeRequestFd}, {answerFd, kProbeAnswerFd}};
    spec.hide = hide;
    spec.reveal = reveal;
    spec.uid = uid;
    spec.gid = gid;
    return spec;
  }

  // When the probe asks for reference forces: their server, its pipes passed in `spec`.
  // Returns an error, or "".
  std::string openForceServer(SandboxSpec& spec) {
    if (!forceModels.spring && !forceModels.external) return "";
    forceServer = std::make_unique<ForceServer>();
    if (std::string error; !forceServer->open(error)) {
      forceServer.reset();
      return error;
    }
    for (const auto& fds : forceServer->probeFds()) spec.mapFds.push_back(fds);
    return "";
  }

  // Starts the probe of `spec` and the force server's thread; on success keeps our ends of the
  // request and answer pipes.
  Outcome launch(const SandboxSpec& spec, OwnedPipe& request, OwnedPipe& answer) {
    process = std::make_unique<SandboxedProcess>(spec);
    request.close(0);
    answer.close(1);
    const bool served = !forceServer || forceServer->start(forceModels, &forceAnswers);
    for (const std::string& note : process->notes()) {
      if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(note);
    }
    if (!process->error().empty() || !served) {
      const std::string error =
          served ? process->error() : "no thread could be started to answer its forces";
      process.reset();
      forceServer.reset();
      ++incidents.startFailures;
      return failure(Fault::StartFailed, "could not start the probe: " + error);
    }
    toProbe = request.take(1);
    fromProbe = answer.take(0);
    for (int fd : {toProbe, fromProbe}) fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    return {};
  }

  // Starts a probe when none runs; returns why not (a fault), or no fault.
  Outcome ensureStarted() {
    if (process) return {};
    if (starts >= maxStarts) {
      return failure(Fault::StartsUsedUp,
                     "the probe was started " + std::to_string(starts) +
                         " times (it crashed or ran out of time each time); the remaining "
                         "requests were not run");
    }
    ++starts;
    std::error_code ec;
    fs::create_directories(workRoot, ec);
    OwnedPipe request, answer;
    if (!request.open() || !answer.open()) {
      return failure(Fault::StartFailed, std::string("pipe: ") + std::strerror(errno));
    }
    SandboxSpec spec = probeSpec(request.fd[0], answer.fd[1]);
    if (std::string error = openForceServer(spec); !error.empty()) {
      return failure(Fault::StartFailed, error);
    }
    return launch(spec, request, answer);
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
  Outcome crashReport() {
    // Give a dying probe time to finish dying, so its signal is what we report: a dying probe
    // returns at once, and only one that closed its pipe and lives on waits the whole 2 s. On a
    // loaded machine an exit can take longer than 300 ms to be seen (CI beside 4 CPU hogs: a
    // probe that had exited was reported as having closed its pipe).
    const bool alive = aliveAfter(std::chrono::seconds(2));
    const Exit exit = shutdown(alive ? "closed its answer pipe" : "crashed");
    // SIGKILL is sent by the grader only at a time limit (not this path), and by the CPU limit
    // once it is used up: otherwise the machine ended it.
    const bool killed = !alive && killedByTheMachine(exit, limits);
    if (!killed) ++incidents.crashes;
    std::string text = alive ? "the probe closed its answer pipe without answering, so it was "
                               "stopped"
                             : "the probe crashed: " + exit.describe();
    if (!alive && exit.kind == Exit::Kind::Signaled && exit.code == SIGXCPU) {
      text += " (the limit is " + secondsText(limits.cpuSeconds) + " s of CPU time per probe)";
    }
    const std::string last = tail(exit.output, 10, 2000);
    if (!last.empty()) text += "\nthe last lines it printed:\n" + last;
    if (killed) {
      return failure(Fault::Killed,
                     "your code was killed by SIGKILL, which neither the grader nor its limits "
                     "sent (the machine ran out of memory, another program, or the code itself)" +
                         (last.empty() ? std::string() : "\nthe last lines it printed:\n" + last));
    }
    return failure(Fault::Crashed, text);
  }

  // One request's bytes out and one answer's text back, within `deadline`. Returns why not, or
  // no fault (the probe is stopped on a time-out, a crash or garbage).
  Outcome exchange(const std::string& bytes, const Deadline& deadline, std::string& body) {
    auto timedOut = [&] {
      shutdown("ran out of time");
      ++incidents.timeouts;
      if (inCheck && deadline.at() >= deadline.hardEnd) {
        return failure(Fault::TimedOut,
                       "ran out of time: the time all checks together may take was used up while "
                       "this request ran, so it was stopped");
      }
      return failure(
          Fault::TimedOut,
          "ran out of time: " + secondsText(inCheck ? checkLimit : timeout) +
              (inCheck ? " s, this check's time limit (is there an endless loop, or a "
                         "loop that runs far too often?), so your code was stopped"
                       : " s, the time limit of this request, so your code was stopped"));
    };
    Io io = sendAll(toProbe, bytes, deadline);
    if (io == Io::TimedOut) return timedOut();
    if (io == Io::Closed) return crashReport();
    std::string header;
    io = receiveExactly(fromProbe, 4, header, deadline);
    if (io == Io::Ok) {
      const std::uint32_t n =
          wire::frameLength(reinterpret_cast<const unsigned char*>(header.data()));
      if (n > kMaxAnswerBytes) {
        shutdown("sent garbage");
        return failure(Fault::Garbage, "garbage from the probe: an answer of " + std::to_string(n) +
                                           " bytes announced, over the limit of " +
                                           std::to_string(kMaxAnswerBytes));
      }
      body.reserve(std::min<std::size_t>(n, 1u << 20));
      io = receiveExactly(fromProbe, n, body, deadline);
    }
    if (io == Io::TimedOut) return timedOut();
    if (io == Io::Closed) return crashReport();
    return {};
  }

  // A probe that ended just after it started: its crash report, once it is dead (300 ms at
  // most); no fault while it still runs.
  Outcome endedAtStart() {
    return aliveAfter(std::chrono::milliseconds(300)) ? Outcome{} : crashReport();
  }

  // Whether the probe still lives after `grace`: returns as soon as it is seen dead.
  bool aliveAfter(Clock::duration grace) {
    const auto until = Clock::now() + grace;
    bool alive = process->alive();
    while (alive && Clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      alive = process->alive();
    }
    return alive;
  }

  // A probe just started: it must answer a request that runs no student code, and then show,
  // in /proc, its seccomp filter on top of the sandbox's and a single thread
  // (grader/probe/filter.h). Returns why it cannot serve, or no fault.
  Outcome verifyStarted(const Deadline& deadline) {
    harness::SceneRequest ping;
    ping.frames = {-1};
    std::string body;
    if (Outcome failed = exchange(wire::frame(wire::encodeRequest(ping)), deadline, body);
        !failed.ok()) {
      return failed;
    }
    const std::optional<process::Info> info = process::describe(process->programPid());
    const bool filtered =
        info && info->seccompMode == 2 && (info->seccompFilters < 0 || info->seccompFilters >= 2);
    if (info && filtered && info->threads == 1) return {};
    // Gone between its answer and this look (a crash, or a kill from outside): how it ended
    // says whose it is (crashReport), not a bad start.
    if (!info || info->state == 'Z') {
      if (Outcome ended = endedAtStart(); !ended.ok()) return ended;
    }
    const std::string what =
        !info       ? "it could not be inspected"
        : !filtered ? "it runs without its seccomp filter"
                    : "it runs " + std::to_string(info->threads) + " threads instead of one";
    shutdown("failed its start-up check");
    ++incidents.startFailures;
    return failure(Fault::BadStart,
                   "the probe failed the grader's start-up check: " + what +
                       " (code that runs before main, such as a static initializer, must not "
                       "start threads or change how the program starts)");
  }

  // The running check's window, or this request's own.
  Deadline requestDeadline() const {
    if (inCheck) {
      return {secondsAfter(checkStart, checkLimit), checkLimit, &forceAnswers, answersAtCheckStart,
              checkHardEnd};
    }
    return {secondsAfter(Clock::now(), timeout), timeout, &forceAnswers, forceAnswers.load()};
  }

  harness::Answer call(const harness::Request& request) {
    std::lock_guard<std::mutex> lock(mutex);
    std::string bytes;
    try {
      bytes = wire::frame(wire::encodeRequest(request));
    } catch (const std::exception& e) {
      return harness::failedAnswer(
          request, failure(Fault::GraderError,
                           std::string("the grader could not encode the request: ") + e.what()));
    }
    checkQuiet();
    const Deadline deadline = requestDeadline();
    Outcome why;
    if (!process) {
      why = ensureStarted();
      if (why.ok()) why = verifyStarted(deadline);
    }
    std::string body;
    if (why.ok()) why = exchange(bytes, deadline, body);
    if (!why.ok()) return harness::failedAnswer(request, std::move(why));
    try {
      harness::Answer answer = wire::decodeAnswer(request.index(), decodeAnswerBytes(body));
      Outcome& outcome = harness::outcomeOf(answer);
      if (!outcome.error.empty()) outcome.error = reworded(std::move(outcome.error));
      return answer;
    } catch (const std::exception& e) {
      shutdown("sent garbage");
      return harness::failedAnswer(
          request, failure(Fault::Garbage, std::string("garbage from the probe: ") + e.what()));
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
  impl_->inCheck = false;
}

void ProbeClient::startCheck(double limit, std::chrono::steady_clock::time_point hardEnd) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->inCheck = true;
  impl_->checkStart = Clock::now();
  impl_->checkLimit = limit;
  impl_->checkHardEnd = hardEnd;
  impl_->answersAtCheckStart = impl_->forceAnswers.load();
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

std::size_t ProbeClient::forceAnswers() const { return impl_->forceAnswers.load(); }

void ProbeClient::serveForces(ForceModel models) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->forceModels = std::move(models);
}

void ProbeClient::setMaxStarts(int starts) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->maxStarts = starts;
}

harness::Answer ProbeClient::respond(const harness::Request& request) {
  return impl_->call(request);
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

ProbeIncidents ProbeClient::incidents() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->incidents;
}

std::vector<std::string> ProbeClient::notes() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->notes;
}

void ProbeClient::stop() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->shutdown();
}

std::string reworded(std::string words) {
  static const char* const setting = std::getenv("A6_REWORD_MESSAGES");
  static const bool on = setting != nullptr && std::string(setting) == "1";
  return on ? "[reworded] " + words : words;
}

}  // namespace a6::grader
