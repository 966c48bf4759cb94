#include "render/replay.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace a6::replay {
namespace {

using Json = nlohmann::json;

constexpr double kStepsPerView = 8000;  // a view's height is 8000 steps: ±4 heights fit
constexpr std::int16_t kNotFinite = -32768;

const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::vector<unsigned char> fromBase64(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned v = 0;
  int bits = 0;
  for (const char c : text) {
    const char* at = std::find(kAlphabet, kAlphabet + 64, c);
    if (at == kAlphabet + 64) continue;  // '=' and anything else
    v = (v << 6) | static_cast<unsigned>(at - kAlphabet);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((v >> bits) & 0xff));
    }
  }
  return out;
}

// Positions as steps of `unit` metres from the view's centre.
class Packer {
 public:
  Packer(const View& view) : center_(view.center), unit_(view.height / kStepsPerView) {}
  double unit() const { return unit_; }
  void point(const Vec2& x) {
    put(x.x() - center_.x());
    put(x.y() - center_.y());
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  void put(double metres) {
    std::int16_t q = kNotFinite;
    if (std::isfinite(metres))
      q = static_cast<std::int16_t>(std::lround(std::clamp(metres / unit_, -32767.0, 32767.0)));
    const auto u = static_cast<std::uint16_t>(q);
    bytes_.push_back(static_cast<unsigned char>(u & 0xff));
    bytes_.push_back(static_cast<unsigned char>(u >> 8));
  }
  Vec2 center_;
  double unit_;
  std::vector<unsigned char> bytes_;
};

int kindOf(const ShapeData& s) {
  return s.kind == ShapeData::Kind::Circle ? 0 : s.kind == ShapeData::Kind::Polygon ? 1 : 2;
}

// The points a shape contributes: a circle's centre and a rim point, or its vertices.
std::vector<Vec2> pointsOf(const ShapeData& s) {
  if (s.kind == ShapeData::Kind::Circle) {
    return {s.center, s.center + s.radius * Vec2(std::cos(s.angle), std::sin(s.angle))};
  }
  return s.points;
}

Json staticLayout(const Snapshot& first) {
  Json layout;
  Json springs = Json::array();
  for (const SpringData& s : first.springs) {
    springs.insert(springs.end(), {s.i, s.j, static_cast<int>(s.type)});
  }
  Json planes = Json::array(), circles = Json::array(), shapes = Json::array();
  for (const HalfPlane& p : first.planes) planes.push_back({p.normal.x(), p.normal.y(), p.offset});
  for (const CircleObstacle& c : first.circles)
    circles.push_back({c.center.x(), c.center.y(), c.radius});
  for (const ShapeData& s : first.shapes) {
    shapes.push_back({kindOf(s), pointsOf(s).size(), s.radius});
  }
  layout["springs"] = std::move(springs);
  layout["planes"] = std::move(planes);
  layout["circles"] = std::move(circles);
  layout["shapes"] = std::move(shapes);
  return layout;
}

// One frame's points: particles, the shapes of the first frame's layout, the joints.
void packFrame(Packer& packer, const Snapshot& s, const Json& shapes) {
  for (const Particle& p : s.particles) packer.point(p.x);
  const Vec2 nowhere(NAN, NAN);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const std::size_t n = shapes[k][1].get<std::size_t>();
    const std::vector<Vec2> points =
        k < s.shapes.size() ? pointsOf(s.shapes[k]) : std::vector<Vec2>{};
    for (std::size_t i = 0; i < n; ++i) packer.point(i < points.size() ? points[i] : nowhere);
  }
  for (const JointData& j : s.joints) {
    packer.point(j.groundA ? j.anchorA : j.centerA);
    packer.point(j.anchorA);
    packer.point(j.anchorB);
    packer.point(j.groundB ? j.anchorB : j.centerB);
  }
}

}  // namespace

std::string toBase64(const unsigned char* bytes, std::size_t size) {
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const unsigned v = (bytes[i] << 16) | ((i + 1 < size ? bytes[i + 1] : 0) << 8) |
                       (i + 2 < size ? bytes[i + 2] : 0);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < size ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < size ? kAlphabet[v & 63] : '=';
  }
  return out;
}

Energy energyOf(const Snapshot& s, const std::vector<SpringData>& springs, const Vec2& gravity) {
  Energy e;
  e.known = !s.particles.empty() || s.shapes.empty();
  if (!e.known) return e;
  for (const Particle& p : s.particles) {
    e.kinetic += 0.5 * p.m * p.v.squaredNorm();
    e.potential -= p.m * gravity.dot(p.x);
  }
  const int n = static_cast<int>(s.particles.size());
  for (const SpringData& sp : springs) {
    if (sp.i < 0 || sp.j < 0 || sp.i >= n || sp.j >= n) continue;
    const double l = (s.particles[static_cast<std::size_t>(sp.j)].x -
                      s.particles[static_cast<std::size_t>(sp.i)].x)
                         .norm();
    e.potential += 0.5 * sp.ks * (l - sp.restLength) * (l - sp.restLength);
  }
  return e;
}

