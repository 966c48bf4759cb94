// The reference forces over a pipe (see force_channel.h).
#include "harness/force_channel.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "harness/wire.h"
#include "harness/wire_fields.h"

namespace a6::harness::forcechannel {
namespace {

enum Kind { kSpring = 1, kExternal = 2, kSprings = 3, kExternals = 4 };

Vec2 notAvailable() { return Vec2::Constant(std::numeric_limits<double>::quiet_NaN()); }

// ---- encoding (the probe's side): the field lists of harness/wire_fields.h, as doubles ----------

template <typename T>
struct IsVector : std::false_type {};
template <typename T>
struct IsVector<std::vector<T>> : std::true_type {};

// Appends each field it visits: a number as itself, a vector as its two components, an enum by
// its value, a list as its length and then its items, a spring's particle by its force inputs.
struct Flatten {
  std::vector<double>& out;

  template <typename T>
  void operator()(const char*, T& x) {
    if constexpr (std::is_same_v<T, Vec2>) {
      out.push_back(x.x());  // (push_back, not an insert of a list: a stepper's hot path)
      out.push_back(x.y());
    } else if constexpr (std::is_enum_v<T>) {
      out.push_back(static_cast<double>(static_cast<int>(x)));
    } else if constexpr (std::is_arithmetic_v<T>) {
      out.push_back(static_cast<double>(x));
    } else if constexpr (std::is_same_v<T, Particle*>) {
      Particle none;  // a spring without its particle: zeros (the student's own bug)
      wire::forceInputs(*this, x != nullptr ? *x : none);
    } else if constexpr (IsVector<T>::value) {
      out.push_back(static_cast<double>(x.size()));
      for (auto& item : x) wire::fields(*this, item);
    } else {
      wire::fields(*this, x);
    }
  }
};

void putSpring(std::vector<double>& out, const Spring& s) {
  Flatten flat{out};
  wire::fields(flat, const_cast<Spring&>(s));  // Flatten only reads
}

void putParticle(std::vector<double>& out, const Particle& p) {
  Flatten flat{out};
  wire::forceInputs(flat, const_cast<Particle&>(p));
}

void putEnvironment(std::vector<double>& out, const Environment& env) {
  Flatten flat{out};
  wire::fields(flat, const_cast<Environment&>(env));
}

// How many doubles a spring and a particle take (both fixed: they hold no list).
std::size_t widthOf(void (*put)(std::vector<double>&)) {
  std::vector<double> out;
  put(out);
  return out.size();
}
const std::size_t kSpringWidth = widthOf([](std::vector<double>& out) {
  Particle p;
  putSpring(out, Spring{&p, &p});
});
const std::size_t kParticleWidth = widthOf([](std::vector<double>& out) { putParticle(out, {}); });

// ---- decoding (the grader's side) ---------------------------------------------------------------

// Reads the fields it visits back from doubles, as Flatten wrote them; `ok` turns false, and
// stays false, at the end of the input, a list longer than what is left of it, or an enum's
// unknown value. A spring's particles must point to particles of the reader's before it reads.
struct Unflatten {
  const double* at;
  const double* end;
  bool ok = true;

