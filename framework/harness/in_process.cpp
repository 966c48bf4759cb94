// The in-process implementation of StudentCode: builds the framework objects from plain data,
// calls the student's functions, and turns what they produced back into plain data.
#include <algorithm>
#include <exception>
#include <string>
#include <unordered_map>

#include "a6/a6.h"
#include "scenes/box2d_scenes.h"
#include "scenes/scene.h"
#include "student_code.h"

namespace a6::harness {

namespace {

Vec2 toVec(const b2Vec2& v) { return Vec2(v.x, v.y); }
b2Vec2 toB2(const Vec2& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }

// Spring pointers back to indices. A spring pointing outside the system gets index -1.
std::vector<SpringData> springsAsData(const MassSpringSystem& system) {
  std::unordered_map<const Particle*, int> index;
  for (std::size_t k = 0; k < system.particles.size(); ++k) {
    index[&system.particles[k]] = static_cast<int>(k);
  }
  auto find = [&](const Particle* p) {
    const auto it = index.find(p);
    return it == index.end() ? -1 : it->second;
  };
  std::vector<SpringData> out;
  out.reserve(system.springs.size());
  for (const Spring& s : system.springs) {
    out.push_back({find(s.p1), find(s.p2), s.restLength, s.ks, s.kd, s.type});
  }
  return out;
}

// What the joint types with local anchors share.
template <class J>
void describeAnchors(J* j, JointInfo& info) {
  info.localAnchorA = toVec(j->GetLocalAnchorA());
  info.localAnchorB = toVec(j->GetLocalAnchorB());
}

// What the revolute, prismatic and wheel joints share: a limit and a motor.
template <class J>
void describeLimitAndMotor(J* j, JointInfo& info) {
  describeAnchors(j, info);
  info.enableLimit = j->IsLimitEnabled();
  info.lower = j->GetLowerLimit();
  info.upper = j->GetUpperLimit();
  info.enableMotor = j->IsMotorEnabled();
  info.motorSpeed = j->GetMotorSpeed();
}

void describeRevolute(b2RevoluteJoint* j, JointInfo& info) {
  info.type = "revolute";
  describeLimitAndMotor(j, info);
  info.maxMotor = j->GetMaxMotorTorque();
}

void describePrismatic(b2PrismaticJoint* j, JointInfo& info) {
  info.type = "prismatic";
  describeLimitAndMotor(j, info);
  info.localAxisA = toVec(j->GetLocalAxisA());
  info.maxMotor = j->GetMaxMotorForce();
}

void describeDistance(b2DistanceJoint* j, JointInfo& info) {
  info.type = "distance";
  describeAnchors(j, info);
  info.length = j->GetLength();
  info.minLength = j->GetMinLength();
  info.maxLength = j->GetMaxLength();
  info.stiffness = j->GetStiffness();
  info.damping = j->GetDamping();
}

void describeWheel(b2WheelJoint* j, JointInfo& info) {
  info.type = "wheel";
  describeLimitAndMotor(j, info);
  info.localAxisA = toVec(j->GetLocalAxisA());
  info.maxMotor = j->GetMaxMotorTorque();
  info.stiffness = j->GetStiffness();
  info.damping = j->GetDamping();
}

void describeMouse(b2MouseJoint* j, JointInfo& info) {
  info.type = "mouse";
  info.target = toVec(j->GetTarget());
  info.maxForce = j->GetMaxForce();
  info.stiffness = j->GetStiffness();
  info.damping = j->GetDamping();
}

JointInfo describe(const Box2DScene& scene, b2Joint* joint, float invDt) {
  JointInfo info;
  info.bodyA = scene.indexOf(joint->GetBodyA());
  info.bodyB = scene.indexOf(joint->GetBodyB());
  info.anchorA = toVec(joint->GetAnchorA());
  info.anchorB = toVec(joint->GetAnchorB());
  info.collideConnected = joint->GetCollideConnected();
  info.reactionForce = toVec(joint->GetReactionForce(invDt));
  switch (joint->GetType()) {
    case e_revoluteJoint:
      describeRevolute(static_cast<b2RevoluteJoint*>(joint), info);
      break;
    case e_prismaticJoint:
      describePrismatic(static_cast<b2PrismaticJoint*>(joint), info);
      break;
    case e_distanceJoint:
      describeDistance(static_cast<b2DistanceJoint*>(joint), info);
      break;
    case e_wheelJoint:
      describeWheel(static_cast<b2WheelJoint*>(joint), info);
      break;
    case e_mouseJoint:
      describeMouse(static_cast<b2MouseJoint*>(joint), info);
      break;
    default:
      info.type = "other";
  }
  return info;
}

std::vector<JointInfo> describeAll(const Box2DScene& scene, float invDt) {
  std::vector<JointInfo> out;
  for (b2Joint* j = scene.world->GetJointList(); j != nullptr; j = j->GetNext()) {
    out.push_back(describe(scene, j, invDt));
  }
  // Box2D lists the newest joint first; report them in creation order.
  return {out.rbegin(), out.rend()};
}

// One frame of a SimulateRequest: step(frameDt) or advance(frameDt, substeps) of task 3, or the
// same with task 7's stepImplicit in place of step.
void advanceFrame(MassSpringSystem& system, const SimulateRequest& request) {
  if (!request.implicit) {
    if (request.stepOnly) {
      system.step(request.frameDt);
    } else {
      system.advance(request.frameDt, request.substeps);
    }
    return;
  }
  system.advanceImplicit(request.frameDt, request.stepOnly ? 1 : request.substeps);
}

// Runs `body` and turns any exception into the result's error.
template <typename Result, typename Body>
Result guarded(Body&& body) {
  Result result;
  try {
    body(result);
  } catch (const std::exception& e) {
    result.fail(Fault::Exception, std::string("exception: ") + e.what());
  } catch (...) {
    result.fail(Fault::Exception, "exception of unknown type");
  }
  return result;
}

class InProcess final : public StudentCode {
 public:
  explicit InProcess(ForceModel reference) : reference_(std::move(reference)) {}