Json pack(const Recording& r) {
  Json out;
  out["scene"] = r.scene;
  out["frameDt"] = r.frameDt;
  out["gravity"] = {r.gravity.x(), r.gravity.y()};
  out["frames"] = r.frames;
  const Snapshot first = r.snapshots.empty() ? Snapshot{} : r.snapshots.front();
  Packer packer(first.view);
  out["view"] = {first.view.center.x(), first.view.center.y(), first.view.height};
  out["unit"] = packer.unit();
  out["radius"] = first.particleRadius;
  out.update(staticLayout(first));
  Json counts = Json::array(), energy = Json::array();
  bool drawn = false;
  for (const Snapshot& s : r.snapshots) {
    for (const Particle& p : s.particles) drawn = drawn || std::isfinite(p.lifetime);
    packFrame(packer, s, out["shapes"]);
    counts.push_back({s.particles.size(), s.joints.size()});
    const Energy e = energyOf(s, first.springs, r.gravity);
    const std::size_t k = counts.size() - 1;
    if (e.known) {
      energy.push_back({e.kinetic, e.potential});
    } else if (r.energies.size() == r.snapshots.size()) {
      energy.push_back({r.energies[k].kinetic, r.energies[k].potential});
    }
  }
  out["counts"] = std::move(counts);
  out["energy"] = energy.size() == r.snapshots.size() ? std::move(energy) : Json::array();
  out["drawn"] = drawn;
  out["data"] = toBase64(packer.bytes().data(), packer.bytes().size());
  return out;
}

Unpacked unpack(const Json& packed) {
  Unpacked u;
  try {
    u.scene = packed.at("scene").get<std::string>();
    u.frameDt = packed.at("frameDt").get<double>();
    u.gravity =
        Vec2(packed.at("gravity").at(0).get<double>(), packed.at("gravity").at(1).get<double>());
    u.frames = packed.at("frames").get<std::vector<int>>();
    const Json& view = packed.at("view");
    u.view.center = Vec2(view.at(0).get<double>(), view.at(1).get<double>());
    u.view.height = view.at(2).get<double>();
    const double unit = packed.at("unit").get<double>();
    std::size_t shapePoints = 0;
    for (const Json& s : packed.at("shapes")) shapePoints += s.at(1).get<std::size_t>();
    const std::vector<unsigned char> bytes = fromBase64(packed.at("data").get<std::string>());
    std::size_t at = 0;
    auto next = [&]() {
      if (at + 4 > bytes.size()) throw std::runtime_error("the data ends early");
      Vec2 x;
      for (int c = 0; c < 2; ++c, at += 2) {
        const auto q = static_cast<std::int16_t>(bytes[at] | (bytes[at + 1] << 8));
        x[c] = q == kNotFinite ? NAN : q * unit + (c == 0 ? u.view.center.x() : u.view.center.y());
      }
      return x;
    };
    const Json& counts = packed.at("counts");
    for (std::size_t f = 0; f < u.frames.size(); ++f) {
      std::vector<Vec2> particles, shapes;
      for (std::size_t i = 0; i < counts.at(f).at(0).get<std::size_t>(); ++i)
        particles.push_back(next());
      for (std::size_t i = 0; i < shapePoints; ++i) shapes.push_back(next());
      for (std::size_t i = 0; i < 4 * counts.at(f).at(1).get<std::size_t>(); ++i) next();
      u.particles.push_back(std::move(particles));
      u.shapePoints.push_back(std::move(shapes));
    }
    u.drawn = packed.value("drawn", false);
    for (const Json& e : packed.at("energy")) {
      u.energy.push_back(Energy{e.at(0).get<double>(), e.at(1).get<double>(), true});
    }
  } catch (const Json::exception& e) {
    throw std::runtime_error(std::string("a packed replay: ") + e.what());
  }
  return u;
}

std::vector<int> replayFrames(int last, int count) {
  std::vector<int> frames;
  last = std::max(0, last);
  count = std::max(1, std::min(count, last));
  for (int k = 0; k <= count; ++k) {
    const int f = static_cast<int>(std::lround(static_cast<double>(k) * last / count));
    if (frames.empty() || frames.back() != f) frames.push_back(f);
  }
  return frames;
}

}  // namespace a6::replay
