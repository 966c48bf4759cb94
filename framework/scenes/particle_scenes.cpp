// The particle-system scene (task 5): a fire whose hot particles rise by buoyancy, stream
// around a disc, cool, slow down by drag, sink back as they cool, and die of old age.
//
// Every frame is `substeps` calls of the student's ParticleSystem::update(dt / substeps); the
// system's random generator is seeded from SceneParams::seed, so a run is reproducible.
#include <algorithm>

#include "a6/particle_system.h"
#include "scenes/scene.h"
#include "scenes/scene_registry.h"

namespace a6 {

Snapshot toSnapshot(const ParticleSystem& system) {
  Snapshot snap;
  snap.particles = system.particles;
  snap.planes = system.env.planes;
  snap.circles = system.env.circles;
  return snap;
}

namespace {

using scene_registry::Entry;

// fire ----------------------------------------------------------------------------------------
namespace fire {
// Emitter: 240 particles of 1 g per second from a 15 cm disc on the floor, 700-1000 K.
const Vec2 kEmitterAt(0, 0.15);
constexpr double kBuoyancy = 4e-5;  // N/K: 550 K above the air lifts 2.2 g against 1 g
constexpr double kDrag = 0.005;     // N·s/m: a fresh particle rises at about 2.4 m/s
constexpr double kCooling = 0.5;    // 1/s: buoyancy falls below gravity after ~1.6 s
constexpr double kRepulsion = 20;   // N/m: sqrt(k_r/m) h = 0.59 at 4 substeps
const CircleObstacle kDisc{Vec2(0, 1.0), 0.18};
constexpr double kParticleRadius = 0.012;
const View kView{Vec2(0, 1.1), 2.4};
}  // namespace fire

class FireScene final : public Scene {
 public:
  explicit FireScene(SceneInfo info) : Scene(std::move(info)) {}

  Snapshot snapshot() const override {
    Snapshot snap = toSnapshot(system_);
    snap.scene = name();
    snap.time = time();
    snap.view = fire::kView;
    snap.particleRadius = fire::kParticleRadius;
    return snap;
  }

  SceneEnergy energy() const override {
    SceneEnergy e;
    const Environment& env = system_.env;
    for (const Particle& p : system_.particles) {
      e.kinetic += 0.5 * p.m * p.v.squaredNorm();
      e.potential -= p.m * env.gravity.dot(p.x);
      for (const HalfPlane& plane : env.planes) {
        const double d = contactWith(plane, p.x).depth;
        if (d > 0) e.potential += 0.5 * env.repulsion * d * d;
      }
      for (const CircleObstacle& circle : env.circles) {
        const double d = contactWith(circle, p.x).depth;
        if (d > 0) e.potential += 0.5 * env.repulsion * d * d;
      }
    }
    return e;
  }

  // Particles live too briefly to hold: the mouse moves the disc, or else the emitter.
  bool grab(const Vec2& point) override {
    release();
    for (std::size_t k = 0; k < system_.env.circles.size(); ++k) {
      const CircleObstacle& c = system_.env.circles[k];
      if ((point - c.center).norm() <= c.radius) {
        grabbedCircle_ = static_cast<int>(k);
        offset_ = c.center - point;
        return true;
      }
    }
    const double reach = std::max(system_.emitter.radius, 0.05 * fire::kView.height);
    if ((point - system_.emitter.position).norm() <= reach) {
      grabbedEmitter_ = true;
      offset_ = system_.emitter.position - point;
      return true;
    }
    return false;
  }

  void drag(const Vec2& point) override {
    if (grabbedCircle_ >= 0) system_.env.circles[grabbedCircle_].center = point + offset_;
    if (grabbedEmitter_) system_.emitter.position = point + offset_;
  }

  void release() override {
    grabbedCircle_ = -1;
    grabbedEmitter_ = false;
  }

  bool grabbing() const override { return grabbedCircle_ >= 0 || grabbedEmitter_; }

 protected:
  void build() override {
    release();
    const SceneParams& p = params();
    system_ = ParticleSystem(p.seed);
    EmitterSpec& e = system_.emitter;
    e.position = fire::kEmitterAt;
    e.radius = 0.15;
    e.velocity = Vec2(0, 0.8);
    e.velocitySpread = 0.4;
    e.mass = 0.001;
    e.temperatureMin = 700;
    e.temperatureMax = 1000;
    e.lifetimeMin = 1.0;
    e.lifetimeMax = 1.8;
    e.rate = 240;
    system_.coolingRate = fire::kCooling;
    Environment& env = system_.env;
    env.gravity = Vec2(0, -p.gravity);
    env.airTemperature = 293.15;
    env.buoyancy = p.buoyancy;
    env.drag = p.drag;
    env.repulsion = fire::kRepulsion;
    env.planes = {HalfPlane{Vec2(0, 1), 0}};  // the floor, y = 0
    env.circles = {fire::kDisc};
  }

  void applyParams() override {
    const SceneParams& p = params();
    system_.env.gravity = Vec2(0, -p.gravity);
    system_.env.buoyancy = p.buoyancy;
    system_.env.drag = p.drag;
  }

  void stepFrame() override {
    const double h = params().dt / params().substeps;
    for (int k = 0; k < params().substeps; ++k) system_.update(h);
  }

 private:
  ParticleSystem system_;
  int grabbedCircle_ = -1;
  bool grabbedEmitter_ = false;
  Vec2 offset_ = Vec2::Zero();
};

}  // namespace

void scene_registry::addParticleScenes(std::vector<Entry>& out) {
  Entry e;
  e.info = {"fire", "Fire",
            "Hot particles rise by buoyancy, stream around a disc, cool towards the air, sink "
            "back as they cool and die of old age. Seeded: every run is the same.",
            5, kUsesSubsteps | kUsesDt | kUsesGravity | kUsesDrag | kUsesBuoyancy | kUsesSeed};
  e.defaults.substeps = 4;
  e.defaults.dt = 1.0 / 60;
  e.defaults.drag = fire::kDrag;
  e.defaults.buoyancy = fire::kBuoyancy;
  e.defaults.seed = 7;
  e.make = [](const SceneInfo& info) -> std::unique_ptr<Scene> {
    return std::make_unique<FireScene>(info);
  };
  out.push_back(std::move(e));
}

}  // namespace a6
