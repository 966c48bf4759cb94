// The Box2D scenes of task 6 (box2d_scenes.h) as Scenes: a camera per scene, the mouse drag
// through the student's beginDrag / moveDrag / endDrag, energies, and the conversion of a
// Box2D world into a Snapshot.
//
// Every frame is `substeps` world steps of dt / substeps (by default one step of 1/60 s) with
// the scene's fixed iteration counts: Box2D 2.4.1 damps the mouse joint's rotation per step,
// so the step is part of the scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "a6/joints.h"
#include "scenes/box2d_scenes.h"
#include "scenes/scene.h"
#include "scenes/scene_registry.h"

namespace a6 {

namespace {

Vec2 toVec(const b2Vec2& v) { return Vec2(v.x, v.y); }
b2Vec2 toB2(const Vec2& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }

// The fixtures of one body, in creation order (Box2D lists the newest first).
void addShapes(const b2Body* body, int index, std::vector<ShapeData>& out) {
  std::vector<const b2Fixture*> fixtures;
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
    fixtures.push_back(f);
  }
  std::reverse(fixtures.begin(), fixtures.end());
  for (const b2Fixture* fixture : fixtures) {
    const b2Shape* shape = fixture->GetShape();
    ShapeData data;
    data.body = index;
    data.angle = body->GetAngle();
    switch (shape->GetType()) {
      case b2Shape::e_circle: {
        const auto* circle = static_cast<const b2CircleShape*>(shape);
        data.kind = ShapeData::Kind::Circle;
        data.center = toVec(body->GetWorldPoint(circle->m_p));
        data.radius = circle->m_radius;
        out.push_back(data);
        break;
      }
      case b2Shape::e_polygon: {
        // Box2D keeps polygon vertices counter-clockwise; a rotation keeps them so.
        const auto* polygon = static_cast<const b2PolygonShape*>(shape);
        data.kind = ShapeData::Kind::Polygon;
        for (int k = 0; k < polygon->m_count; ++k) {
          data.points.push_back(toVec(body->GetWorldPoint(polygon->m_vertices[k])));
        }
        out.push_back(data);
        break;
      }
      case b2Shape::e_edge: {
        const auto* edge = static_cast<const b2EdgeShape*>(shape);
        data.kind = ShapeData::Kind::Edge;
        data.points = {toVec(body->GetWorldPoint(edge->m_vertex1)),
                       toVec(body->GetWorldPoint(edge->m_vertex2))};
        out.push_back(data);
        break;
      }
      case b2Shape::e_chain: {
        const auto* chain = static_cast<const b2ChainShape*>(shape);
        data.kind = ShapeData::Kind::Edge;
        for (int k = 0; k + 1 < chain->m_count; ++k) {
          data.points = {toVec(body->GetWorldPoint(chain->m_vertices[k])),
                         toVec(body->GetWorldPoint(chain->m_vertices[k + 1]))};
          out.push_back(data);
        }
        break;
      }
      default:
        break;
    }
  }
}

std::string jointType(b2JointType type) {
  switch (type) {
    case e_revoluteJoint:
      return "revolute";
    case e_prismaticJoint:
      return "prismatic";
    case e_distanceJoint:
      return "distance";
    case e_wheelJoint:
      return "wheel";
    case e_mouseJoint:
      return "mouse";
    default:
      return "other";
  }
}

}  // namespace

