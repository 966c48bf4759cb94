// The mass-spring scenes (tasks 1-4): a single spring, a hanging chain, a soft ball on
// obstacles, the cloth with its three spring sets, and the stiff cloth with 1 and 10 substeps.
//
// Each scene is a build function (particles, springs, environment) plus a camera. The
// framework adds the particles and springs of the small scenes itself; the cloths come from the
// student's buildCloth. Every frame is the student's MassSpringSystem::advance(dt, substeps).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <unordered_map>

#include "a6/cloth.h"
#include "a6/mass_spring_system.h"
#include "scenes/scene.h"
#include "scenes/scene_registry.h"

namespace a6 {

Snapshot toSnapshot(const MassSpringSystem& system) {
  Snapshot snap;
  snap.particles.assign(system.particles.begin(), system.particles.end());
  // Spring pointers back to indices.
  std::unordered_map<const Particle*, int> index;
  for (std::size_t k = 0; k < system.particles.size(); ++k) {
    index[&system.particles[k]] = static_cast<int>(k);
  }
  auto find = [&](const Particle* p) {
    const auto it = index.find(p);
    return it == index.end() ? -1 : it->second;
  };
  snap.springs.reserve(system.springs.size());
  for (const Spring& s : system.springs) {
    snap.springs.push_back({find(s.p1), find(s.p2), s.restLength, s.ks, s.kd, s.type});
  }
  snap.planes = system.env.planes;
  snap.circles = system.env.circles;
  return snap;
}

namespace {

using scene_registry::Entry;

constexpr int kTypes = 4;  // SpringType values: Structural, Shear, Bending, Other
int typeIndex(SpringType type) { return std::clamp(static_cast<int>(type), 0, kTypes - 1); }

// How one mass-spring scene is built and shown.
struct MassSpringDef {
  std::function<void(MassSpringSystem&, const SceneParams&)> build;
  View view;
  double particleRadius = 0.02;  ///< m, drawing size
  /// Spring constants by SpringType relative to SceneParams::ks and ::kd (what tune() applies).
  std::array<double, kTypes> ksScale{1, 1, 1, 1};
  std::array<double, kTypes> kdScale{1, 1, 1, 1};
};

// Penalty energy of a contact: the repulsion k_r d n is the force of a spring of stiffness k_r
// compressed by d.
double contactEnergy(const Environment& env, const Vec2& x) {
  double e = 0;
  for (const HalfPlane& plane : env.planes) {
    const double d = contactWith(plane, x).depth;
    if (d > 0) e += 0.5 * env.repulsion * d * d;
  }
  for (const CircleObstacle& circle : env.circles) {
    const double d = contactWith(circle, x).depth;
    if (d > 0) e += 0.5 * env.repulsion * d * d;
  }
  return e;
}

class MassSpringScene final : public Scene {
 public:
  MassSpringScene(SceneInfo info, MassSpringDef def)
      : Scene(std::move(info)), def_(std::move(def)) {}

  Snapshot snapshot() const override {
    Snapshot snap = toSnapshot(system_);
    snap.scene = name();
    snap.time = time();
    snap.view = def_.view;
    snap.particleRadius = def_.particleRadius;
    return snap;
  }

  SceneEnergy energy() const override {
    SceneEnergy e;
    e.kinetic = system_.kineticEnergy();
    e.potential = system_.gravityEnergy() + system_.springEnergy();
    for (const Particle& p : system_.particles) e.potential += contactEnergy(system_.env, p.x);
    return e;
  }

  bool grab(const Vec2& point) override {
    release();
    // The nearest particle within a few particle radii (at least 3 % of the view).
    const double reach = std::max(2.5 * def_.particleRadius, 0.03 * def_.view.height);
    double best = reach;
    for (std::size_t k = 0; k < system_.particles.size(); ++k) {
      const double d = (system_.particles[k].x - point).norm();
      if (d <= best) {
        best = d;
        grabbed_ = static_cast<int>(k);
      }
    }
    if (grabbed_ >= 0) {
      Particle& p = system_.particles[grabbed_];
      wasPinned_ = p.pinned;
      p.pinned = true;
      drag(point);
      return true;
    }
    // Else an obstacle disc under the point.
    for (std::size_t k = 0; k < system_.env.circles.size(); ++k) {
      const CircleObstacle& c = system_.env.circles[k];
      if ((point - c.center).norm() <= c.radius) {
        grabbedCircle_ = static_cast<int>(k);
        circleOffset_ = c.center - point;
        return true;
      }
    }
    return false;
  }

  void drag(const Vec2& point) override {
    if (grabbed_ >= 0) {
      Particle& p = system_.particles[grabbed_];
      p.x = point;
      p.v.setZero();
    } else if (grabbedCircle_ >= 0) {
      system_.env.circles[grabbedCircle_].center = point + circleOffset_;
    }
  }

