// Benchmark: the solution's MassSpringSystem::step on cloths of n = 16 ... 256 cells per side,
// next to a plain structure-of-arrays kernel of the same physics, in the same binary.
//
// Design note: what the kernel is for.
// The kernel is the practical limit of this physics on this machine: flat arrays, the spring
// loop written out by hand, no virtual calls, no std::function, no pointers to chase. It is
// deliberately plain (no SIMD intrinsics, no threads), so that it measures what a careful
// scalar implementation reaches, not what heroic tuning reaches. The targets (issue text):
// the solution reaches at least half of the kernel's rate, and its cost is linear in the
// number of springs. Both are printed at the end of every run, with the figures they rest on.
//
// Run it from a Release build (see tests/bench/README.md):
//   a6_cloth_step_bench --benchmark_out=cloth_step.json --benchmark_out_format=json
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "a6/cloth.h"
#include "a6/mass_spring_system.h"

namespace {

// The cloth every benchmark steps: the framework's default constants (those the viewer starts
// with), with structural, shear and bending springs, top corners pinned, gravity on. The
// constants are per particle and per spring, so one step size is stable for every n.
a6::ClothSpec benchSpec(int n) {
  a6::ClothSpec spec;
  spec.n = n;
  spec.shear = true;
  spec.bending = true;
  spec.pinTopCorners = true;
  return spec;
}
// One substep of a 60 Hz frame split in 10, as the cloth scenes do (scenes/mass_spring_scenes.cpp).
constexpr double kDt = 1.0 / 600;

// The number of springs buildCloth makes for benchSpec(n): structural, shear and bending
// (docs/handout.md, "Task 4").
long clothSprings(long n) { return 2 * n * (n + 1) + 2 * n * n + 2 * (n - 1) * (n + 1); }

// ---------------------------------------------------------------------------------------------
// The structure-of-arrays kernel: the same physics as the slides' step, on flat arrays.
struct SoACloth {
  // Particles.
  std::vector<double> x, y, vx, vy, fx, fy, m, invMass;
  std::vector<unsigned char> pinned;
  // Springs: particle indices of p1 (i) and p2 (j), rest length, stiffness, damping.
  std::vector<int> i, j;
  std::vector<double> l0, ks, kd;
  double gx = 0, gy = 0;

  // A copy of a mass-spring system with gravity as its only external force.
  explicit SoACloth(const a6::MassSpringSystem& system) {
    std::unordered_map<const a6::Particle*, int> index;
    for (const a6::Particle& p : system.particles) {
      index[&p] = static_cast<int>(x.size());
      x.push_back(p.x.x());
      y.push_back(p.x.y());
      vx.push_back(p.v.x());
      vy.push_back(p.v.y());
      m.push_back(p.m);
      invMass.push_back(1.0 / p.m);
      pinned.push_back(p.pinned ? 1 : 0);
    }
    fx.assign(x.size(), 0.0);
    fy.assign(x.size(), 0.0);
    for (const a6::Spring& s : system.springs) {
      i.push_back(index.at(s.p1));
      j.push_back(index.at(s.p2));
      l0.push_back(s.restLength);
      ks.push_back(s.ks);
      kd.push_back(s.kd);
    }
    gx = system.env.gravity.x();
    gy = system.env.gravity.y();
  }

