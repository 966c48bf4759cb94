// The reference forces over a pipe (see force_channel.h).
#include "harness/force_channel.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "harness/wire.h"

namespace a6::harness::forcechannel {
namespace {

enum Kind { kSpring = 1, kExternal = 2, kSprings = 3, kExternals = 4 };
constexpr std::size_t kSpringWidth = 11;   // x1, v1, x2, v2, l0, ks, kd
constexpr std::size_t kParticleWidth = 6;  // x, v, m, T
constexpr std::size_t kEnvHead = 8;        // g, T_air, b, k_d, k_r, planes, circles

Vec2 notAvailable() { return Vec2::Constant(std::numeric_limits<double>::quiet_NaN()); }

// ---- encoding (the probe's side) ----------------------------------------------------------------

void put(std::vector<double>& out, const Vec2& v) {
  out.push_back(v.x());
  out.push_back(v.y());
}

void putSpring(std::vector<double>& out, const Spring& s) {
  put(out, s.p1->x);
  put(out, s.p1->v);
  put(out, s.p2->x);
  put(out, s.p2->v);
  out.insert(out.end(), {s.restLength, s.ks, s.kd});
}

void putParticle(std::vector<double>& out, const Particle& p) {
  put(out, p.x);
  put(out, p.v);
  out.insert(out.end(), {p.m, p.temperature});
}

void putEnvironment(std::vector<double>& out, const Environment& env) {
  put(out, env.gravity);
  out.insert(out.end(),
             {env.airTemperature, env.buoyancy, env.drag, env.repulsion,
              static_cast<double>(env.planes.size()), static_cast<double>(env.circles.size())});
  for (const HalfPlane& plane : env.planes) {
    put(out, plane.normal);
    out.push_back(plane.offset);
  }
  for (const CircleObstacle& circle : env.circles) {
    put(out, circle.center);
    out.push_back(circle.radius);
  }
}

// ---- decoding (the grader's side) ---------------------------------------------------------------

Vec2 at(const double* r) { return Vec2(r[0], r[1]); }

Vec2 springForce(const double* in, const ForceModel& models) {
  Particle p1, p2;
  p1.x = at(in);
  p1.v = at(in + 2);
  p2.x = at(in + 4);
  p2.v = at(in + 6);
  Spring s;
  s.p1 = &p1;
  s.p2 = &p2;
  s.restLength = in[8];
  s.ks = in[9];
  s.kd = in[10];
  return models.spring ? models.spring(s) : notAvailable();
}

Vec2 externalForce(const double* in, const Environment& env, const ForceModel& models) {
  Particle p;
  p.x = at(in);
  p.v = at(in + 2);
  p.m = in[4];
  p.temperature = in[5];
  return models.external ? models.external(p, env) : notAvailable();
}

// The environment at r[from, end): its length in doubles, or 0 when malformed.
std::size_t readEnvironment(const std::vector<double>& r, std::size_t from, Environment& env) {
  if (r.size() < from + kEnvHead) return 0;
  const double* e = r.data() + from;
  const double planes = e[6], circles = e[7];
  if (!(planes >= 0 && circles >= 0 && planes + circles <= kMaxObstacles)) return 0;
  const auto nPlanes = static_cast<std::size_t>(planes);
  const auto nCircles = static_cast<std::size_t>(circles);
  const std::size_t length = kEnvHead + 3 * (nPlanes + nCircles);
  if (r.size() < from + length) return 0;
  env.gravity = at(e);
  env.airTemperature = e[2];
  env.buoyancy = e[3];
  env.drag = e[4];
  env.repulsion = e[5];
  const double* o = e + kEnvHead;
  for (std::size_t k = 0; k < nPlanes; ++k, o += 3) env.planes.push_back({at(o), o[2]});
  for (std::size_t k = 0; k < nCircles; ++k, o += 3) env.circles.push_back({at(o), o[2]});
  return length;
}

// The forces a request asks for, or false when it is malformed.
bool answer(const std::vector<double>& r, const ForceModel& models, std::vector<Vec2>& out) {
  out.clear();
  const double kind = r[0];
  if (kind == kSpring) {
    if (r.size() != 1 + kSpringWidth) return false;
    out.push_back(springForce(r.data() + 1, models));
    return true;
  }
  if (kind == kExternal) {
    Environment env;
    const std::size_t length = readEnvironment(r, 1 + kParticleWidth, env);
    if (length == 0 || r.size() != 1 + kParticleWidth + length) return false;
    out.push_back(externalForce(r.data() + 1, env, models));
    return true;
  }
  if (r.size() < 2 || !(r[1] >= 0 && r[1] <= static_cast<double>(kMaxRequestDoubles))) return false;
  const auto count = static_cast<std::size_t>(r[1]);
  if (kind == kSprings) {
    if (r.size() != 2 + count * kSpringWidth) return false;
    for (std::size_t i = 0; i < count; ++i) {
      out.push_back(springForce(r.data() + 2 + i * kSpringWidth, models));
    }
    return true;
  }
  if (kind == kExternals) {
    Environment env;
    const std::size_t length = readEnvironment(r, 2, env);
    if (length == 0 || r.size() != 2 + length + count * kParticleWidth) return false;
    // Each force looks at every obstacle: bound the grader's work for one request.
    if (count * (1 + env.planes.size() + env.circles.size()) > kMaxRequestDoubles) return false;
    for (std::size_t i = 0; i < count; ++i) {
      out.push_back(externalForce(r.data() + 2 + length + i * kParticleWidth, env, models));
    }
    return true;
  }
  return false;
}

// ---- the probe's side: blocking, whole buffers (it writes with wire::writeAll) ----------------

bool readAll(int fd, void* data, std::size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t k = ::read(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

// One request; `forces` answers (false when the grader is gone or the request too large).
bool ask(int requestFd, int answerFd, const std::vector<double>& request, std::size_t forces,
         std::vector<Vec2>& out) {
  if (request.size() > kMaxRequestDoubles) return false;
  const auto n = static_cast<std::uint32_t>(request.size());
  std::vector<double> answer(2 * forces);
  std::string bytes(reinterpret_cast<const char*>(&n), sizeof n);
  bytes.append(reinterpret_cast<const char*>(request.data()), n * sizeof(double));
  if (!wire::writeAll(requestFd, bytes) ||
      !readAll(answerFd, answer.data(), answer.size() * sizeof(double))) {
    return false;
  }
  out.resize(forces);
  for (std::size_t i = 0; i < forces; ++i) out[i] = Vec2(answer[2 * i], answer[2 * i + 1]);
  return true;
}

// The bytes of `n` doubles, as a key: equal keys are equal inputs, bit for bit (NaN and -0.0
// included), and so equal forces.
std::string bytesOf(const double* d, std::size_t n) {
  return std::string(reinterpret_cast<const char*>(d), n * sizeof(double));
}

// What the grader last answered for all of a system's springs (or particles), keyed by the
// inputs it answered for: a force whose inputs are among them is taken from here, so a stepper
// that asks for every force of one state costs one round trip, whether it passes the system's
// own springs or copies of them, in any order.
struct Batch {
  std::unordered_map<std::string, Vec2> forces;  // inputs -> force
  std::string env;                               // externals: the environment asked with

  const Vec2* find(const std::string& key) const {
    const auto it = forces.find(key);
    return it == forces.end() ? nullptr : &it->second;
  }
};

class Remote {
 public:
  Remote(int requestFd, int answerFd) : requestFd_(requestFd), answerFd_(answerFd) {}

  Vec2 spring(const Spring& s) {
    std::vector<double> r{kSpring};
    putSpring(r, s);
    return one(r);
  }

  Vec2 external(const Particle& p, const Environment& env) {
    if (env.planes.size() + env.circles.size() > kMaxObstacles) return notAvailable();
    std::vector<double> r{kExternal};
    putParticle(r, p);
    putEnvironment(r, env);
    return one(r);
  }

  Vec2 springAmong(const Spring& s, const std::vector<Spring>& all) {
    key_.clear();
    putSpring(key_, s);
    const std::string key = bytesOf(key_.data(), key_.size());
    if (const Vec2* f = springs_.find(key)) return *f;
    std::vector<double> r{kSprings, static_cast<double>(all.size())};
    for (const Spring& each : all) putSpring(r, each);
    refresh(springs_, r, 2, kSpringWidth, all.size());
    if (const Vec2* f = springs_.find(key)) return *f;
    return spring(s);  // not like any of the system's springs
  }

  Vec2 externalAmong(const Particle& p, const ParticlesView& all, const Environment& env) {
    if (env.planes.size() + env.circles.size() > kMaxObstacles) return notAvailable();
    key_.clear();
    putParticle(key_, p);
    const std::string key = bytesOf(key_.data(), key_.size());
    env_.clear();
    putEnvironment(env_, env);
    const std::string envKey = bytesOf(env_.data(), env_.size());
    if (envKey == externals_.env) {
      if (const Vec2* f = externals_.find(key)) return *f;
    }
    std::vector<double> r{kExternals, static_cast<double>(all.count)};
    r.insert(r.end(), env_.begin(), env_.end());
    for (std::size_t i = 0; i < all.count; ++i) putParticle(r, all.at(i));
    refresh(externals_, r, 2 + env_.size(), kParticleWidth, all.count);
    externals_.env = envKey;
    if (const Vec2* f = externals_.find(key)) return *f;
    return external(p, env);
  }

 private:
  Vec2 one(const std::vector<double>& request) {
    std::vector<Vec2> out;
    return ask(requestFd_, answerFd_, request, 1, out) ? out[0] : notAvailable();
  }

  // Asks `request` (`count` items of `width` doubles from `first` on) and keeps the answers in
  // `batch`; on failure it is left empty (every force then asked for alone).
  void refresh(Batch& batch, const std::vector<double>& request, std::size_t first,
               std::size_t width, std::size_t count) {
    batch.forces.clear();
    batch.env.clear();
    std::vector<Vec2> forces;
    if (!ask(requestFd_, answerFd_, request, count, forces)) return;
    for (std::size_t i = 0; i < count; ++i) {
      batch.forces.emplace(bytesOf(request.data() + first + i * width, width), forces[i]);
    }
  }

  int requestFd_, answerFd_;
  Batch springs_, externals_;
  std::vector<double> key_, env_;  // reused buffers
};

// ---- the grader's side: non-blocking, and a stop pipe -------------------------------------------

// Waits for `fd` (POLLIN or POLLOUT) or for `stopFd`; false when stopped or the other end is gone.
bool await(int fd, short events, int stopFd) {
  for (;;) {
    pollfd fds[2] = {{fd, events, 0}, {stopFd, POLLIN, 0}};
    const int k = ::poll(fds, 2, -1);
    if (k < 0 && errno == EINTR) continue;
    if (k < 0 || fds[1].revents != 0) return false;
    if ((fds[0].revents & events) != 0) return true;
    if (fds[0].revents != 0) return false;  // POLLHUP or POLLERR without data
  }
}

bool transfer(int fd, char* p, std::size_t n, bool reading, int stopFd) {
  while (n > 0) {
    const ssize_t k = reading ? ::read(fd, p, n) : ::write(fd, p, n);
    if (k > 0) {
      p += k;
      n -= static_cast<std::size_t>(k);
      continue;
    }
    if (k == 0) return false;  // the requests ended
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return false;
    if (!await(fd, reading ? POLLIN : POLLOUT, stopFd)) return false;
  }
  return true;
}

}  // namespace

ForceModel remoteModel(int requestFd, int answerFd) {
  auto remote = std::make_shared<Remote>(requestFd, answerFd);
  ForceModel model;
  model.spring = [remote](const Spring& s) { return remote->spring(s); };
  model.external = [remote](const Particle& p, const Environment& env) {
    return remote->external(p, env);
  };
  model.springAmong = [remote](const Spring& s, const std::vector<Spring>& all) {
    return remote->springAmong(s, all);
  };
  model.externalAmong = [remote](const Particle& p, const ParticlesView& all,
                                 const Environment& env) {
    return remote->externalAmong(p, all, env);
  };
  return model;
}

bool available(int requestFd, int answerFd) {
  // fstat, not fcntl: the probe asks under its seccomp filter, which allows only the former.
  struct stat request {};
  struct stat answer {};
  return ::fstat(requestFd, &request) == 0 && ::fstat(answerFd, &answer) == 0 &&
         S_ISFIFO(request.st_mode) && S_ISFIFO(answer.st_mode);
}

std::size_t serve(int requestFd, int answerFd, int stopFd, const ForceModel& models,
                  std::atomic<std::size_t>* answered) {
  // A probe that is gone must not end the grader: EPIPE instead of SIGPIPE in this thread.
  sigset_t pipeSet;
  sigemptyset(&pipeSet);
  sigaddset(&pipeSet, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipeSet, nullptr);
  for (int fd : {requestFd, answerFd}) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  std::size_t count = 0;
  std::vector<double> request;
  std::vector<Vec2> forces;
  std::vector<double> reply;
  for (;;) {
    std::uint32_t n = 0;
    if (!transfer(requestFd, reinterpret_cast<char*>(&n), sizeof n, true, stopFd)) break;
    if (n == 0 || n > kMaxRequestDoubles) break;
    request.assign(n, 0.0);
    if (!transfer(requestFd, reinterpret_cast<char*>(request.data()), n * sizeof(double), true,
                  stopFd) ||
        !answer(request, models, forces)) {
      break;
    }
    reply.clear();
    for (const Vec2& f : forces) put(reply, f);
    if (!transfer(answerFd, reinterpret_cast<char*>(reply.data()), reply.size() * sizeof(double),
                  false, stopFd)) {
      break;
    }
    ++count;
    if (answered != nullptr) ++*answered;
  }
  return count;
}

}  // namespace a6::harness::forcechannel