  void release() override {
    if (grabbed_ >= 0) system_.particles[grabbed_].pinned = wasPinned_;
    grabbed_ = -1;
    grabbedCircle_ = -1;
  }

  bool grabbing() const override { return grabbed_ >= 0 || grabbedCircle_ >= 0; }

 protected:
  void build() override {
    grabbed_ = -1;
    grabbedCircle_ = -1;
    system_ = MassSpringSystem();
    def_.build(system_, params());
  }

  void applyParams() override {
    const SceneParams& p = params();
    system_.env.gravity = Vec2(0, -p.gravity);
    system_.env.drag = p.drag;
    for (Spring& s : system_.springs) {
      s.ks = def_.ksScale[typeIndex(s.type)] * p.ks;
      s.kd = def_.kdScale[typeIndex(s.type)] * p.kd;
    }
  }

  void stepFrame() override {
    const SceneParams& p = params();
    if (p.implicit) {
      system_.advanceImplicit(p.dt, p.substeps);
    } else {
      system_.advance(p.dt, p.substeps);
    }
  }

 private:
  MassSpringDef def_;
  MassSpringSystem system_;
  int grabbed_ = -1;        // index of the held particle, or -1
  bool wasPinned_ = false;  // its pinned flag before it was grabbed
  int grabbedCircle_ = -1;  // index of the held obstacle disc, or -1
  Vec2 circleOffset_ = Vec2::Zero();
};

// The environment every mass-spring scene starts from: gravity and drag from the sliders.
Environment baseEnvironment(const SceneParams& p) {
  Environment env;
  env.gravity = Vec2(0, -p.gravity);
  env.drag = p.drag;
  return env;
}

// The flags of the mass-spring sliders.
constexpr unsigned kMassSpringUses =
    kUsesKs | kUsesKd | kUsesSubsteps | kUsesDt | kUsesGravity | kUsesDrag | kUsesIntegrator;

// single_spring -------------------------------------------------------------------------------
// A 1 kg mass on one 100 N/m spring (ω = 10 rad/s, period 0.63 s) hanging from a pinned
// particle, released 0.3 m beyond the spring's rest length: it oscillates about its equilibrium,
// undamped, for ever.
namespace single_spring {
const Vec2 kAnchor(0, 1);
constexpr double kRestLength = 0.5;  // m
constexpr double kStretch = 0.3;     // m beyond the rest length at release
constexpr double kMass = 1.0;        // kg

void build(MassSpringSystem& system, const SceneParams& p) {
  system.env = baseEnvironment(p);
  Particle anchor;
  anchor.x = kAnchor;
  anchor.m = kMass;
  anchor.pinned = true;
  Particle bob;
  bob.x = kAnchor - Vec2(0, kRestLength + kStretch);
  bob.m = kMass;
  system.addParticle(anchor);
  system.addParticle(bob);
  system.addSpring(0, 1, p.ks, p.kd, SpringType::Other, kRestLength);
}
}  // namespace single_spring

// hanging_chain -------------------------------------------------------------------------------
// Ten 50 g particles on 0.1 m springs, the first end pinned, released horizontal: the chain
// swings down like a whip and settles hanging.
namespace hanging_chain {
constexpr int kLinks = 10;
constexpr double kLinkLength = 0.1;  // m
constexpr double kMass = 0.05;       // kg per particle
const Vec2 kPin(0, 1);

void build(MassSpringSystem& system, const SceneParams& p) {
  system.env = baseEnvironment(p);
  for (int k = 0; k <= kLinks; ++k) {
    Particle particle;
    particle.x = kPin + Vec2(k * kLinkLength, 0);
    particle.m = kMass;
    particle.pinned = k == 0;
    system.addParticle(particle);
  }
  for (int k = 0; k < kLinks; ++k) {
    system.addSpring(k, k + 1, p.ks, p.kd, SpringType::Structural, kLinkLength);
  }
}
}  // namespace hanging_chain

// soft_body -----------------------------------------------------------------------------------
// A soft ball (a rim of 16 particles, spokes to a centre particle, and rim springs that skip one
// particle to resist folding) dropped on a peg; it falls into a valley between two ramps and
// comes to rest on the floor. Collisions are the student's repulsion force (task 2).
namespace soft_body {
constexpr int kRim = 16;
constexpr double kRadius = 0.25;     // m
constexpr double kMass = 0.05;       // kg per particle
const Vec2 kStart(-0.05, 2.0);       // centre of the ball at release, m
constexpr double kRepulsion = 5000;  // N/m
constexpr double kPi = 3.14159265358979323846;

// A ramp: the solid half-plane under the line through `foot` that rises at `slope` rad
// (positive: rising to the left).
HalfPlane ramp(const Vec2& foot, double slope) {
  HalfPlane plane;
  plane.normal = Vec2(std::sin(slope), std::cos(slope));
  plane.offset = plane.normal.dot(foot);
  return plane;
}

void build(MassSpringSystem& system, const SceneParams& p) {
  system.env = baseEnvironment(p);
  system.env.repulsion = kRepulsion;
  system.env.planes = {HalfPlane{Vec2(0, 1), 0},               // the floor, y = 0
                       ramp(Vec2(-0.6, 0), kPi / 6),           // rising to the left, 30°
                       ramp(Vec2(1.4, 0), -kPi / 6)};          // rising to the right, 30°
  system.env.circles = {CircleObstacle{Vec2(0.1, 1.0), 0.2}};  // the peg

  Particle centre;
  centre.x = kStart;
  centre.m = kMass;
  system.addParticle(centre);
  for (int k = 0; k < kRim; ++k) {
    const double a = 2 * kPi * k / kRim;
    Particle rim;
    rim.x = kStart + kRadius * Vec2(std::cos(a), std::sin(a));
    rim.m = kMass;
    system.addParticle(rim);
  }
  const double bendScale = 0.5;  // the skip-one rim springs are softer
  for (int k = 0; k < kRim; ++k) {
    const int a = 1 + k, b = 1 + (k + 1) % kRim, c = 1 + (k + 2) % kRim;
    system.addSpring(a, b, p.ks, p.kd, SpringType::Structural);  // rim
    system.addSpring(0, a, p.ks, p.kd, SpringType::Shear);       // spoke
    system.addSpring(a, c, bendScale * p.ks, bendScale * p.kd, SpringType::Bending);
  }
}
}  // namespace soft_body

// The cloths ----------------------------------------------------------------------------------
// A 1 m cloth of n x n cells built by the student's buildCloth, top corners pinned, hanging in
// the x-y plane under gravity. Shear and bending springs keep the ratios of ClothSpec's
// defaults to the structural constants.
namespace cloth {
constexpr double kShearScale = 0.25;   // ClothSpec: ksShear / ksStructural = 50 / 200
constexpr double kBendingScale = 0.1;  // ClothSpec: ksBending / ksStructural = 20 / 200

ClothSpec spec(const SceneParams& p, double particleMass) {
  ClothSpec spec;
  spec.n = p.n;
  spec.size = 1.0;
  spec.origin = Vec2(-0.5, 1.0);
  spec.particleMass = particleMass;
  spec.ksStructural = p.ks;
  spec.kdStructural = p.kd;
  spec.shear = p.shear;
  spec.ksShear = kShearScale * p.ks;
  spec.kdShear = kShearScale * p.kd;
  spec.bending = p.bending;
  spec.ksBending = kBendingScale * p.ks;
  spec.kdBending = kBendingScale * p.kd;
  spec.pinTopCorners = true;
  return spec;
}

void build(MassSpringSystem& system, const SceneParams& p, double particleMass) {
  system.env = baseEnvironment(p);
  buildCloth(system, spec(p, particleMass));
  if (!p.structural) {
    auto& s = system.springs;
    s.erase(std::remove_if(s.begin(), s.end(),
                           [](const Spring& x) { return x.type == SpringType::Structural; }),
            s.end());
  }
}

MassSpringDef def(double particleMass) {
  MassSpringDef d;
  d.build = [particleMass](MassSpringSystem& s, const SceneParams& p) {
    build(s, p, particleMass);
  };
  d.view = View{Vec2(0, 0.35), 1.6};
  d.particleRadius = 0.012;
  d.ksScale = {1, kShearScale, kBendingScale, 1};
  d.kdScale = {1, kShearScale, kBendingScale, 1};
  return d;
}
}  // namespace cloth

// The stiff cloth: springs 5x stiffer than the cloth's and the same 10 g particles, so
// ω = sqrt(ks/m) = 316 rad/s. One 1/60 s step per frame gives ω h = 5.3 > 2 (unstable: it
// explodes within a few frames); ten substeps give ω h = 0.53, and even the cloth's fastest
// mode (about 2.2 ω) stays below 2.
namespace stiff_cloth {
constexpr double kKs = 1000;  // N/m
constexpr double kKd = 0.5;   // N·s/m
}  // namespace stiff_cloth

constexpr double kClothParticleMass = 0.01;  // kg, ClothSpec's default

SceneParams clothParams(bool shear, bool bending) {
  SceneParams p;
  p.ks = 200;
  p.kd = 0.2;
  p.substeps = 10;
  p.n = 10;
  p.dt = 1.0 / 60;
  p.drag = 0.002;
  p.structural = true;
  p.shear = shear;
  p.bending = bending;
  return p;
}

SceneParams stiffClothParams(int substeps, bool implicit = false) {
  SceneParams p = clothParams(true, false);
  p.ks = stiff_cloth::kKs;
  p.kd = stiff_cloth::kKd;
  p.substeps = substeps;
  p.implicit = implicit;
  return p;
}

Entry entry(SceneInfo info, SceneParams defaults, MassSpringDef def) {
  Entry e;
  e.info = std::move(info);
  e.defaults = defaults;
  e.make = [def = std::move(def)](const SceneInfo& i) -> std::unique_ptr<Scene> {
    return std::make_unique<MassSpringScene>(i, def);
  };
  return e;
}

// Task 1: one spring.
Entry singleSpring() {
  SceneParams p;
  p.ks = 100;
  p.kd = 0;
  p.substeps = 10;
  MassSpringDef d;
  d.build = single_spring::build;
  d.view = View{Vec2(0, 0.55), 1.3};
  d.particleRadius = 0.04;
  return entry({"single_spring", "A single spring",
                "A 1 kg mass on a 100 N/m spring, released stretched: it oscillates "
                "about its equilibrium with period 0.63 s, and its energy stays bounded.",
                1, kMassSpringUses},
               p, d);
}

// Task 3: a chain of springs.
Entry hangingChain() {
  SceneParams p;
  p.ks = 1000;
  p.kd = 0.1;
  p.substeps = 10;
  p.drag = 0.01;
  MassSpringDef d;
  d.build = hanging_chain::build;
  d.view = View{Vec2(0, 0.45), 1.7};
  d.particleRadius = 0.025;
  return entry({"hanging_chain", "A hanging chain",
                "Ten particles on springs, pinned at one end and released horizontal: "
                "the chain swings down and settles hanging.",
                3, kMassSpringUses},
               p, d);
}

// Task 2: a ball of springs against obstacles.
Entry softBody() {
  SceneParams p;
  p.ks = 500;
  p.kd = 0.5;
  p.substeps = 10;
  p.drag = 0.05;
  MassSpringDef d;
  d.build = soft_body::build;
  d.view = View{Vec2(0.4, 1.05), 2.5};
  d.particleRadius = 0.02;
  d.ksScale = {1, 1, 0.5, 1};
  d.kdScale = {1, 1, 0.5, 1};
  return entry({"soft_body", "A soft ball on obstacles",
                "A ball of springs falls on a peg and into a valley between two ramps; "
                "the obstacles push back with the repulsion force k_r d n.",
                2, kMassSpringUses},
               p, d);
}

// The cloth (task 4) with one more spring type each time, then stiff: one step and ten
// substeps (task 3), one implicit step (task 7).
void addClothScenes(std::vector<Entry>& out) {
  constexpr unsigned kClothUses = kMassSpringUses | kUsesN | kUsesSpringTypes;
  out.push_back(entry({"cloth_structural", "Cloth: structural springs only",
                       "Without shear springs nothing resists shearing: the cloth folds and "
                       "collapses under its own weight.",
                       4, kClothUses},
                      clothParams(false, false), cloth::def(kClothParticleMass)));
  out.push_back(entry({"cloth_shear", "Cloth: + shear springs",
                       "Shear springs across every cell keep the cloth's shape; it still "
                       "creases freely.",
                       4, kClothUses},
                      clothParams(true, false), cloth::def(kClothParticleMass)));
  out.push_back(
      entry({"cloth_bending", "Cloth: + shear + bending springs",
             "Bending springs over two cells make the cloth resist folding.", 4, kClothUses},
            clothParams(true, true), cloth::def(kClothParticleMass)));
  out.push_back(entry({"stiff_cloth_1", "Stiff cloth, 1 substep",
                       "Springs so stiff that one 1/60 s step is beyond the stability limit "
                       "ω h < 2: the cloth explodes. Compare stiff_cloth_10.",
                       3, kClothUses},
                      stiffClothParams(1), cloth::def(kClothParticleMass)));
  out.push_back(entry({"stiff_cloth_10", "Stiff cloth, 10 substeps",
                       "The same stiff cloth in ten substeps per frame: ω h is ten times "
                       "smaller and the cloth holds.",
                       3, kClothUses},
                      stiffClothParams(10), cloth::def(kClothParticleMass)));
  out.push_back(entry({"stiff_cloth_implicit", "Stiff cloth, implicit Euler",
                       "The same stiff cloth in ONE implicit Euler step per frame (task 7): "
                       "backward Euler is stable at any ω h, and damps the fastest modes. "
                       "Switch the integrator to compare it with stiff_cloth_1.",
                       7, kClothUses},
                      stiffClothParams(1, true), cloth::def(kClothParticleMass)));
}

}  // namespace

void scene_registry::addMassSpringScenes(std::vector<Entry>& out) {
  out.push_back(singleSpring());
  out.push_back(hangingChain());
  out.push_back(softBody());
  addClothScenes(out);
}

}  // namespace a6
