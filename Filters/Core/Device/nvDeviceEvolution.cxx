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

std::vector<StepReport> Evolve(
  const NarrowBand& band, const Parameters& parameters, EvolutionLauncher& launcher, Monitor* monitor)
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
  return RunTimeSteps(
    parameters, monitor,
    [&](bool) {
      StepReport report;
      launcher.KeepPrevious();
      report.Sweeps = SweepUntilSettled( // (10)-(11)
        [&](double omega) { return launcher.Sweep(red, black, omega); }, parameters, relaxation,
        report.SweepChange);
      launcher.React(); // (12)
      // The relative change of section 4, summed red then black as the CPU
      // core's solver does (Previous still holds phi^n).
      double sums[4];
      launcher.StepSums(red, black, sums);
      double change2 = 0.0, norm2 = 0.0;
      change2 += sums[0];
      change2 += sums[1];
      norm2 += sums[2];
      norm2 += sums[3];
      report.RelativeChange = RelativeChange(change2, norm2);
      return report;
    },
    [](bool stop) { return stop; });
}

} // namespace device
} // namespace nv
