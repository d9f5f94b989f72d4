// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end (Filters/Core/Device) against the CPU core.
//
//   TestCoreDevice          its kernels through the host launcher: phi on
//                           the band is the CPU core's solver's bit for bit
//                           (the same formulas, the same reductions), on a
//                           sphere and a torus, both edge-stopping functions
//                           and the literal stopping rule;
//   TestCoreDevice cuda     the same kernels through the CUDA launcher, on
//                           a GPU (scripts/test-gpu.sh): phi within 1e-9 of
//                           the CPU core's (fused multiply-adds and the
//                           reductions' order change the last bits).
#include "nvAllenCahnSolver.h"
#include "nvDeviceEvolution.h"
#include "nvDeviceLauncher.h"
#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvTestUtilities.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#ifndef NV_TEST_NAME
#define NV_TEST_NAME "TestCoreDevice"
#endif

namespace
{
bool OnGpu = false; ///< the CUDA launcher instead of the host launcher

std::unique_ptr<nv::device::EvolutionLauncher> Launcher()
{
  if (!OnGpu)
  {
    return nv::device::MakeHostLauncher();
  }
  std::string why;
  std::unique_ptr<nv::device::EvolutionLauncher> launcher = nv::device::MakeCudaLauncher(why);
  if (!launcher)
  {
    std::printf("FAILED: no CUDA launcher: %s\n", why.c_str());
  }
  return launcher;
}

/// Points on a torus of radii R (the tube's centre) and r about the z axis.
std::vector<double> TorusPoints(int n, double R, double r)
{
  std::vector<double> xyz;
  const int around = static_cast<int>(std::sqrt(n * R / r));
  const int tube = std::max(3, n / around);
  for (int a = 0; a < around; ++a)
  {
    const double u = 2.0 * M_PI * a / around;
    for (int b = 0; b < tube; ++b)
    {
      const double v = 2.0 * M_PI * (b + 0.5 * (a % 2)) / tube;
      xyz.push_back((R + r * std::cos(v)) * std::cos(u));
      xyz.push_back((R + r * std::cos(v)) * std::sin(u));
      xyz.push_back(r * std::sin(v));
    }
  }
  return xyz;
}

/// The band of the points on a grid of spacing h padded for offset l.
nv::NarrowBand BandOf(const std::vector<double>& xyz, const nv::Parameters& parameters)
{
  double bounds[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (std::size_t p = 0; p < xyz.size(); p += 3)
  {
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], xyz[p + a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], xyz[p + a]);
    }
  }
  const nv::Grid grid = nv::MakeGrid(bounds, parameters.Spacing,
    nv::GridPadding(parameters.Reach(), parameters.Spacing));
  const nv::TruncatedDistance distance(
    grid, xyz.data(), static_cast<std::int64_t>(xyz.size() / 3), parameters.Reach());
  return nv::BuildNarrowBand(distance, parameters);
}

/// The device back end's phi against the CPU core's solver on one band.
void Compare(const char* what, const std::vector<double>& xyz, const nv::Parameters& parameters)
{
  const nv::NarrowBand band = BandOf(xyz, parameters);
  NV_CHECK(band.Size() > 1000);

  nv::AllenCahnSolver solver(band, parameters);
  const std::vector<nv::StepReport> cpu = solver.Run();

  std::unique_ptr<nv::device::EvolutionLauncher> launcher = Launcher();
  if (!launcher)
  {
    NV_CHECK(false);
    return;
  }
  std::vector<nv::StepReport> device;
  const nv::BandValues phi = nv::device::Evolve(band, parameters, *launcher, nullptr, device);

  NV_CHECK(phi.size() == solver.GetPhi().size());
  NV_CHECK(device.size() == cpu.size());
  double largest = 0.0;
  for (std::size_t s = 0; s < phi.size() && s < solver.GetPhi().size(); ++s)
  {
    largest = std::max(largest, std::fabs(phi[s] - solver.GetPhi()[s]));
  }
  int sweepsCpu = 0, sweepsDevice = 0;
  for (std::size_t n = 0; n < cpu.size() && n < device.size(); ++n)
  {
    sweepsCpu += cpu[n].Sweeps;
    sweepsDevice += device[n].Sweeps;
    if (OnGpu)
    {
      NV_CHECK_NEAR(device[n].RelativeChange, cpu[n].RelativeChange, 1e-9);
    }
    else
    {
      NV_CHECK(device[n].RelativeChange == cpu[n].RelativeChange);
      NV_CHECK(device[n].Sweeps == cpu[n].Sweeps);
    }
  }
  std::printf("%s on %s: %lld band nodes, %zu steps, sweeps %d (CPU %d), max |phi - phi_CPU| %.3g\n", what,
    launcher->Name().c_str(), static_cast<long long>(band.Size()), device.size(), sweepsDevice, sweepsCpu, largest);
  NV_CHECK(largest <= (OnGpu ? 1e-9 : 0.0));
}

void TestSphere()
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  nv::Parameters p;
  p.OffsetDistance = 0.1;
  p.Spacing = 0.02;
  p.MaximumNumberOfIterations = 3;
  Compare("sphere, eq. (4), 3 steps", nvtest::SpherePoints(4000, 0.5, center), p);
  p.EdgeStoppingFunction = nv::EdgeStopping::Eq3;
  p.Domain = nv::Domain::WholeDomain;
  Compare("sphere, eq. (3), whole domain", nvtest::SpherePoints(4000, 0.5, center), p);
}

void TestTorus()
{
  nv::Parameters p;
  p.OffsetDistance = 0.08;
  p.Spacing = 0.02;
  // The paper's literal rule, within a cap.
  p.MaximumNumberOfIterations = 8;
  p.ConvergenceTolerance = 1e-5;
  Compare("torus, the literal stopping rule", TorusPoints(8000, 0.6, 0.25), p);
  p.ConvergenceTolerance = 0.02; // stops before the cap
  p.Relaxation = 1.0;            // plain Gauss-Seidel
  Compare("torus, tolerance 0.02, plain Gauss-Seidel", TorusPoints(8000, 0.6, 0.25), p);
}

} // namespace

int main(int argc, char* argv[])
{
  OnGpu = argc > 1 && std::strcmp(argv[1], "cuda") == 0;
  TestSphere();
  TestTorus();
  return nvtest::Result(NV_TEST_NAME);
}