  void step(double dt) {
    const std::size_t np = x.size(), ns = i.size();
    // 1. External force: m g.
    for (std::size_t k = 0; k < np; ++k) {
      fx[k] = m[k] * gx;
      fy[k] = m[k] * gy;
    }
    // 2. Springs: f2 = -ks (l - l0) e - kd v_rel e on j, the opposite on i.
    for (std::size_t s = 0; s < ns; ++s) {
      const int a = i[s], b = j[s];
      const double dx = x[b] - x[a], dy = y[b] - y[a];
      const double l = std::sqrt(dx * dx + dy * dy);
      if (l < 1e-12) continue;
      const double invL = 1.0 / l;  // one division, two multiplications
      const double ex = dx * invL, ey = dy * invL;
      const double vRel = (vx[b] - vx[a]) * ex + (vy[b] - vy[a]) * ey;
      const double magnitude = -ks[s] * (l - l0[s]) - kd[s] * vRel;
      const double f2x = magnitude * ex, f2y = magnitude * ey;
      fx[b] += f2x;
      fy[b] += f2y;
      fx[a] -= f2x;
      fy[a] -= f2y;
    }
    // 3. Symplectic Euler, pinned particles skipped.
    for (std::size_t k = 0; k < np; ++k) {
      if (pinned[k]) continue;
      vx[k] += fx[k] * invMass[k] * dt;
      vy[k] += fy[k] * invMass[k] * dt;
      x[k] += vx[k] * dt;
      y[k] += vy[k] * dt;
    }
  }
};

a6::MassSpringSystem makeCloth(int n) {
  a6::MassSpringSystem system;
  a6::buildCloth(system, benchSpec(n));
  return system;
}

// ---------------------------------------------------------------------------------------------
// One-off check: the kernel and the solution agree to round-off after a few steps on n = 16.
struct Agreement {
  double relX = 0, relV = 0;  ///< largest difference over largest magnitude, x and v
  std::string error;          ///< empty when they agree within 1e-9
};
constexpr int kCheckSteps = 20;

Agreement kernelAgreesWithSolution() {
  a6::MassSpringSystem system = makeCloth(16);
  SoACloth kernel(system);
  if (kernel.i.size() != static_cast<std::size_t>(clothSprings(16))) {
    return {0, 0,
            "buildCloth made " + std::to_string(kernel.i.size()) + " springs for n=16, expected " +
                std::to_string(clothSprings(16))};
  }
  for (int k = 0; k < kCheckSteps; ++k) {
    system.step(kDt);
    kernel.step(kDt);
  }
  // Largest difference relative to the largest magnitude, positions and velocities apart.
  double dx = 0, sx = 0, dv = 0, sv = 0;
  for (std::size_t k = 0; k < kernel.x.size(); ++k) {
    const a6::Particle& p = system.particles[k];
    dx = std::max({dx, std::abs(p.x.x() - kernel.x[k]), std::abs(p.x.y() - kernel.y[k])});
    sx = std::max({sx, std::abs(p.x.x()), std::abs(p.x.y())});
    dv = std::max({dv, std::abs(p.v.x() - kernel.vx[k]), std::abs(p.v.y() - kernel.vy[k])});
    sv = std::max({sv, std::abs(p.v.x()), std::abs(p.v.y())});
  }
  Agreement result{dx / sx, dv / sv, ""};
  if (!(result.relX <= 1e-9) || !(result.relV <= 1e-9)) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer,
                  "kernel and solution disagree after %d steps on n=16: relative difference "
                  "%.3g in positions, %.3g in velocities (allowed 1e-9)",
                  kCheckSteps, result.relX, result.relV);
    result.error = buffer;
  }
  return result;
}

const Agreement& agreement() {
  static const Agreement result = kernelAgreesWithSolution();
  return result;
}

// Every position still finite: the step size kept the cloth stable while it was timed.
template <typename IsFinite>
bool stayedFinite(std::size_t count, IsFinite isFinite) {
  for (std::size_t k = 0; k < count; ++k) {
    if (!isFinite(k)) return false;
  }
  return true;
}

