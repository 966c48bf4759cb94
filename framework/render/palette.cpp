#include "render/palette.h"

#include <algorithm>
#include <cmath>

namespace a6::palette {

Rgba mix(Rgba a, Rgba b, double t) {
  t = std::clamp(t, 0.0, 1.0);
  auto channel = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (double(y) - double(x)) * t));
  };
  return Rgba{channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b), channel(a.a, b.a)};
}

Rgba springColor(SpringType type) {
  switch (type) {
    case SpringType::Structural:
      return kStructural;
    case SpringType::Shear:
      return kShear;
    case SpringType::Bending:
      return kBending;
    case SpringType::Other:
      break;
  }
  return kOtherSpring;
}

Rgba strainColor(double strain, double full) {
  if (!std::isfinite(strain) || !(full > 0)) return kAtRest;
  const double t = strain / full;
  return t < 0 ? mix(kAtRest, kCompressed, -t) : mix(kAtRest, kStretched, t);
}

Rgba temperatureColor(double temperature, double ambient, double hot) {
  static constexpr Rgba kSmoke{125, 125, 125, 255}, kCold{150, 190, 235, 255};
  // Stops from ambient (u = 0) to hot (u = 1).
  static constexpr struct Stop {
    double u;
    Rgba color;
  } kStops[] = {{0.00, kSmoke},
                {0.15, {140, 50, 40, 255}},    // dark red
                {0.40, {220, 40, 20, 255}},    // red
                {0.65, {250, 130, 20, 255}},   // orange
                {0.85, {255, 200, 30, 255}},   // yellow
                {1.00, {255, 235, 90, 255}}};  // light yellow (white would vanish on the
                                               // light background)
  if (!std::isfinite(temperature) || !(hot > ambient)) return kSmoke;
  if (temperature < ambient) return mix(kSmoke, kCold, (ambient - temperature) / 100.0);
  const double u = std::min((temperature - ambient) / (hot - ambient), 1.0);
  for (size_t k = 1; k < std::size(kStops); ++k) {
    if (u <= kStops[k].u) {
      const Stop &a = kStops[k - 1], &b = kStops[k];
      return mix(a.color, b.color, (u - a.u) / (b.u - a.u));
    }
  }
  return kStops[std::size(kStops) - 1].color;
}

Rgba bodyFill(int body) {
  static constexpr Rgba kFills[] = {{240, 170, 120, 255}, {150, 190, 235, 255},
                                    {235, 210, 110, 255}, {195, 160, 225, 255},
                                    {150, 210, 175, 255}, {235, 150, 175, 255}};
  if (body < 0) return kGroundFill;
  return kFills[body % std::size(kFills)];
}

Rgba outlineOf(Rgba fill) {
  if (fill == kGroundFill) return kGroundEdge;
  return mix(Rgba{0, 0, 0, fill.a}, fill, 0.45);
}

Rgba jointColor(const std::string& type) {
  if (type == "revolute") return {200, 30, 40, 255};
  if (type == "prismatic") return {130, 50, 190, 255};
  if (type == "distance") return {0, 140, 150, 255};
  if (type == "wheel") return {190, 110, 0, 255};
  if (type == "mouse") return {230, 0, 170, 255};
  return {50, 50, 50, 255};
}

}  // namespace a6::palette
