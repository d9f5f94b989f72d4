// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvDeviceEvolution.h"

#include "nvParallel.h"

#include <algorithm>
#include <cmath>

namespace nv
{
namespace device
{
namespace
{
/// Plain sweeps before the over-relaxation factor is estimated, as the CPU
/// core's solver (nvAllenCahnSolver.cxx says why 8).
constexpr int EstimationSweeps = 8;

/// The implicit step (10)-(11) by red-black sweeps, as
/// AllenCahnSolver::Diffuse: returns the sweeps, sets the last one's max
/// change; `omega` and `estimate` carry the over-relaxation between steps.
int Diffuse(EvolutionLauncher& launcher, const NarrowBand& band, const Parameters& parameters, double& omega,
  bool& estimate, double& lastChange)
{
  launcher.KeepPrevious();
  std::int64_t redBegin, redEnd, blackBegin, blackEnd;
  band.OwnedNodes(true, redBegin, redEnd);
  band.OwnedNodes(false, blackBegin, blackEnd);
  int sweeps = 0;
  double change = 0.0;
  double previousChange = 0.0;
  do
  {
    const double red = launcher.Relax(redBegin, redEnd, omega);
    const double black = launcher.Relax(blackBegin, blackEnd, omega);
    change = std::max(red, black);
    if (estimate && sweeps == EstimationSweeps && previousChange > 0.0)
    {
      // 2 / (1 + sqrt(1 - rho^2)) from the contraction of plain sweeps,
      // rho^2 (the CPU core's solver explains it).
      const double contraction = std::min(change / previousChange, 0.99);
      omega = 2.0 / (1.0 + std::sqrt(1.0 - contraction));
      estimate = false;
    }
    previousChange = change;
    ++sweeps;
  } while (change >= parameters.GaussSeidelTolerance && sweeps < parameters.MaximumNumberOfSweeps);
  lastChange = change;
  return sweeps;
}
} // namespace

EvolutionConstants ConstantsOf(const Parameters& parameters)
{
  EvolutionConstants constants;
  constants.Offset = parameters.OffsetDistance;
  constants.Xi = parameters.Xi();
  constants.TimeStep = parameters.EffectiveTimeStep();
  constants.Spacing = parameters.Spacing;
  constants.Epsilon = parameters.Epsilon();
  constants.EdgeStopEq4 = parameters.EdgeStoppingFunction == EdgeStopping::Eq4;
  return constants;
}

BandValues Evolve(const NarrowBand& band, const Parameters& parameters, EvolutionLauncher& launcher,
  Monitor* monitor, std::vector<StepReport>& reports)
{
  const std::int64_t size = band.Size();
  const EvolutionConstants constants = ConstantsOf(parameters);
  // A band built by the launcher (BuildNarrowBand with a LauncherDistance)
  // has its distances and neighbour table there only: null arrays say so.
  const bool held = band.Neighbor.empty() && size > 0;
  launcher.Upload(size, held ? nullptr : band.Neighbor.data(), held ? nullptr : band.Distance.data(),
    1.0 - parameters.Delta, -1.0 + parameters.Delta);
  launcher.InitialField(constants); // eq. (2)
  launcher.Coefficients(constants); // g of eq. (4) or (3), the coefficients of (10) and (12)
  double omega = parameters.Relaxation > 0.0 ? parameters.Relaxation : 1.0;
  bool estimate = !(parameters.Relaxation > 0.0);

  std::int64_t red[2], black[2];
  band.OwnedNodes(true, red[0], red[1]);
  band.OwnedNodes(false, black[0], black[1]);
  const int steps = std::max(0, parameters.MaximumNumberOfIterations);
  for (int n = 0; n < steps; ++n)
  {
    if (monitor)
    {
      monitor->Progress(static_cast<double>(n) / steps);
      if (monitor->Aborted())
      {
        break;
      }
    }
    StepReport report;
    report.Sweeps = Diffuse(launcher, band, parameters, omega, estimate, report.SweepChange); // (10)-(11)
    launcher.React(); // (12)
    // The relative change of section 4, summed red then black as the CPU
    // core's solver does (Previous still holds phi^n).
    double change2 = 0.0, norm2 = 0.0;
    change2 += launcher.ChangeSquared(red[0], red[1]);
    change2 += launcher.ChangeSquared(black[0], black[1]);
    norm2 += launcher.NormSquared(red[0], red[1]);
    norm2 += launcher.NormSquared(black[0], black[1]);
    report.RelativeChange = norm2 > 0.0 ? std::sqrt(change2 / norm2) : 0.0;
    reports.push_back(report);
    if (parameters.ConvergenceTolerance > 0.0 && report.RelativeChange < parameters.ConvergenceTolerance)
    {
      break;
    }
  }
  if (monitor)
  {
    monitor->Progress(1.0);
  }
  BandValues phi;
  launcher.Download(phi);
  return phi;
}

} // namespace device
} // namespace nv