Snapshot toSnapshot(const Box2DScene& scene) {
  Snapshot snap;
  snap.scene = scene.name;
  if (!scene.world) return snap;
  // The ground first, then the dynamic bodies in the scene's order, then anything else.
  if (scene.ground) addShapes(scene.ground, -1, snap.shapes);
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    addShapes(scene.bodies[k], static_cast<int>(k), snap.shapes);
  }
  std::vector<const b2Body*> others;
  for (const b2Body* body = scene.world->GetBodyList(); body != nullptr; body = body->GetNext()) {
    if (scene.indexOf(body) == -2) others.push_back(body);
  }
  for (auto it = others.rbegin(); it != others.rend(); ++it) addShapes(*it, -2, snap.shapes);

  // Joints in creation order (Box2D lists the newest first).
  for (b2Joint* j = scene.world->GetJointList(); j != nullptr; j = j->GetNext()) {
    JointData data;
    data.type = jointType(j->GetType());
    data.anchorA = toVec(j->GetAnchorA());
    data.anchorB = toVec(j->GetAnchorB());
    data.centerA = toVec(j->GetBodyA()->GetPosition());
    data.centerB = toVec(j->GetBodyB()->GetPosition());
    data.groundA = j->GetBodyA()->GetType() == b2_staticBody;
    data.groundB = j->GetBodyB()->GetType() == b2_staticBody;
    snap.joints.push_back(data);
  }
  std::reverse(snap.joints.begin(), snap.joints.end());
  return snap;
}

namespace {

using scene_registry::Entry;

// Finds the dynamic fixture under a point (as Box2D's testbed does).
class PointQuery final : public b2QueryCallback {
 public:
  explicit PointQuery(const b2Vec2& point) : point_(point) {}
  bool ReportFixture(b2Fixture* fixture) override {
    if (fixture->GetBody()->GetType() == b2_dynamicBody && fixture->TestPoint(point_)) {
      hit = fixture->GetBody();
      return false;  // found one: stop the query
    }
    return true;
  }
  b2Body* hit = nullptr;

 private:
  b2Vec2 point_;
};

// How the camera frames a scene: fixed, or following a body horizontally.
struct Camera {
  View view;
  int follow = -1;          ///< index into bodies of the body the camera follows in x, or -1
  double followOffset = 0;  ///< m, view centre x minus the followed body's x
};

class Box2DSceneAdapter final : public Scene {
 public:
  Box2DSceneAdapter(SceneInfo info, Camera camera) : Scene(std::move(info)), camera_(camera) {}

  Snapshot snapshot() const override {
    Snapshot snap = scene_ ? toSnapshot(*scene_) : Snapshot();
    snap.scene = name();
    snap.time = time();
    snap.view = camera_.view;
    if (scene_ && camera_.follow >= 0 && camera_.follow < static_cast<int>(scene_->bodies.size())) {
      const double x = scene_->bodies[camera_.follow]->GetPosition().x;
      if (std::isfinite(x)) snap.view.center.x() = x + camera_.followOffset;
    }
    return snap;
  }

  SceneEnergy energy() const override {
    SceneEnergy e;
    if (!scene_) return e;
    const Vec2 g = toVec(scene_->world->GetGravity());
    for (const b2Body* body : scene_->bodies) {
      const double m = body->GetMass();
      const double inertia = body->GetInertia() - m * body->GetLocalCenter().LengthSquared();
      const double w = body->GetAngularVelocity();
      e.kinetic += 0.5 * m * toVec(body->GetLinearVelocity()).squaredNorm() + 0.5 * inertia * w * w;
      e.potential -= m * g.dot(toVec(body->GetWorldCenter()));
    }
    // Joint springs: the wheel suspension, the mouse joint, sprung distance joints.
    for (b2Joint* joint = scene_->world->GetJointList(); joint; joint = joint->GetNext()) {
      if (joint->GetType() == e_wheelJoint) {
        auto* j = static_cast<b2WheelJoint*>(joint);
        const double t = j->GetJointTranslation();
        e.potential += 0.5 * j->GetStiffness() * t * t;
      } else if (joint->GetType() == e_mouseJoint) {
        auto* j = static_cast<b2MouseJoint*>(joint);
        e.potential +=
            0.5 * j->GetStiffness() * toVec(j->GetTarget() - j->GetAnchorB()).squaredNorm();
      } else if (joint->GetType() == e_distanceJoint) {
        auto* j = static_cast<b2DistanceJoint*>(joint);
        const double stretch = (j->GetAnchorB() - j->GetAnchorA()).Length() - j->GetLength();
        e.potential += 0.5 * j->GetStiffness() * stretch * stretch;
      }
    }
    return e;
  }

