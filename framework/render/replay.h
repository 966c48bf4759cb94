// A replay: a scene's snapshots at a series of frames, packed small for the HTML report's player
// (positions as 16-bit steps on the scene's view, base64), with the energy of every frame.
// a6_render_solution --replays packs the reference runs (tests/golden/replays/, graders'
// material); the grader packs the student's run the same way and sets the two side by side.
// Plain data: no GL, no student code.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenes/snapshot.h"

namespace a6::replay {

/// The energy of one snapshot, J. Known for particles (mass-spring systems and particle
/// systems, 0 while there are none); Box2D's bodies are not in a snapshot with their masses, so
/// unknown there (a Recording's `energies`, the scene's own sum, stand in).
struct Energy {
  double kinetic = 0;    ///< sum of ½ m |v|²
  double potential = 0;  ///< sum of -m g·x (gravity) and ½ ks (l - l0)² (springs)
  bool known = false;
  double total() const { return kinetic + potential; }
};

/// The energy of `s`, with the springs of the run (`springs`: a lean snapshot has none of its
/// own) and the scene's gravity, m/s².
Energy energyOf(const Snapshot& s, const std::vector<SpringData>& springs, const Vec2& gravity);

/// A run to pack: snapshots[k] after frames[k] frames of frameDt seconds. Only the first
/// snapshot needs its springs and obstacles (they do not move).
struct Recording {
  std::string scene;
  double frameDt = 1.0 / 60;  ///< s
  Vec2 gravity = Vec2(0, -9.81);
  std::vector<int> frames;
  std::vector<Snapshot> snapshots;
  /// The scene's own energies per snapshot (harness::SceneResult::energies), used where the
  /// snapshots cannot tell them (Box2D bodies); may be empty.
  std::vector<SceneEnergy> energies = {};
};

/// The packed form, as the player reads it:
///   scene, frameDt, gravity [x, y], frames [...], view [cx, cy, height], unit (m per step),
///   radius (m), springs [i, j, type, ...], planes [[nx, ny, offset]...], circles [[x, y, r]...],
///   shapes [[kind (0 circle, 1 polygon, 2 edge), points, radius]...] (from the first frame),
///   counts [[particles, joints]...] per frame,
///   data: base64 of little-endian int16 pairs, per frame: the particles, the shapes' points (a
///   circle: its centre and a point on its rim at its angle), each joint's four points
///   (centre A, anchor A, anchor B, centre B; the ground's side collapsed on its anchor);
///   -32768 where a number is not finite,
///   energy [[kinetic, potential]...] per frame, or [] when unknown,
///   drawn: true when the particles are drawn at random (a particle system: a finite lifetime),
///   so that runs compare by distribution, never particle by particle.
nlohmann::json pack(const Recording& recording);

/// `size` bytes as base64 (RFC 4648, with '=' padding): the packed data, and the report's
/// embedded images.
std::string toBase64(const unsigned char* bytes, std::size_t size);

/// A packed recording read back: per frame, the particles' and the shapes' points, m (NaN where
/// the packed number was not finite), and the energies.
struct Unpacked {
  std::string scene;
  double frameDt = 1.0 / 60;
  Vec2 gravity = Vec2(0, -9.81);
  View view;
  std::vector<int> frames;
  std::vector<std::vector<Vec2>> particles;
  std::vector<std::vector<Vec2>> shapePoints;
  std::vector<Energy> energy;
  bool drawn = false;
};
/// Throws std::runtime_error naming what is missing or malformed.
Unpacked unpack(const nlohmann::json& packed);

/// The frames a replay shows: about `count` evenly spaced from 0 to `last`, 0 and `last`
/// included, in order, without repeats.
std::vector<int> replayFrames(int last, int count = 60);

}  // namespace a6::replay
