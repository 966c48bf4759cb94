// The out-of-process StudentCode: each request goes to the sandboxed probe over a pipe, and
// comes back as plain data. A crash, a timeout or garbage fails that request with the reason,
// and the next request starts a fresh probe.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "harness/student_code.h"
#include "sandbox.h"

namespace a6::grader {

class ProbeClient final : public harness::StudentCode {
 public:
  /// `probe`: the linked probe executable; `workRoot`: where fresh working directories go.
  ProbeClient(std::filesystem::path probe, std::filesystem::path workRoot, Limits limits);
  ~ProbeClient() override;

  /// The wall-clock limit for the next requests (the rubric's per-test limit), s.
  void setRequestTimeout(double seconds);

  harness::SpringForceResult springForce(const harness::SpringForceRequest&) override;
  harness::ForcesResult forces(const harness::ForcesRequest&) override;
  harness::SimulateResult simulate(const harness::SimulateRequest&) override;
  harness::ClothResult buildCloth(const ClothSpec&) override;
  harness::ParticlesResult emit(const harness::EmitRequest&) override;
  harness::ParticlesResult runParticles(const harness::ParticleRunRequest&) override;
  harness::Box2DResult runBox2D(const harness::Box2DRequest&) override;
  harness::SceneResult runScene(const harness::SceneRequest&) override;

  /// Everything the probe printed so far (capped), for the report; never parsed.
  std::string output() const;
  /// How many probes were started (1 + restarts after crashes and timeouts).
  int starts() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace a6::grader
