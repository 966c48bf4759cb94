// The renderer's colours, in one place: tests read them to know what a pixel should be.
#pragma once

#include <string>

#include "a6/spring.h"
#include "image/image.h"

namespace a6::palette {

inline constexpr Rgba kBackground{246, 244, 238, 255};
// Obstacles: half-planes and circles.
inline constexpr Rgba kSolid{196, 186, 168, 255};
inline constexpr Rgba kSolidEdge{120, 108, 90, 255};
// Particles.
inline constexpr Rgba kParticle{60, 60, 75, 255};
inline constexpr Rgba kPinned{0, 0, 0, 255};
// Springs by type.
inline constexpr Rgba kStructural{40, 90, 190, 255};   // blue
inline constexpr Rgba kShear{30, 150, 80, 255};        // green
inline constexpr Rgba kBending{235, 135, 20, 255};     // orange
inline constexpr Rgba kOtherSpring{70, 70, 80, 255};   // slate
inline constexpr Rgba kPlainSpring{90, 90, 100, 255};  // neither type nor strain colours
// Springs by strain.
inline constexpr Rgba kCompressed{30, 80, 230, 255};  // blue
inline constexpr Rgba kAtRest{150, 150, 150, 255};    // grey
inline constexpr Rgba kStretched{220, 40, 30, 255};   // red
// Box2D.
inline constexpr Rgba kGroundFill{150, 170, 140, 255};
inline constexpr Rgba kGroundEdge{70, 90, 60, 255};

/// A spring's colour by its type.
Rgba springColor(SpringType type);
/// A spring's colour by its strain (l - l0) / l0: kCompressed at -full or less, kAtRest at 0,
/// kStretched at +full or more, linear in between (per channel, rounded).
Rgba strainColor(double strain, double full);
/// A particle's colour by its temperature T (K), like fire: at `hot` K and above light yellow,
/// then yellow, orange, red, fading to smoke grey at `ambient`; below ambient, towards light blue.
Rgba temperatureColor(double temperature, double ambient, double hot);
/// A Box2D body's fill (a fixed cycle of pastel colours by body index; the ground is -1).
Rgba bodyFill(int body);
/// The outline of a shape filled with `fill`: the same hue, darker.
Rgba outlineOf(Rgba fill);
/// A joint's colour by its type name (revolute, prismatic, distance, wheel, mouse, other).
Rgba jointColor(const std::string& type);
/// Linear interpolation, rounded per channel; t clamped to [0, 1].
Rgba mix(Rgba a, Rgba b, double t);

}  // namespace a6::palette
