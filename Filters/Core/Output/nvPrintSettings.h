// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The user's printing settings (the property table's Printing group), as
// the part to print takes them (MakePart, nvPrintPart.h): one struct, which
// the run fills once from its Settings; and what the run plans for the part
// before it is made (its grid and memory). Apart from printing itself, so
// that the settings (Run/nvSettings.h) need not include all of it.
#ifndef nvPrintSettings_h
#define nvPrintSettings_h

#include <vector>

namespace nv
{

/// The grid cells the wall spans at least where the spacing is automatic
/// (nvReconstruction.cxx, ResolveAutomatic): f > 0 across a wall under two
/// cells thick is under a cell in places, and contours into a lace of
/// fragments; three keep it whole with a cell to spare. A spacing the user
/// set that gives fewer is warned about.
constexpr double LeastCellsPerWall = 3.0;

/// Bytes per grid node that MakePart holds beside the dense phi: the outer
/// sheet's copy of phi (4), the nearest-vertex keys of SheetDistance (8) and
/// the distance D (4); with a cavity closing distance, its distance G (4)
/// too. The memory limit counts them (CheckMemory).
constexpr double PartBytesPerNode = 16.0;
constexpr double ClosingBytesPerNode = 4.0;

/// The way down for the drain holes (DrainHoleAxis): axis value / 2, towards
/// its low end for even values.
enum class DrainAxis
{
  MinusX = 0,
  PlusX = 1,
  MinusY = 2,
  PlusY = 3,
  MinusZ = 4,
  PlusZ = 5
};

/// What the user asks of the part to print.
struct PrintSettings
{
  double Wall = 0.0;                   ///< w (WallThickness)
  double MinimumCavity = 0.0;          ///< MinimumCavityVolume (0: 1 % of the largest cavity)
  double CavityClosing = 0.0;          ///< CavityClosingDistance c (0: the exact offset)
  int DrainHoles = 0;                  ///< NumberOfDrainHoles per cavity kept
  double DrainDiameter = 0.0;          ///< DrainHoleDiameter (0: 2 w, at least 4 h)
  DrainAxis Down = DrainAxis::MinusZ;  ///< DrainHoleAxis
  double DrainAngle = 0.0;             ///< DrainHoleAngle, degrees from Down a hole may lean
  std::vector<double> DrainPositions;  ///< where holes go, x y z after one another (none: NumberOfDrainHoles)
};

} // namespace nv

#endif
