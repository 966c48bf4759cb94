// The scene registry and what every scene shares: reset, tuning, frame and time counting.
#include <algorithm>

#include "scenes/scene.h"
#include "scenes/scene_registry.h"

namespace a6 {

namespace {

using scene_registry::Entry;

const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries = [] {
    std::vector<Entry> out;
    scene_registry::addMassSpringScenes(out);
    scene_registry::addParticleScenes(out);
    scene_registry::addBox2DScenes(out);
    return out;
  }();
  return entries;
}

const Entry* find(const std::string& name) {
  for (const Entry& entry : registry()) {
    if (entry.info.name == name) return &entry;
  }
  return nullptr;
}

// Keeps a scene out of what cannot run: no step of zero or negative length, at least one
// substep, a cloth of at least one cell, and nothing absurdly large.
SceneParams sanitized(SceneParams p) {
  p.substeps = std::clamp(p.substeps, 1, 1000);
  p.n = std::clamp(p.n, 1, 256);
  if (!(p.dt > 0) || !(p.dt <= 1)) p.dt = 1.0 / 60;
  return p;
}

}  // namespace

void Scene::reset(const SceneParams& params) {
  params_ = sanitized(params);
  time_ = 0;
  frame_ = 0;
  build();
}

bool Scene::tune(const SceneParams& params) {
  const SceneParams p = sanitized(params);
  const unsigned uses = info_.uses;
  if ((uses & kUsesN) && p.n != params_.n) return false;
  if ((uses & kUsesSeed) && p.seed != params_.seed) return false;
  if ((uses & kUsesSpringTypes) && (p.structural != params_.structural ||
                                    p.shear != params_.shear || p.bending != params_.bending)) {
    return false;
  }
  params_ = p;
  applyParams();
  return true;
}

void Scene::advanceFrame() {
  stepFrame();
  time_ += params_.dt;
  ++frame_;
}

const std::vector<std::string>& sceneNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Entry& entry : registry()) out.push_back(entry.info.name);
    return out;
  }();
  return names;
}

const SceneInfo* sceneInfo(const std::string& name) {
  const Entry* entry = find(name);
  return entry ? &entry->info : nullptr;
}

SceneParams defaultParams(const std::string& name) {
  const Entry* entry = find(name);
  return entry ? entry->defaults : SceneParams();
}

std::unique_ptr<Scene> makeScene(const std::string& name) {
  const Entry* entry = find(name);
  if (!entry) return nullptr;
  std::unique_ptr<Scene> scene = entry->make(entry->info);
  scene->reset(entry->defaults);
  return scene;
}

}  // namespace a6
