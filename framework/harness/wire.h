// The harness's requests and results as JSON, for the pipe between the grader and the probe.
//
// Doubles must survive the trip exactly, NaN and infinities included (a NaN from student code
// must reach the grader as NaN): encode every double so that decode(encode(x)) is bit-identical.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "harness/student_code.h"

namespace a6::wire {

/// A request: {"kind": "springForce" | "forces" | "simulate" | "buildCloth" | "emit" |
/// "runParticles" | "runBox2D" | "runScene", "body": {...}}.
nlohmann::json encodeSpringForce(const harness::SpringForceRequest&);
nlohmann::json encodeForces(const harness::ForcesRequest&);
nlohmann::json encodeSimulate(const harness::SimulateRequest&);
nlohmann::json encodeBuildCloth(const ClothSpec&);
nlohmann::json encodeEmit(const harness::EmitRequest&);
nlohmann::json encodeRunParticles(const harness::ParticleRunRequest&);
nlohmann::json encodeRunBox2D(const harness::Box2DRequest&);
nlohmann::json encodeRunScene(const harness::SceneRequest&);

/// Answers one encoded request with `code` (the probe calls this with the in-process
/// implementation); returns the encoded result. Never throws: a malformed request gives a
/// result whose error says so.
nlohmann::json serve(harness::StudentCode& code, const nlohmann::json& request);

/// Decoding results: each throws std::runtime_error with a clear message on malformed input
/// (the ProbeClient turns that into the result's error: "garbage from the probe: ...").
harness::SpringForceResult decodeSpringForce(const nlohmann::json&);
harness::ForcesResult decodeForces(const nlohmann::json&);
harness::SimulateResult decodeSimulate(const nlohmann::json&);
harness::ClothResult decodeBuildCloth(const nlohmann::json&);
harness::ParticlesResult decodeParticles(const nlohmann::json&);
harness::Box2DResult decodeRunBox2D(const nlohmann::json&);
harness::SceneResult decodeRunScene(const nlohmann::json&);

/// Framing on a byte stream: a 4-byte little-endian length, then that many bytes of JSON text.
std::string frame(const nlohmann::json& message);

}  // namespace a6::wire
