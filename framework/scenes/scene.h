// The scenes, defined once and registered by name: the viewer, the headless renderer, the
// tests, the harness (and through it the grader's probe) and the benchmarks all build scenes
// from here, so a picture, a test and a golden image always show the same physics.
//
// A scene is data plus the student code it exercises:
//   single_spring, hanging_chain      springs (task 1), forces (task 2), time stepping (task 3)
//   cloth_structural/_shear/_bending  the cloth builder (task 4) on top of tasks 1-3
//   stiff_cloth_1, stiff_cloth_10     the same stiff cloth with 1 and with 10 substeps
//   stiff_cloth_implicit              the same stiff cloth, one implicit Euler step per frame (task
//   7) soft_body                         a soft ball on obstacles: repulsion (task 2) and task 3
//   fire                              the particle system (task 5)
//   pendulum, rope, bridge, piston, car, mouse_drag   Box2D joints (task 6)
//
// Design note: every scene fixes what its result depends on.
// The frame duration, the substeps, the random seed, Box2D's time step and iteration counts
// (Box2D 2.4.1 damps the mouse joint's rotation per step) and the camera are part of the
// scene's defaults (defaultParams), so two runs of a scene give bit-identical snapshots and a
// golden image is a pure function of the student's code. The viewer's sliders override them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scenes/snapshot.h"

namespace a6 {

class MassSpringSystem;
class ParticleSystem;
struct Box2DScene;

/// The viewer's sliders. Every scene fills its own defaults (defaultParams) and ignores the
/// fields it does not use (SceneInfo::uses says which it uses).
struct SceneParams {
  double ks = 0;           ///< main spring stiffness, N/m (cloth: structural; shear and
                           ///< bending springs keep their ratio to it)
  double kd = 0;           ///< main spring damping, N·s/m (other springs keep their ratio)
  int substeps = 1;        ///< steps per frame, >= 1; each step is dt / substeps
  int n = 10;              ///< cloth resolution: n x n cells, (n+1)² particles
  double dt = 1.0 / 60;    ///< duration of one frame, s
  double gravity = 9.81;   ///< magnitude of gravity, m/s², pointing along -y
  double drag = 0;         ///< drag coefficient k_d of every particle, N·s/m
  double buoyancy = 0;     ///< buoyancy coefficient b, N/K (particle systems)
  bool structural = true;  ///< cloth: keep the structural springs
  bool shear = false;      ///< cloth: add shear springs
  bool bending = false;    ///< cloth: add bending springs
  std::uint64_t seed = 1;  ///< seed of the scene's random generator (particle systems)
  bool implicit = false;   ///< mass-spring scenes: task 7's stepImplicit in place of task 3's
                           ///< step (symplectic Euler), `substeps` steps per frame alike
};

/// Which SceneParams fields a scene uses, as bits of SceneInfo::uses.
enum SceneParamBit : unsigned {
  kUsesKs = 1u << 0,
  kUsesKd = 1u << 1,
  kUsesSubsteps = 1u << 2,
  kUsesN = 1u << 3,
  kUsesDt = 1u << 4,
  kUsesGravity = 1u << 5,
  kUsesDrag = 1u << 6,
  kUsesBuoyancy = 1u << 7,
  kUsesSpringTypes = 1u << 8,  ///< structural / shear / bending toggles
  kUsesSeed = 1u << 9,
  kUsesIntegrator = 1u << 10,  ///< the integrator switch (symplectic / implicit)
};

/// What the scene list shows.
struct SceneInfo {
  std::string name;         ///< registry name, e.g. "cloth_shear"
  std::string title;        ///< short title for a menu, e.g. "Cloth: + shear springs"
  std::string description;  ///< one or two sentences: what to look at
  int task = 0;             ///< the task (1-7) whose code the scene shows off most
  unsigned uses = 0;        ///< SceneParamBit flags
};

/// One running scene. Build it with makeScene(name); it starts reset to defaultParams(name).
///
/// makeScene, reset, advanceFrame and the mouse calls run student code: they may throw (catch
/// and show the message), and student code may leave non-finite numbers in a snapshot (an
/// exploding cloth): draw what is finite.
class Scene {
 public:
  virtual ~Scene() = default;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  const SceneInfo& info() const { return info_; }
  const std::string& name() const { return info_.name; }
  const SceneParams& params() const { return params_; }

  /// Rebuilds the scene from scratch with `params` (time 0, nothing grabbed).
  void reset(const SceneParams& params);
  /// Applies what can change while the scene runs (ks, kd, substeps, dt, gravity, drag,
  /// buoyancy). Returns false, changing nothing, when the change needs a reset (n, spring
  /// toggles, seed).
  bool tune(const SceneParams& params);
  /// Advances by one frame: params().dt seconds in params().substeps steps.
  void advanceFrame();
  /// Time since the last reset, s; frames since the last reset.
  double time() const { return time_; }
  int frame() const { return frame_; }

  /// The picture of the scene now (scene name, time and view filled in).
  virtual Snapshot snapshot() const = 0;
  virtual SceneEnergy energy() const = 0;

  /// Mouse interaction, world coordinates (m). grab() picks what is under the point (the
  /// nearest particle within a small radius, an obstacle disc, the emitter, or the Box2D body
  /// under the point through the student's beginDrag) and returns whether it got something;
  /// drag() moves it; release() lets go. A grabbed particle is held in place (pinned) until
  /// released.
  virtual bool grab(const Vec2& worldPoint) = 0;
  virtual void drag(const Vec2& worldPoint) = 0;
  virtual void release() = 0;
  virtual bool grabbing() const = 0;

 protected:
  explicit Scene(SceneInfo info) : info_(std::move(info)) {}
  /// Builds the scene's state from params() (called by reset()). What the student's code
  /// built (a cloth's springs and their constants) is left as it built it.
  virtual void build() = 0;
  /// Applies a tuned params() to the running state without rebuilding it (called by tune()).
  virtual void applyParams() = 0;
  /// Advances the state by one frame of params() (called by advanceFrame()).
  virtual void stepFrame() = 0;

 private:
  SceneInfo info_;
  SceneParams params_;
  double time_ = 0;
  int frame_ = 0;
};

/// Every registered scene, in teaching order (tasks 1 to 7).
const std::vector<std::string>& sceneNames();
/// The scene list entry of `name`; nullptr for an unknown name.
const SceneInfo* sceneInfo(const std::string& name);
/// The fixed defaults of `name` (frame dt, substeps, constants, seed); SceneParams() for an
/// unknown name.
SceneParams defaultParams(const std::string& name);
/// A new scene, reset to defaultParams(name); nullptr for an unknown name. The caller owns it.
std::unique_ptr<Scene> makeScene(const std::string& name);

// Snapshot conversion: the plain-data picture of a system (scene name, time and view are left
// for the caller to fill).

/// Particles, springs as index pairs (a spring pointing outside the system gets index -1) and
/// the environment's obstacles.
Snapshot toSnapshot(const MassSpringSystem& system);
/// Particles and the environment's obstacles.
Snapshot toSnapshot(const ParticleSystem& system);
/// Every fixture in world coordinates (polygons counter-clockwise, circles with centre,
/// radius and body angle, edges and chains as edges; body index from Box2DScene::indexOf) and
/// every joint as its type and two world anchors, in creation order.
Snapshot toSnapshot(const Box2DScene& scene);

}  // namespace a6
