// "The student's code", as the test suite sees it: a few coarse requests in plain data.
//
// Design note: why an interface. The suite is written once against it. Students run it
// in-process (their seven files linked in: fast, and a debugger works); the grader runs it
// against a sandboxed probe that links the student's files and answers over a pipe, so student
// code never runs in the process that decides the grade. Hence plain data: it must serialise.
//
// Design note: one request type. The requests are one std::variant (Request), answered by one
// call (ask); each layer between a test and the student's functions (wire, probe, time budget,
// transcript) is one function over it. Adding a kind takes its struct here (in Request, with its
// Result and kKind), its field list (wire_fields.h) and its student call (in_process.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "a6/cloth.h"
#include "a6/forces.h"
#include "a6/implicit.h"
#include "a6/particle_system.h"
#include "scenes/scene.h"
#include "scenes/snapshot.h"

namespace a6::harness {

using a6::SpringData;  // particle indices instead of pointers (scenes/snapshot.h)

/// Why a request did not run to the end. Decisions (scoring, retries, the report) read this
/// value, never the wording of `error`, which is for people.
enum class Fault : unsigned char {
  None,          ///< it ran to the end
  Exception,     ///< the student's code threw
  Refused,       ///< the request was invalid (an unknown scene, a frame out of range): no
                 ///< student code ran
  Crashed,       ///< the grader's probe died, or closed its answer pipe, on this request
  TimedOut,      ///< the request's time limit ran out, and the probe was stopped
  Garbage,       ///< the probe's answer could not be read
  BadStart,      ///< the probe started but failed the start-up check (threads, no filter)
  StartFailed,   ///< the sandbox could not start the probe (a grader problem)
  StartsUsedUp,  ///< the probe was started as often as this check allows: not sent
  NotRun,        ///< not sent: the check's time limit or all checks' time budget was spent
  Unavailable,   ///< not sent: there is no probe (the build failed; `error` says why)
  GraderError,   ///< the grader itself failed on this request
  Killed,        ///< the probe was killed by SIGKILL the grader did not send (the machine's
                 ///< doing: out of memory, another program): the check is run again
};

/// Every result carries an outcome: no fault and an empty error when the student code ran to
/// the end, otherwise the fault and, in `error`, what went wrong in words (an exception's
/// message, a crash or a timeout in the grader's probe).
struct Outcome {
  Fault fault = Fault::None;
  std::string error;
  bool ok() const { return fault == Fault::None && error.empty(); }
  void fail(Fault why, std::string words) {
    fault = why;
    error = std::move(words);
  }
};

// Each request kind: its answer type (Result), its name on the wire (kKind); its fields are in
// wire_fields.h.
struct SpringForceResult;
struct ForcesResult;
struct SimulateResult;
struct ClothResult;
struct ParticlesResult;
struct Box2DResult;
struct SceneResult;
struct JacobiansResult;

// Task 1 ---------------------------------------------------------------------------------------
struct SpringForceRequest {
  using Result = SpringForceResult;
  static constexpr const char* kKind = "springForce";
  Particle p1, p2;
  double restLength = 0, ks = 0, kd = 0;
};
struct SpringForceResult : Outcome {
  Vec2 force = Vec2::Zero();  ///< computeForce(): on p2, N
};

// Task 2 ---------------------------------------------------------------------------------------
struct ForcesRequest {
  using Result = ForcesResult;
  static constexpr const char* kKind = "forces";
  Particle particle;
  Environment env;
  Contact contact;  ///< the contact handed to repulsionForce on its own
};
struct ForcesResult : Outcome {
  Vec2 gravity = Vec2::Zero(), buoyancy = Vec2::Zero(), drag = Vec2::Zero();
  Vec2 repulsion = Vec2::Zero();  ///< repulsionForce(request.contact, env.repulsion)
  Vec2 total = Vec2::Zero();      ///< externalForce(particle, env)
};

// Task 3 ---------------------------------------------------------------------------------------
struct SimulateRequest {
  using Result = SimulateResult;
  static constexpr const char* kKind = "simulate";
  std::vector<Particle> particles;
  std::vector<SpringData> springs;
  Environment env;
  double frameDt = 1.0 / 60;  ///< s
  int substeps = 1;           ///< advance(frameDt, substeps) per frame...
  bool stepOnly = false;      ///< ...or, when true, step(frameDt) per frame
  bool implicit = false;      ///< task 7: stepImplicit in place of step (substeps alike)
  int frames = 1;
  int recordEvery = 1;           ///< record the state after every k-th frame (and the last)
  bool referenceForces = false;  ///< swap in the reference force models (force_model.h)
};
struct SimulateResult : Outcome {
  std::vector<int> recordedFrames;            ///< frame numbers (1-based) recorded
  std::vector<std::vector<Particle>> states;  ///< one particle list per recorded frame
};

// Task 4 ---------------------------------------------------------------------------------------
/// buildCloth runs on a system that already holds these (a ball on a two-spring rope: three
/// particles, two springs, none pinned), as in a scene with more than the cloth: the cloth must
/// append its particles after them (at base = clothPrelude().particles.size()) and leave them
/// as they were. The result holds the whole system, prelude first.
struct ClothPrelude {
  std::vector<Particle> particles;
  std::vector<SpringData> springs;
};
inline const ClothPrelude& clothPrelude() {
  static const ClothPrelude prelude = [] {
    ClothPrelude out;
    Particle anchor, knot, ball;
    anchor.x = Vec2(-3, 2), anchor.m = 1;
    knot.x = Vec2(-3, 1.5), knot.m = 0.05;
    ball.x = Vec2(-3, 1), ball.m = 0.4;
    out.particles = {anchor, knot, ball};
    out.springs = {{0, 1, 0.5, 300, 0.3, SpringType::Other},
                   {1, 2, 0.5, 300, 0.3, SpringType::Other}};
    return out;
  }();
  return prelude;
}
struct ClothRequest {
  using Result = ClothResult;
  static constexpr const char* kKind = "buildCloth";
  ClothSpec spec;  ///< buildCloth(system, spec) on a system holding clothPrelude()
};
struct ClothResult : Outcome {
  std::vector<Particle> particles;  ///< the prelude's, then the cloth's
  std::vector<SpringData> springs;  ///< the prelude's, then the cloth's
};

// Task 5 ---------------------------------------------------------------------------------------
struct EmitRequest {
  using Result = ParticlesResult;
  static constexpr const char* kKind = "emit";
  EmitterSpec spec;
  std::uint64_t seed = 1;
  int count = 1;
};
struct ParticlesResult : Outcome {
  std::vector<Particle> particles;
  std::vector<int> counts;  ///< number of live particles after every step (update runs only)
};
struct ParticleRunRequest {
  using Result = ParticlesResult;
  static constexpr const char* kKind = "runParticles";
  EmitterSpec emitter;
  Environment env;
  double coolingRate = 1;
  std::uint64_t seed = 1;
  std::vector<Particle> initial;  ///< particles alive before the first step
  double dt = 1.0 / 60;           ///< s
  int steps = 1;
  bool referenceForces = false;
};

// Task 6 ---------------------------------------------------------------------------------------
/// A scripted mouse drag: at the start of step `step` (0-based), begin, move or end.
struct DragEvent {
  enum class Kind { Begin, Move, End } kind = Kind::Begin;
  int step = 0;
  Vec2 target = Vec2::Zero();  ///< m, world frame
};
struct Box2DRequest {
  using Result = Box2DResult;
  static constexpr const char* kKind = "runBox2D";
  std::string scene;
  int steps = 60;
  std::vector<DragEvent> drag;
};
/// A body's state after a step: position of its origin (m), angle
/// (rad), linear (m/s) and angular (rad/s) velocity.
struct BodyPose {
  Vec2 position = Vec2::Zero();
  double angle = 0;
  Vec2 velocity = Vec2::Zero();
  double angularVelocity = 0;
  bool awake = true;  ///< false while Box2D lets the body sleep
};
struct BodyInfo {
  std::string name;
  double mass = 0;                  ///< kg
  double inertia = 0;               ///< about the centre of mass, kg·m²
  Vec2 localCenter = Vec2::Zero();  ///< centre of mass in the body frame, m
};
/// Everything a test may ask of a joint (fields that do not apply stay zero / false).
struct JointInfo {
  std::string type;            ///< revolute, prismatic, distance, wheel, mouse, other
  int bodyA = -2, bodyB = -2;  ///< index into bodies; -1 the ground; -2 unknown
  Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();            ///< world, m
  Vec2 localAnchorA = Vec2::Zero(), localAnchorB = Vec2::Zero();  ///< body frames, m
  Vec2 localAxisA = Vec2::Zero();  ///< prismatic and wheel axis in bodyA's frame
  bool collideConnected = false;
  bool enableLimit = false;
  double lower = 0, upper = 0;  ///< limits: m (prismatic) or rad (revolute)
  bool enableMotor = false;
  double motorSpeed = 0;                            ///< m/s or rad/s
  double maxMotor = 0;                              ///< max motor force (N) or torque (N·m)
  double length = 0, minLength = 0, maxLength = 0;  ///< distance joint, m
  double stiffness = 0, damping = 0;                ///< distance, wheel, mouse
  double maxForce = 0;                              ///< mouse, N
  Vec2 target = Vec2::Zero();                       ///< mouse, m
  Vec2 reactionForce = Vec2::Zero();                ///< on bodyB at the last step, N
};
struct Box2DResult : Outcome {
  std::vector<BodyInfo> bodies;
  std::vector<std::vector<BodyPose>> poses;  ///< poses[step][body], after each step
  std::vector<JointInfo> joints;             ///< the world's joints after the last step
  std::vector<JointInfo> builtJoints;        ///< the world's joints right after building
  std::vector<int> jointCounts;              ///< the world's joint count after each step
  std::vector<JointInfo> dragJoints;         ///< each mouse joint, as beginDrag returned it
  std::vector<int> endDragCleared;  ///< per endDrag: 1 if it set the caller's pointer to null
};

// Task 7 ---------------------------------------------------------------------------------------
struct JacobiansRequest {
  using Result = JacobiansResult;
  static constexpr const char* kKind = "springJacobians";
  SpringForceRequest spring;  ///< springJacobians() of this spring
};
struct JacobiansResult : Outcome {
  Mat2 dfdx = Mat2::Zero();  ///< N/m
  Mat2 dfdv = Mat2::Zero();  ///< N·s/m
};

// Scenes (scenes/scene.h): what golden images are rendered from -------------------------------
struct SceneRequest {
  using Result = SceneResult;
  static constexpr const char* kKind = "runScene";
  std::string scene;        ///< a name from sceneNames()
  std::vector<int> frames;  ///< record a snapshot after each of these frame counts (0: the
                            ///< initial state); any order, repeats allowed
  bool useDefaults = true;  ///< run with defaultParams(scene)...
  SceneParams params;       ///< ...or, when useDefaults is false, with these
  bool lean = false;        ///< a replay's many frames: only the first snapshot keeps its springs
};
struct SceneResult : Outcome {
  std::vector<Snapshot> snapshots;  ///< snapshots[k] after request.frames[k] frames
  /// energies[k]: the scene's own energies (Scene::energy) at snapshots[k]; a replay plots them
  /// where a snapshot cannot tell them (Box2D bodies carry no masses or velocities).
  std::vector<SceneEnergy> energies;
};

/// Every request, one type: a request kind is one of these alternatives.
using Request =
    std::variant<SpringForceRequest, ForcesRequest, SimulateRequest, ClothRequest, EmitRequest,
                 ParticleRunRequest, Box2DRequest, SceneRequest, JacobiansRequest>;

/// Every answer, one type: the answer to a request holds that request's Result, at the same
/// index (two kinds may share a Result type, so the index says which request it answers).
template <class Requests>
struct AnswersTo;
template <class... Kinds>
struct AnswersTo<std::variant<Kinds...>> {
  using type = std::variant<typename Kinds::Result...>;
};
using Answer = AnswersTo<Request>::type;

/// The index of request kind R in Request (and of its answer in Answer).
template <class R, class... Kinds>
constexpr std::size_t indexIn(const std::variant<Kinds...>*) {
  constexpr bool same[] = {std::is_same_v<R, Kinds>...};
  std::size_t k = 0;
  while (k < sizeof...(Kinds) && !same[k]) ++k;
  return k;
}
template <class R>
constexpr std::size_t kKindOf = indexIn<R>(static_cast<const Request*>(nullptr));

/// The answer to a request of kind R that holds `result`.
template <class R>
Answer answerTo(typename R::Result result) {
  return Answer(std::in_place_index<kKindOf<R>>, std::move(result));
}
/// The outcome every answer carries.
inline Outcome& outcomeOf(Answer& answer) {
  return std::visit([](auto& a) -> Outcome& { return a; }, answer);
}
inline const Outcome& outcomeOf(const Answer& answer) {
  return std::visit([](const auto& a) -> const Outcome& { return a; }, answer);
}
/// An answer to `request` that holds only `outcome` (a request that failed before any answer).
inline Answer failedAnswer(const Request& request, Outcome outcome) {
  return std::visit(
      [&](const auto& r) {
        typename std::decay_t<decltype(r)>::Result result;
        static_cast<Outcome&>(result) = std::move(outcome);
        return answerTo<std::decay_t<decltype(r)>>(std::move(result));
      },
      request);
}

/// The student's code: answers requests. Each implementation catches what it can and reports
/// it in the answer's outcome.
class StudentCode {
 public:
  virtual ~StudentCode() = default;

  /// The answer to `request`, at the request's index.
  Answer ask(const Request& request) { return respond(request); }
  /// The typed form: code.ask(SpringForceRequest{...}) gives a SpringForceResult.
  template <class R>
  typename R::Result ask(const R& request) {
    return std::get<kKindOf<R>>(respond(Request(std::in_place_index<kKindOf<R>>, request)));
  }

 private:
  /// What each implementation defines: one function over every kind.
  virtual Answer respond(const Request& request) = 0;
};

/// The in-process implementation: calls the seven files linked into this binary. `reference`
/// is the force model used for requests that ask for referenceForces (empty: the student's).
std::unique_ptr<StudentCode> makeInProcess(ForceModel reference = {});

}  // namespace a6::harness
