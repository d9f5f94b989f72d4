// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// How close the red-black sweeps of (10)-(11) come to the machine's memory
// bandwidth. Builds the band of a sphere's points, runs the implicit step
// (AllenCahnSolver::Diffuse) with a fixed number of sweeps, and counts the
// bytes a sweep must move per node update:
//   six neighbour indices 24, phi read 8 and written 8, phi^n 8, w 8, and the
//   other colour's phi 8 (read once a half sweep if the neighbours' values
//   stay in the cache while a brick is swept): 64 bytes;
// plus Diffuse's copy of phi into phi^n (16 bytes a node). The same threads
// then run a STREAM triad a[i] = b[i] + s c[i] (24 bytes an element, the
// STREAM convention: no write-allocate traffic counted, as for the sweeps).
// Prints medians of --repeat runs as a Markdown table; the step and a triad
// alternate, and the ratio is the median of the runs' own ratios.
//
//   sweep_bandwidth [--cells 512] [--points 200000] [--sweeps 20] [--repeat 9] [--threads 1 2]
#include "nvAllenCahnSolver.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvReconstruction.h"
#include "nvSampling.h"
#include "nvTruncatedDistance.h"
#include "nvTestUtilities.h" // nvtest::SpherePoints

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
constexpr double BytesPerUpdate = 24.0 + 8.0 + 8.0 + 8.0 + 8.0 + 8.0;
constexpr double BytesPerCopiedNode = 16.0;

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// A STREAM triad a[i] = b[i] + s c[i] over arrays of n doubles.
class Triad
{
public:
  explicit Triad(std::int64_t n)
    : A(static_cast<std::size_t>(n))
    , B(A.size())
    , C(A.size())
  {
    this->Loop([this](std::int64_t i) { this->A[i] = 0.0, this->B[i] = 1.0, this->C[i] = 2.0; }); // first touch
  }
  /// GB/s of one pass (24 bytes an element).
  double Run()
  {
    const double start = Now();
    this->Loop([this](std::int64_t i) { this->A[i] = this->B[i] + 3.0 * this->C[i]; });
    return 24.0 * static_cast<double>(this->A.size()) / (Now() - start) / 1e9;
  }

private:
  template <typename Fn>
  void Loop(Fn fn)
  {
    nv::ParallelFor(0, static_cast<std::int64_t>(this->A.size()), 1 << 16, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t i = begin; i < end; ++i)
      {
        fn(i);
      }
    });
  }
  std::vector<double> A, B, C;
};
} // namespace

int main(int argc, char* argv[])
{
  int cells = 512, sweeps = 20, repeat = 9;
  std::int64_t points = 200000; // a Fibonacci spiral on a sphere of radius 0.5
  std::vector<int> threads = { 1, 2 };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--cells" && i + 1 < argc)
      cells = std::atoi(argv[++i]);
    else if (arg == "--points" && i + 1 < argc)
      points = std::atoll(argv[++i]);
    else if (arg == "--sweeps" && i + 1 < argc)
      sweeps = std::atoi(argv[++i]);
    else if (arg == "--repeat" && i + 1 < argc)
      repeat = std::atoi(argv[++i]);
    else if (arg == "--threads")
    {
      threads.clear();
      while (i + 1 < argc && argv[i + 1][0] != '-')
        threads.push_back(std::atoi(argv[++i]));
    }
    else
    {
      std::fprintf(stderr, "usage: %s [--cells N] [--points N] [--sweeps N] [--repeat N] [--threads T ...]\n", argv[0]);
      return 2;
    }
  }

  // The band of Table 2's large sphere: l = 4 h, xi = 2 h, h = 1 / cells.
  const double center[3] = { 0.0, 0.0, 0.0 };
  const std::vector<double> xyz = nvtest::SpherePoints(static_cast<int>(points), 0.5, center);
  nv::Settings settings;
  settings.SampleSpacing = 1.0 / cells;
  settings.OffsetDistance = 4.0 * settings.SampleSpacing;
  const double bounds[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  const nv::Plan plan = nv::MakePlan(settings, bounds, nv::SamplingStatistics{});
  if (!plan.Valid())
  {
    std::fprintf(stderr, "%s\n", plan.Error.c_str());
    return 1;
  }
  nv::Parameters parameters = plan.Scheme;
  parameters.GaussSeidelTolerance = 0.0; // exactly `sweeps` sweeps a step
  parameters.MaximumNumberOfSweeps = sweeps;
  const nv::TruncatedDistance distance(plan.TheGrid, xyz.data(), points, parameters.Reach());
  const nv::NarrowBand band = nv::BuildNarrowBand(distance, parameters);
  const double nodes = static_cast<double>(band.Size());
  const double bytes = nodes * (sweeps * BytesPerUpdate + BytesPerCopiedNode);

  std::printf("Sphere of %lld points, grid %lldx%lldx%lld, %.0f band nodes; %d sweeps a step, "
              "%.0f bytes a node update; medians of %d runs.\n\n",
    static_cast<long long>(points), static_cast<long long>(plan.TheGrid.Dims[0]),
    static_cast<long long>(plan.TheGrid.Dims[1]), static_cast<long long>(plan.TheGrid.Dims[2]), nodes, sweeps,
    BytesPerUpdate, repeat);
  std::printf("| threads | step (s) | M node updates/s | sweeps GB/s | triad GB/s | sweeps ÷ triad |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int t : threads)
  {
    nv::WithThreads(t, [&]() {
      nv::AllenCahnSolver solver(band, parameters);
      // Three arrays of at least 64 MB each, well beyond any cache.
      Triad triad(std::max<std::int64_t>(8 << 20, band.Size()));
      // The step and a triad in turn, so that both see the machine in the
      // same state (others share it): the ratio is taken run by run.
      std::vector<double> seconds, triads, ratios;
      for (int r = 0; r < repeat; ++r)
      {
        const double start = Now();
        solver.Diffuse();
        seconds.push_back(Now() - start);
        triads.push_back(triad.Run());
        ratios.push_back(bytes / seconds.back() / 1e9 / triads.back());
      }
      const double step = Median(seconds);
      std::printf("| %d | %.3f | %.0f | %.1f | %.1f | %.0f %% |\n", t, step, nodes * sweeps / step / 1e6,
        bytes / step / 1e9, Median(triads), 100.0 * Median(ratios));
      std::fflush(stdout);
    });
  }
  return 0;
}
