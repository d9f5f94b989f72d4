// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPlan.h"

#include "nvGapClosing.h"
#include "nvPrintPart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#ifdef _WIN32
#include <windows.h>
#else
#include <unistd.h>
#endif

namespace nv
{
namespace
{
/// The machine's physical memory in bytes (0 if unknown).
double PhysicalMemoryBytes()
{
#ifdef _WIN32
  MEMORYSTATUSEX status;
  status.dwLength = sizeof(status);
  return GlobalMemoryStatusEx(&status) ? static_cast<double>(status.ullTotalPhys) : 0.0;
#else
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0.0;
#endif
}

/// The settings with the automatic offset (OffsetDistance 0) and spacing
/// (SampleSpacing <= 0 and MaximumDimension 0) chosen as nvSampling.h says.
Settings ResolveAutomatic(const Settings& settings, const SamplingStatistics& sampling, const double bounds[6], Plan& plan)
{
  Settings values = settings;
  const bool automaticOffset = settings.OffsetDistance == 0.0;
  const bool automaticSpacing = !(settings.SampleSpacing > 0.0) && settings.MaximumDimension == 0;
  plan.AutomaticOffset = automaticOffset;
  plan.AutomaticSpacing = automaticSpacing;
  if (!(bounds[0] <= bounds[1]) || (automaticOffset && !sampling.Valid()))
  {
    return values; // no points, or no spacing to follow: MakePlan says so
  }
  if (automaticOffset)
  {
    values.OffsetDistance = std::max(1.5 * sampling.MedianSpacing, sampling.WideSpacing);
  }
  if (automaticSpacing && std::isfinite(values.OffsetDistance) && values.OffsetDistance > 0.0)
  {
    // The paper's l = 4 h, unless the grid would get too large.
    double spacing = values.OffsetDistance / 4.0;
    const double coarsest =
      SpacingForMaximumDimension(bounds, values.OffsetDistance, values.XiCells, AutomaticMaximumDimension);
    if (coarsest > spacing)
    {
      plan.CoarsenedFrom = spacing;
      plan.OffsetBeforeCoarsening = values.OffsetDistance;
      spacing = coarsest;
      if (automaticOffset)
      {
        values.OffsetDistance = std::max(values.OffsetDistance, 4.0 * spacing);
      }
    }
    // Printing: the wall spans LeastCellsPerWall cells at least, whatever
    // the cap (nvPrintPart.h); the memory limit decides (CheckMemory).
    const double wallSpacing = settings.WallThickness > 0.0 ? settings.WallThickness / LeastCellsPerWall : 0.0;
    if (wallSpacing > 0.0 && spacing > wallSpacing)
    {
      plan.WallSpacing = wallSpacing;
      spacing = wallSpacing;
      if (plan.CoarsenedFrom > 0.0)
      {
        // The cap no longer decides: the offset as the sampling asks, l = 4 h at least.
        if (automaticOffset)
        {
          values.OffsetDistance = std::max(plan.OffsetBeforeCoarsening, 4.0 * spacing);
        }
        plan.CoarsenedFrom = 0.0;
        plan.OffsetBeforeCoarsening = 0.0;
      }
    }
    values.SampleSpacing = spacing;
  }
  else if (automaticOffset && values.OffsetDistance > 0.0)
  {
    // A spacing set by the user: the automatic offset spans at least 4 cells
    // (the paper's l = 4 h), or the shell would not survive on that grid. With
    // MaximumDimension the spacing grows with l's padding: a few rounds settle it.
    for (int round = 0; round < 4; ++round)
    {
      const double spacing = settings.SampleSpacing > 0.0
        ? settings.SampleSpacing
        : SpacingForMaximumDimension(bounds, values.OffsetDistance, values.XiCells, settings.MaximumDimension);
      values.OffsetDistance = std::max(values.OffsetDistance, 4.0 * spacing);
    }
  }
  return values;
}

/// The scheme's parameters (nvParameters.h) from the settings with the
/// automatic values resolved: the properties of the same names, and h (0
/// or less when MaximumDimension gives none). The one place they are copied.
Parameters SchemeParameters(const Settings& settings, const double bounds[6])
{
  Parameters parameters;
  parameters.OffsetDistance = settings.OffsetDistance;
  parameters.XiCells = settings.XiCells;
  parameters.EpsilonCells = settings.EpsilonCells;
  parameters.TimeStep = settings.TimeStep;
  parameters.MaximumNumberOfIterations = settings.MaximumNumberOfIterations;
  parameters.ConvergenceTolerance = settings.ConvergenceTolerance;
  parameters.GaussSeidelTolerance = settings.GaussSeidelTolerance;
  parameters.Domain = settings.Domain;
  parameters.EdgeStoppingFunction = settings.EdgeStoppingFunction;
  parameters.PreserveOffset = settings.PreserveOffset;
  parameters.Spacing = settings.SampleSpacing > 0.0
    ? settings.SampleSpacing
    : SpacingForMaximumDimension(bounds, settings.OffsetDistance, settings.XiCells, settings.MaximumDimension);
  return parameters;
}
} // namespace

//------------------------------------------------------------------------------
double ThreeDigits(double value, bool up)
{
  if (!(value > 0.0) || !std::isfinite(value))
  {
    return value;
  }
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 2.0);
  return (up ? std::ceil(value / unit) : std::floor(value / unit)) * unit;
}