  bool take(std::size_t n) {
    ok = ok && static_cast<std::size_t>(end - at) >= n;
    return ok;
  }
  template <typename T>
  void operator()(const char*, T& x) {
    if constexpr (std::is_same_v<T, Vec2>) {
      if (!take(2)) return;
      x = Vec2(at[0], at[1]);
      at += 2;
    } else if constexpr (std::is_enum_v<T>) {
      if (!take(1)) return;
      const double value = *at++;
      ok = false;
      for (const auto& [e, name] : wire::namesOf(x)) {
        if (value != static_cast<double>(static_cast<int>(e))) continue;
        x = e;
        ok = true;
      }
    } else if constexpr (std::is_same_v<T, bool>) {
      if (take(1)) x = *at++ != 0;
    } else if constexpr (std::is_floating_point_v<T>) {
      // (No integer field is sent: one would need a range check before its conversion, and
      // until it has one it does not compile, falling to fields() below.)
      if (take(1)) x = static_cast<T>(*at++);
    } else if constexpr (std::is_same_v<T, Particle*>) {
      if (x != nullptr) wire::forceInputs(*this, *x);
    } else if constexpr (IsVector<T>::value) {
      if (!take(1)) return;
      // Each item takes a double at least: no list outgrows the request it came in.
      const double n = *at++;
      ok = n >= 0 && n <= static_cast<double>(end - at) && n == std::floor(n);
      if (!ok) return;
      x.resize(static_cast<std::size_t>(n));
      for (auto& item : x) wire::fields(*this, item);
    } else {
      wire::fields(*this, x);
    }
  }
};

// The force on the spring at `in` (kSpringWidth doubles), appended to `out`; false when the
// doubles are no spring (an unknown type).
bool springForce(const double* in, const ForceModel& models, std::vector<Vec2>& out) {
  Particle p1, p2;
  Spring s{&p1, &p2};
  Unflatten read{in, in + kSpringWidth};
  wire::fields(read, s);
  out.push_back(models.spring && read.ok ? models.spring(s) : notAvailable());
  return read.ok;
}

// The external force on the particle at `in` (kParticleWidth doubles), appended to `out`.
bool externalForce(const double* in, const Environment& env, const ForceModel& models,
                   std::vector<Vec2>& out) {
  Particle p;
  Unflatten read{in, in + kParticleWidth};
  wire::forceInputs(read, p);
  out.push_back(models.external && read.ok ? models.external(p, env) : notAvailable());
  return read.ok;
}

// Each external force looks at every obstacle: the grader's work for one batch is bounded (the
// probe asks a larger batch one force at a time).
bool withinWork(std::size_t count, const Environment& env) {
  return count * (1 + env.planes.size() + env.circles.size()) <= kMaxRequestDoubles;
}

// The environment at r[from, end): its length in doubles, or 0 when malformed.
std::size_t readEnvironment(const std::vector<double>& r, std::size_t from, Environment& env) {
  if (r.size() < from) return 0;
  Unflatten read{r.data() + from, r.data() + r.size()};
  wire::fields(read, env);
  if (!read.ok || env.planes.size() + env.circles.size() > kMaxObstacles) return 0;
  return static_cast<std::size_t>(read.at - (r.data() + from));
}

// The forces a request asks for, or false when it is malformed.
bool answer(const std::vector<double>& r, const ForceModel& models, std::vector<Vec2>& out) {
  out.clear();
  const double kind = r[0];
  if (kind == kSpring) {
    return r.size() == 1 + kSpringWidth && springForce(r.data() + 1, models, out);
  }
  if (kind == kExternal) {
    Environment env;
    const std::size_t length = readEnvironment(r, 1 + kParticleWidth, env);
    if (length == 0 || r.size() != 1 + kParticleWidth + length) return false;
    return externalForce(r.data() + 1, env, models, out);
  }
  if (r.size() < 2 || !(r[1] >= 0 && r[1] <= static_cast<double>(kMaxRequestDoubles)) ||
      r[1] != std::floor(r[1])) {
    return false;
  }
  const auto count = static_cast<std::size_t>(r[1]);
  if (kind == kSprings) {
    if (r.size() != 2 + count * kSpringWidth) return false;
    for (std::size_t i = 0; i < count; ++i) {
      if (!springForce(r.data() + 2 + i * kSpringWidth, models, out)) return false;
    }
    return true;
  }
  if (kind == kExternals) {
    Environment env;
    const std::size_t length = readEnvironment(r, 2, env);
    if (length == 0 || r.size() != 2 + length + count * kParticleWidth) return false;
    if (!withinWork(count, env)) return false;
    for (std::size_t i = 0; i < count; ++i) {
      if (!externalForce(r.data() + 2 + length + i * kParticleWidth, env, models, out))
        return false;
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
    r.reserve(2 + all.size() * kSpringWidth);
    for (const Spring& each : all) putSpring(r, each);
    refresh(springs_, r, 2, kSpringWidth, all.size());
    if (const Vec2* f = springs_.find(key)) return *f;
    return spring(s);  // not like any of the system's springs
  }

  Vec2 externalAmong(const Particle& p, const ParticlesView& all, const Environment& env) {
    if (env.planes.size() + env.circles.size() > kMaxObstacles) return notAvailable();
    if (!withinWork(all.count, env)) return external(p, env);  // too large a batch: alone
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
    for (const Vec2& f : forces) {
      reply.push_back(f.x());
      reply.push_back(f.y());
    }
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