void setCounters(benchmark::State& state, long springs) {
  state.counters["springs"] = static_cast<double>(springs);
  state.counters["springs_per_s"] =
      benchmark::Counter(static_cast<double>(springs) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

// ---------------------------------------------------------------------------------------------
// The solution: MassSpringSystem::step, the student's real path (no reference force models).
void BM_SolutionStep(benchmark::State& state) {
  if (!agreement().error.empty()) {
    state.SkipWithError(agreement().error.c_str());
    return;
  }
  a6::MassSpringSystem system = makeCloth(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    system.step(kDt);
    benchmark::ClobberMemory();
  }
  const auto& particles = system.particles;
  if (!stayedFinite(particles.size(), [&](std::size_t k) { return particles[k].x.allFinite(); })) {
    state.SkipWithError("the cloth became non-finite: lower kDt");
  }
  setCounters(state, static_cast<long>(system.springs.size()));
}

// The kernel: SoACloth::step on a copy of the same cloth.
void BM_SoAKernelStep(benchmark::State& state) {
  if (!agreement().error.empty()) {
    state.SkipWithError(agreement().error.c_str());
    return;
  }
  SoACloth kernel(makeCloth(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    kernel.step(kDt);
    benchmark::ClobberMemory();
  }
  if (!stayedFinite(kernel.x.size(), [&](std::size_t k) {
        return std::isfinite(kernel.x[k]) && std::isfinite(kernel.y[k]);
      })) {
    state.SkipWithError("the cloth became non-finite: lower kDt");
  }
  setCounters(state, static_cast<long>(kernel.i.size()));
}

// n = 16, 32, 64, 128, 256; three repetitions of at least 0.3 s each, the median reported.
void clothSizes(benchmark::internal::Benchmark* b) {
  b->ArgName("n")->RangeMultiplier(2)->Range(16, 256);
  b->MinTime(0.3)->Repetitions(3)->DisplayAggregatesOnly(true);
  b->Unit(benchmark::kMicrosecond);
}
BENCHMARK(BM_SolutionStep)->Apply(clothSizes);
BENCHMARK(BM_SoAKernelStep)->Apply(clothSizes);

// ---------------------------------------------------------------------------------------------
// The console reporter, which also keeps the figures for the summary.
struct Figure {
  double springs = 0, springsPerSecond = 0;
};

// Whether a run failed or was skipped: Google Benchmark 1.7 says so in Run::error_occurred,
// 1.8 and later in Run::skipped (error_occurred is gone). The first overload exists only where
// error_occurred does, and is preferred there (an int argument matches it exactly).
template <class Run>
auto didNotRun(const Run& run, int) -> decltype(static_cast<bool>(run.error_occurred)) {
  return run.error_occurred;
}
template <class Run>
auto didNotRun(const Run& run, long) -> decltype(static_cast<bool>(run.skipped)) {
  return static_cast<bool>(run.skipped);
}

class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  using ConsoleReporter::ConsoleReporter;
  // figures[function][n]: the median over repetitions, or the single run without repetitions.
  std::map<std::string, std::map<int, Figure>> figures;

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
      const auto springs = run.counters.find("springs");
      const auto rate = run.counters.find("springs_per_s");
      if (didNotRun(run, 0) || !(median || single) || springs == run.counters.end() ||
          rate == run.counters.end()) {
        continue;
      }
      const std::string& args = run.run_name.args;  // "n:16"
      const int n = std::stoi(args.substr(args.find(':') + 1));
      figures[run.run_name.function_name][n] = Figure{springs->second, rate->second};
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

// The table and the two verdicts of the issue: ratio >= 0.5 at every n, and linear scaling
// (time per step against springs has a log-log slope near 1).
void printSummary(const SummaryReporter& reporter) {
  if (!agreement().error.empty()) {
    std::printf("\nNo figures: %s\n", agreement().error.c_str());
    return;
  }
  const auto solution = reporter.figures.find("BM_SolutionStep");
  const auto kernel = reporter.figures.find("BM_SoAKernelStep");
  if (solution == reporter.figures.end() || kernel == reporter.figures.end()) {
    std::printf("\nSummary: needs both BM_SolutionStep and BM_SoAKernelStep (check the filter)\n");
    return;
  }
  std::printf(
      "\nKernel vs solution after %d steps on n=16: relative difference %.2g in x, "
      "%.2g in v (allowed 1e-9)\n",
      kCheckSteps, agreement().relX, agreement().relV);
  std::printf("Cloth step, springs per second (median of the repetitions, CPU time)\n");
  std::printf("%6s %9s %16s %16s %8s %14s %14s\n", "n", "springs", "solution/s", "kernel/s",
              "ratio", "solution ns/sp", "kernel ns/sp");
  double minRatio = 1e300;
  int minRatioN = 0;
  double minRate = 1e300, maxRate = 0;
  std::vector<double> logSprings, logTime;
  for (const auto& [n, sol] : solution->second) {
    const auto ker = kernel->second.find(n);
    if (ker == kernel->second.end()) continue;
    const double ratio = sol.springsPerSecond / ker->second.springsPerSecond;
    std::printf("%6d %9.0f %16.4g %16.4g %8.3f %14.3f %14.3f\n", n, sol.springs,
                sol.springsPerSecond, ker->second.springsPerSecond, ratio,
                1e9 / sol.springsPerSecond, 1e9 / ker->second.springsPerSecond);
    if (ratio < minRatio) {
      minRatio = ratio;
      minRatioN = n;
    }
    minRate = std::min(minRate, sol.springsPerSecond);
    maxRate = std::max(maxRate, sol.springsPerSecond);
    logSprings.push_back(std::log(sol.springs));
    logTime.push_back(std::log(sol.springs / sol.springsPerSecond));
  }
  if (logSprings.empty()) return;
  std::printf("Target: solution >= 0.5 x kernel at every n: %s (lowest ratio %.3f at n = %d)\n",
              minRatio >= 0.5 ? "MET" : "NOT MET", minRatio, minRatioN);
  if (logSprings.size() < 2) return;
  // Least-squares slope of log(time per step) against log(springs): 1 is linear.
  const double count = static_cast<double>(logSprings.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < logSprings.size(); ++k) {
    mx += logSprings[k] / count;
    my += logTime[k] / count;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < logSprings.size(); ++k) {
    sxy += (logSprings[k] - mx) * (logTime[k] - my);
    sxx += (logSprings[k] - mx) * (logSprings[k] - mx);
  }
  const double slope = sxy / sxx;
  std::printf(
      "Target: solution linear in the spring count: %s (time per step ~ springs^%.3f, "
      "linear means an exponent within [0.9, 1.1]; springs/s from %.3g to %.3g)\n",
      slope >= 0.9 && slope <= 1.1 ? "MET" : "NOT MET", slope, minRate, maxRate);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SummaryReporter reporter(isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_ColorTabular
                                                 : benchmark::ConsoleReporter::OO_Tabular);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printSummary(reporter);
  benchmark::Shutdown();
  return agreement().error.empty() ? 0 : 1;
}