 private:
  Answer respond(const Request& request) override {
    return std::visit([this](const auto& r) { return answerTo<std::decay_t<decltype(r)>>(run(r)); },
                      request);
  }

  // One run() per request kind, each the student call it stands for.

  // The spring of a request, between copies of its particles.
  struct SpringOf {
    Particle p1, p2;
    Spring spring;
    explicit SpringOf(const SpringForceRequest& r) : p1(r.p1), p2(r.p2) {
      spring.p1 = &p1, spring.p2 = &p2;
      spring.restLength = r.restLength, spring.ks = r.ks, spring.kd = r.kd;
    }
  };

  SpringForceResult run(const SpringForceRequest& request) {
    return guarded<SpringForceResult>([&](SpringForceResult& result) {
      SpringOf s(request);
      result.force = s.spring.computeForce();
    });
  }

  JacobiansResult run(const JacobiansRequest& request) {
    return guarded<JacobiansResult>([&](JacobiansResult& result) {
      SpringOf s(request.spring);
      const SpringJacobians j = springJacobians(s.spring);
      result.dfdx = j.dfdx;
      result.dfdv = j.dfdv;
    });
  }

  ForcesResult run(const ForcesRequest& request) {
    return guarded<ForcesResult>([&](ForcesResult& result) {
      const Particle& p = request.particle;
      const Environment& env = request.env;
      result.gravity = gravityForce(p, env.gravity);
      result.buoyancy = buoyancyForce(p, env.buoyancy, env.airTemperature);
      result.drag = dragForce(p, env.drag);
      result.repulsion = repulsionForce(request.contact, env.repulsion);
      result.total = externalForce(p, env);
    });
  }

  SimulateResult run(const SimulateRequest& request) {
    return guarded<SimulateResult>([&](SimulateResult& result) {
      MassSpringSystem system;
      system.env = request.env;
      for (const Particle& p : request.particles) system.addParticle(p);
      for (const SpringData& s : request.springs) {
        system.addSpring(s.i, s.j, s.ks, s.kd, s.type, s.restLength);
      }
      if (request.referenceForces) system.setForceModel(reference_);
      const int every = std::max(1, request.recordEvery);
      for (int frame = 1; frame <= request.frames; ++frame) {
        advanceFrame(system, request);
        if (frame % every == 0 || frame == request.frames) {
          result.recordedFrames.push_back(frame);
          result.states.emplace_back(system.particles.begin(), system.particles.end());
        }
      }
    });
  }

  ClothResult run(const ClothRequest& request) {
    return guarded<ClothResult>([&](ClothResult& result) {
      MassSpringSystem system;
      const ClothPrelude& prelude = clothPrelude();
      for (const Particle& p : prelude.particles) system.addParticle(p);
      for (const SpringData& s : prelude.springs) {
        system.addSpring(s.i, s.j, s.ks, s.kd, s.type, s.restLength);
      }
      a6::buildCloth(system, request.spec);
      result.particles.assign(system.particles.begin(), system.particles.end());
      result.springs = springsAsData(system);
    });
  }