//------------------------------------------------------------------------------
double Settings::MemoryLimitBytes() const
{
  if (this->MemoryLimit > 0.0)
  {
    return this->MemoryLimit * 1048576.0;
  }
  const double physical = PhysicalMemoryBytes();
  return physical > 0.0 ? 0.5 * physical : 4.0 * 1073741824.0; // unknown: 4 GiB
}

double Settings::OutputBytesPerNode() const
{
  // phi (float), the optional arrays, and the isosurfacer's working memory.
  return this->OutputVolume ? 4.0 + (this->OutputInitialPhi ? 4.0 : 0.0) + (this->OutputDistance ? 4.0 : 0.0) +
      (this->OutputNarrowBand ? 1.0 : 0.0) + 2.0
                            : 0.0;
}

//------------------------------------------------------------------------------
Plan MakePlan(const Settings& chosen, const double bounds[6], const SamplingStatistics& sampling)
{
  Plan plan;
  std::ostringstream error;
  const Settings settings = ResolveAutomatic(chosen, sampling, bounds, plan);
  if (!std::isfinite(chosen.OffsetDistance) || chosen.OffsetDistance < 0.0)
  {
    error << "OffsetDistance must be a finite value > 0 (or 0: automatic), not " << chosen.OffsetDistance << ".";
  }
  else if (!std::isfinite(chosen.ClosingRadius) || chosen.ClosingRadius < 0.0)
  {
    error << "ClosingRadius must be a finite value > 0 (or 0: automatic), not " << chosen.ClosingRadius << ".";
  }
  else if (!std::isfinite(chosen.SampleSpacing))
  {
    error << "SampleSpacing must be finite, not " << chosen.SampleSpacing << ".";
  }
  else if (!(settings.OffsetDistance > 0.0) && bounds[0] <= bounds[1])
  {
    error << "An automatic OffsetDistance needs at least two distinct points; set OffsetDistance.";
  }
  else if (!std::isfinite(chosen.WallThickness) || chosen.WallThickness < 0.0)
  {
    error << "WallThickness must be a finite value >= 0 (0: the shell, no part to print), not "
          << chosen.WallThickness << ".";
  }
  else if (!std::isfinite(chosen.DrainHoleDiameter) || chosen.DrainHoleDiameter < 0.0)
  {
    error << "DrainHoleDiameter must be a finite value >= 0 (0: automatic), not " << chosen.DrainHoleDiameter
          << ".";
  }
  else if (!std::isfinite(chosen.CavityClosingDistance) || chosen.CavityClosingDistance < 0.0)
  {
    error << "CavityClosingDistance must be a finite value >= 0 (0: the exact offset), not "
          << chosen.CavityClosingDistance << ".";
  }
  else if (chosen.DrainHolePositions.size() % 3 != 0 ||
    !std::all_of(chosen.DrainHolePositions.begin(), chosen.DrainHolePositions.end(),
      [](double x) { return std::isfinite(x); }))
  {
    error << "DrainHolePositions must be points, three finite coordinates each (x y z), not "
          << chosen.DrainHolePositions.size() << " values"
          << (chosen.DrainHolePositions.size() % 3 != 0 ? "" : " with one that is not finite") << ".";
  }
  else if (!std::isfinite(chosen.MinimumCavityVolume) || chosen.MinimumCavityVolume < 0.0)
  {
    error << "MinimumCavityVolume must be a finite value >= 0 (0: automatic), not " << chosen.MinimumCavityVolume
          << ".";
  }
  else if (!std::isfinite(settings.TimeStep))
  {
    error << "TimeStep must be finite, not " << settings.TimeStep << ".";
  }
  // The property table's ranges that a run refuses values outside of.
#define NV_REFUSE_OUTSIDE(Name, Low, High)                                                                         \
  else if (!(settings.Name >= Low && settings.Name <= High))                                                       \
  {                                                                                                                \
    error << #Name " must be in [" << Low << ", " << High << "], not " << settings.Name << ".";                    \
  }
  NV_SETTINGS_VALID(NV_REFUSE_OUTSIDE)
#undef NV_REFUSE_OUTSIDE
  else if (!(bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5]))
  {
    error << "The input has no points: nothing to reconstruct.";
  }
  else if (chosen.WallThickness > 0.0 && (chosen.NumberOfDrainHoles > 0 || !chosen.DrainHolePositions.empty()) &&
    chosen.DrainHoleDiameter > 0.0)
  {
    // A hole wider than half the cloud across its axis cuts the part apart.
    const int axis = static_cast<int>(chosen.DrainHoleAxis) / 2;
    const double across[2] = { bounds[2 * ((axis + 1) % 3) + 1] - bounds[2 * ((axis + 1) % 3)],
      bounds[2 * ((axis + 2) % 3) + 1] - bounds[2 * ((axis + 2) % 3)] };
    const double narrowest = std::min(across[0], across[1]);
    if (chosen.DrainHoleDiameter > 0.5 * narrowest)
    {
      error << "DrainHoleDiameter (" << chosen.DrainHoleDiameter
            << ") is more than half the cloud's width across DrainHoleAxis (" << across[0] << " x " << across[1]
            << "): a hole that wide cuts the part apart.\nSet DrainHoleDiameter to " << 0.5 * narrowest
            << " or less (0: twice WallThickness).";
    }
  }
  if (!error.str().empty())
  {
    plan.Error = error.str();
    return plan;
  }

  plan.Scheme = SchemeParameters(settings, bounds);
  Parameters& parameters = plan.Scheme;
  if (!(parameters.Spacing > 0.0) || !std::isfinite(parameters.Spacing))
  {
    error << "Cannot derive a grid spacing from MaximumDimension " << settings.MaximumDimension
          << "; set SampleSpacing.";
    plan.Error = error.str();
    return plan;
  }

  // The grid's size, in floating point so that no integer can overflow; a
  // grid must also fit VTK's int extents.
  const double padding = GridPadding(parameters.Reach(), parameters.Spacing);
  double nodes = 1.0;
  bool fits = true;
  for (int a = 0; a < 3; ++a)
  {
    const double cells = (bounds[2 * a + 1] - bounds[2 * a] + 2.0 * padding) / parameters.Spacing + 2.0;
    nodes *= cells;
    fits = fits && std::isfinite(cells) && cells < static_cast<double>(std::numeric_limits<int>::max());
  }
  if (!fits || !(nodes < 9.2e18))
  {
    error << "The grid is too large: about " << nodes << " nodes (spacing " << parameters.Spacing
          << "). Increase SampleSpacing or lower MaximumDimension.";
    plan.Error = error.str();
    return plan;
  }
  plan.TheGrid = MakeGrid(bounds, parameters.Spacing, padding);
  plan.Diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
    std::pow(bounds[5] - bounds[4], 2));
  std::copy(bounds, bounds + 6, plan.PointsBounds.begin());
  if (settings.CloseGaps)
  {
    plan.ClosingRadius = settings.ClosingRadius > 0.0 ? settings.ClosingRadius
                                                      : AutomaticClosingRadius * parameters.OffsetDistance;
  }
  return plan;
}

} // namespace nv
