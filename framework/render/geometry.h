// The CPU half of the renderer: a Snapshot becomes a list of coloured triangles, in the order
// they are painted (later triangles cover earlier ones). No GL here, so it is testable and
// deterministic: every coordinate is computed in double and rounded once to float.
//
// Painting order: obstacles (half-planes, circles), Box2D shapes, springs (bending, shear,
// structural, other), particles (free, then pinned), joints.
#pragma once

#include <cstdint>
#include <vector>

#include "render/render_options.h"
#include "scenes/snapshot.h"

namespace a6 {

/// One vertex: position in normalized device coordinates, colour RGBA8.
struct Vertex {
  float x = 0, y = 0;
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};
static_assert(sizeof(Vertex) == 12, "Vertex must be tightly packed");

/// The triangles (3 vertices each) that draw `snapshot` into a width x height image.
std::vector<Vertex> buildGeometry(const Snapshot& snapshot, int width, int height,
                                  const RenderOptions& options);

/// The number of segments of a particle's disc.
inline constexpr int kParticleSegments = 20;

}  // namespace a6