  ParticlesResult run(const EmitRequest& request) {
    return guarded<ParticlesResult>([&](ParticlesResult& result) {
      Random rng(request.seed);
      for (int k = 0; k < request.count; ++k) {
        result.particles.push_back(emitParticle(request.spec, rng));
      }
    });
  }

  ParticlesResult run(const ParticleRunRequest& request) {
    return guarded<ParticlesResult>([&](ParticlesResult& result) {
      ParticleSystem system(request.seed);
      system.emitter = request.emitter;
      system.env = request.env;
      system.coolingRate = request.coolingRate;
      system.particles = request.initial;
      if (request.referenceForces) system.setForceModel(reference_);
      for (int k = 0; k < request.steps; ++k) {
        system.update(request.dt);
        result.counts.push_back(static_cast<int>(system.particles.size()));
      }
      result.particles = system.particles;
    });
  }

  Box2DResult run(const Box2DRequest& request) {
    return guarded<Box2DResult>([&](Box2DResult& result) {
      std::unique_ptr<Box2DScene> scene = makeBox2DScene(request.scene);
      if (!scene) {
        result.fail(Fault::Refused, "unknown Box2D scene '" + request.scene + "'");
        return;
      }
      const float invDt = 1.0f / scene->dt;
      for (std::size_t k = 0; k < scene->bodies.size(); ++k) {
        const b2Body* body = scene->bodies[k];
        result.bodies.push_back(
            {scene->bodyNames[k], body->GetMass(),
             body->GetInertia() - body->GetMass() * body->GetLocalCenter().LengthSquared(),
             toVec(body->GetLocalCenter())});
      }
      result.builtJoints = describeAll(*scene, invDt);

      b2MouseJoint* mouse = nullptr;
      for (int step = 0; step < request.steps; ++step) {
        // The drag script for this step.
        for (const DragEvent& event : request.drag) {
          if (event.step != step) continue;
          if (event.kind == DragEvent::Kind::Begin && mouse == nullptr && scene->dragBody >= 0) {
            mouse = beginDrag(*scene->world, scene->ground, scene->bodies[scene->dragBody],
                              toB2(event.target));
            if (mouse != nullptr) result.dragJoints.push_back(describe(*scene, mouse, invDt));
          } else if (event.kind == DragEvent::Kind::Move && mouse != nullptr) {
            moveDrag(mouse, toB2(event.target));
          } else if (event.kind == DragEvent::Kind::End && mouse != nullptr) {
            endDrag(*scene->world, mouse);
            result.endDragCleared.push_back(mouse == nullptr ? 1 : 0);
            mouse = nullptr;  // whatever endDrag did, never touch that joint again
          }
        }
        scene->step();
        std::vector<BodyPose>& poses = result.poses.emplace_back();
        for (b2Body* body : scene->bodies) {
          poses.push_back({toVec(body->GetPosition()), body->GetAngle(),
                           toVec(body->GetLinearVelocity()), body->GetAngularVelocity(),
                           body->IsAwake()});
        }
        result.jointCounts.push_back(scene->world->GetJointCount());
      }
      result.joints = describeAll(*scene, invDt);
    });
  }

  SceneResult run(const SceneRequest& request) {
    return guarded<SceneResult>([&](SceneResult& result) {
      constexpr int kMaxFrames = 36000;  // ten minutes at 60 frames per second
      int last = 0;
      for (int frame : request.frames) {
        if (frame < 0 || frame > kMaxFrames) {
          result.fail(Fault::Refused, "runScene: frame " + std::to_string(frame) +
                                          " is outside [0, " + std::to_string(kMaxFrames) + "]");
          return;
        }
        last = std::max(last, frame);
      }
      std::unique_ptr<Scene> scene = makeScene(request.scene);
      if (!scene) {
        result.fail(Fault::Refused, "unknown scene '" + request.scene + "'");
        return;
      }
      if (!request.useDefaults) scene->reset(request.params);
      // Run to the last requested frame, recording on the way.
      result.snapshots.resize(request.frames.size());
      result.energies.resize(request.frames.size());
      for (int frame = 0;; ++frame) {
        for (std::size_t k = 0; k < request.frames.size(); ++k) {
          if (request.frames[k] != frame) continue;
          result.snapshots[k] = scene->snapshot();
          result.energies[k] = scene->energy();
          if (request.lean && k > 0) result.snapshots[k].springs.clear();
        }
        if (frame >= last) break;
        scene->advanceFrame();
      }
    });
  }

  ForceModel reference_;
};

}  // namespace

std::unique_ptr<StudentCode> makeInProcess(ForceModel reference) {
  return std::make_unique<InProcess>(std::move(reference));
}

}  // namespace a6::harness
