// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The run's plan: the settings checked and the grid derived from the
// points' bounds and sampling (the automatic offset and spacing resolved),
// before anything grows with the grid. The pipeline's information pass
// asks for it too (nvReconstruct.h).
#ifndef nvPlan_h
#define nvPlan_h

#include "nvGrid.h"
#include "nvParameters.h"
#include "nvSampling.h"
#include "nvSettings.h"

#include <array>
#include <string>

namespace nv
{

/// The grid that points with given bounds get, and the scheme's parameters on
/// it (with the automatic offset and spacing filled in).
struct Plan
{
  Grid TheGrid;
  Parameters Scheme;
  /// The widest hole the run bridges (radius, world units); 0: none (CloseGaps off).
  double ClosingRadius = 0.0;
  bool AutomaticOffset = false;
  bool AutomaticSpacing = false;
  /// The automatic grid was coarsened to AutomaticMaximumDimension cells on
  /// its longest side: the spacing l / 4 asked for (0: not coarsened), and
  /// the automatic offset before it was raised to 4 h on that grid.
  double CoarsenedFrom = 0.0;
  double OffsetBeforeCoarsening = 0.0;
  /// Printing (WallThickness > 0) with an automatic spacing: the spacing the
  /// wall asked for (WallThickness / LeastCellsPerWall, nvPrintSettings.h) where
  /// it made the grid finer than the offset alone would (0: it did not).
  /// Such a grid is not capped at AutomaticMaximumDimension; the memory
  /// limit decides, and its message says so (CheckMemory).
  double WallSpacing = 0.0;
  double Diagonal = 0.0; ///< the diagonal of the points' bounding box
  std::array<double, 6> PointsBounds{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } }; ///< that box: xmin, xmax, ymin, ...
  std::string Error; ///< why there is no grid; empty when there is one
  bool Valid() const { return this->Error.empty(); }
};

/**
 * Checks the settings and derives the grid from the points' bounds (xmin,
 * xmax, ymin, ...) and, for the automatic offset and spacing, their sampling:
 * the information a pipeline needs before the run, and the run's own first
 * step. The message of an invalid plan says what to change.
 */
Plan MakePlan(const Settings& settings, const double bounds[6], const SamplingStatistics& sampling);

/// A value rounded to three significant digits, up or down: the figure a
/// message can print that still holds (a setting to reach, a factor not to
/// pass).
double ThreeDigits(double value, bool up);

} // namespace nv

#endif
