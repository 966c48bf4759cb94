// What the renderer draws and how: colour modes, toggles, sizes. Sizes are in pixels, so lines
// and dots keep their thickness whatever the view's scale.
#pragma once

#include <array>

#include "a6/spring.h"

namespace a6 {

struct RenderOptions {
  // Springs.
  bool colorSpringsByType = true;     ///< structural / shear / bending / other colours
  bool colorSpringsByStrain = false;  ///< (l - l0)/l0: blue compressed, grey at rest, red
                                      ///< stretched; overrides colorSpringsByType
  double strainForFullColor = 0.1;    ///< |strain| that gets the full blue or red
  std::array<bool, 4> springTypeVisible = {true, true, true, true};  ///< indexed by SpringType
  /// Widths by type, px. Bending springs lie along structural ones in a cloth: drawn first and
  /// wider, they show as an orange border around the structural lines.
  std::array<double, 4> springWidthPx = {2.0, 1.0, 4.0, 2.0};

  // Particles.
  bool showParticles = true;
  double minParticleRadiusPx = 2.5;    ///< a particle is drawn at least this large
  double pinnedScale = 1.6;            ///< pinned particles: this much larger, and darker
  double ambientTemperature = 293.15;  ///< K; particles at another temperature glow like fire
  double hotTemperature = 900;         ///< K; at and above: light yellow

  // Obstacles, Box2D shapes, joints.
  bool showObstacles = true;
  bool showShapes = true;
  bool showJoints = true;
  double outlineWidthPx = 2.0;  ///< obstacle edges and shape outlines
  double jointWidthPx = 1.5;    ///< joint lines
  double anchorRadiusPx = 3.0;  ///< joint anchor dots

  bool springVisible(SpringType type) const { return springTypeVisible[static_cast<int>(type)]; }
  void setSpringVisible(SpringType type, bool visible) {
    springTypeVisible[static_cast<int>(type)] = visible;
  }
  double springWidth(SpringType type) const { return springWidthPx[static_cast<int>(type)]; }
};

}  // namespace a6
