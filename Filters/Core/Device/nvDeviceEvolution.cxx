// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvDeviceEvolution.h"

#include "nvParallel.h"
#include "nvTimeLoop.h"

#include <algorithm>

namespace nv
{
namespace device
{
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
  OverRelaxation relaxation(parameters.Relaxation);
  std::int64_t red[2], black[2];
  band.OwnedNodes(true, red[0], red[1]);
  band.OwnedNodes(false, black[0], black[1]);
  reports = RunTimeSteps(
    parameters, monitor,
    [&](bool) {
      StepReport report;
      launcher.KeepPrevious();
      report.Sweeps = SweepUntilSettled( // (10)-(11)
        [&](double omega) {
          const double changeRed = launcher.Relax(red[0], red[1], omega);
          return std::max(changeRed, launcher.Relax(black[0], black[1], omega));
        },
        parameters, relaxation, report.SweepChange);
      launcher.React(); // (12)
      // The relative change of section 4, summed red then black as the CPU
      // core's solver does (Previous still holds phi^n).
      double change2 = 0.0, norm2 = 0.0;
      change2 += launcher.ChangeSquared(red[0], red[1]);
      change2 += launcher.ChangeSquared(black[0], black[1]);
      norm2 += launcher.NormSquared(red[0], red[1]);
      norm2 += launcher.NormSquared(black[0], black[1]);
      report.RelativeChange = RelativeChange(change2, norm2);
      return report;
    },
    [](bool stop) { return stop; });
  BandValues phi;
  launcher.Download(phi);
  return phi;
}

} // namespace device
} // namespace nv
