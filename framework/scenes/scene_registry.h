// Internal to framework/scenes: how each scene family registers its scenes. Users include
// scenes/scene.h and never this file.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "scenes/scene.h"

namespace a6::scene_registry {

/// One registered scene: its list entry, its fixed defaults, and how to build it.
struct Entry {
  SceneInfo info;
  SceneParams defaults;
  std::function<std::unique_ptr<Scene>(const SceneInfo&)> make;
};

/// Each family appends its scenes, in teaching order.
void addMassSpringScenes(std::vector<Entry>& out);  // mass_spring_scenes.cpp (tasks 1-4)
void addParticleScenes(std::vector<Entry>& out);    // particle_scenes.cpp (task 5)
void addBox2DScenes(std::vector<Entry>& out);       // box2d_scene_adapter.cpp (task 6)

}  // namespace a6::scene_registry