  bool grab(const Vec2& point) override {
    release();
    if (!scene_) return false;
    const b2Vec2 p = toB2(point);
    const b2Vec2 d(0.001f, 0.001f);
    b2AABB box;
    box.lowerBound = p - d;
    box.upperBound = p + d;
    PointQuery query(p);
    scene_->world->QueryAABB(&query, box);
    if (query.hit == nullptr) return false;
    mouse_ = beginDrag(*scene_->world, scene_->ground, query.hit, p);
    return mouse_ != nullptr;
  }

  void drag(const Vec2& point) override {
    if (scene_ && mouse_ != nullptr) moveDrag(mouse_, toB2(point));
  }

  void release() override {
    if (scene_ && mouse_ != nullptr) endDrag(*scene_->world, mouse_);
    mouse_ = nullptr;  // whatever endDrag did, never touch that joint again
  }

  bool grabbing() const override { return mouse_ != nullptr; }

 protected:
  void build() override {
    mouse_ = nullptr;
    scene_.reset();  // if the student's joint code throws, the scene stays empty
    scene_ = makeBox2DScene(name());
    applyParams();
  }

  void applyParams() override {
    if (!scene_) return;
    const SceneParams& p = params();
    scene_->world->SetGravity(b2Vec2(0.0f, static_cast<float>(-p.gravity)));
    scene_->dt = static_cast<float>(p.dt / p.substeps);
  }

  void stepFrame() override {
    if (!scene_) return;
    for (int k = 0; k < params().substeps; ++k) scene_->step();
  }

 private:
  Camera camera_;
  std::unique_ptr<Box2DScene> scene_;
  b2MouseJoint* mouse_ = nullptr;
};

Entry entry(SceneInfo info, Camera camera) {
  Entry e;
  e.info = std::move(info);
  e.info.task = 6;
  e.info.uses = kUsesSubsteps | kUsesDt | kUsesGravity;
  e.defaults.substeps = 1;
  e.defaults.dt = 1.0 / 60;
  e.make = [camera](const SceneInfo& i) -> std::unique_ptr<Scene> {
    return std::make_unique<Box2DSceneAdapter>(i, camera);
  };
  return e;
}

}  // namespace

void scene_registry::addBox2DScenes(std::vector<Entry>& out) {
  // The angle from the scene's own constant: the description follows a change of it.
  char angle[32];
  std::snprintf(angle, sizeof angle, "%g", static_cast<double>(box2d_params::kPendulumAngle));
  out.push_back(entry({"pendulum", "Box2D: pendulum",
                       std::string("A bob on a revolute joint, released ") + angle +
                           " rad from the vertical: it swings with the period 2π sqrt(L/g) of a "
                           "simple pendulum."},
                      {View{Vec2(0, 1.45), 1.4}}));
  out.push_back(entry({"rope", "Box2D: rope",
                       "A bob on a rope (a distance joint with a maximum length): it falls "
                       "freely until the rope goes taut, then swings."},
                      {View{Vec2(0, 1.15), 2.6}}));
  out.push_back(entry({"bridge", "Box2D: bridge",
                       "Planks hinged to each other with revolute joints; a box falls on the "
                       "middle and the bridge sags under it."},
                      {View{Vec2(0, 1.1), 4.2}}));
  out.push_back(entry({"piston", "Box2D: pistons",
                       "Two prismatic joints with limits and motors: one driven up into its "
                       "upper limit, one down into its lower limit."},
                      {View{Vec2(0, 1.15), 2.2}}));
  out.push_back(entry({"car", "Box2D: car",
                       "A chassis on two wheel joints (sprung suspension, motors) driving "
                       "right over bumps. The camera follows the chassis."},
                      {View{Vec2(1, 1.2), 4.5}, 0, 1.0}));
  out.push_back(entry({"mouse_drag", "Box2D: mouse drag",
                       "A box on the floor: grab it with the mouse (a mouse joint: a 5 Hz "
                       "spring, damping ratio 0.7, max force 1000 × mass) and throw it."},
                      {View{Vec2(0, 1.0), 2.5}}));
}

}  // namespace a6
