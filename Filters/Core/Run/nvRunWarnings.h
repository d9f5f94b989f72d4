// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The warnings about the run's outputs (step 9 of Reconstruct,
// nvReconstruct.h), and the errors and warnings of the settings that cannot
// go together: one line of what happened, one of what to change, with the
// properties' names (the VTK filter puts the panel's labels in their place
// in ParaView, the command line its options). Internal to Run/.
#ifndef nvRunWarnings_h
#define nvRunWarnings_h

#include "nvReconstruct.h"

#include <string>
#include <vector>

namespace nv
{
namespace warnings
{
/// The warnings about the holes left open that pierce the evolved shell
/// (OpenHole::Pierced; the others are covered by the wall and only counted
/// in NumberOfGaps), in two kinds, each with the change that covers it:
/// holes wider than ClosingRadius (or than l when nothing is bridged), which
/// a larger radius bridges, and holes the bridging left open although they
/// are narrower (its rounds ran out, or their rim is not flat enough to
/// bridge: nvGapClosing.h), which only a thicker wall covers.
std::vector<std::string> GapWarnings(const GapReport& gaps, double closingRadius, double offset, bool printing);

/// OffsetDistance above the diagonal of the cloud's bounds.
std::string OffsetOverCloudWarning(double offset, double diagonal);
/// The automatic grid coarsened to AutomaticMaximumDimension cells.
std::string CoarsenedGridWarning(const Reconstruction& run);
/// The shell encloses no cavity (open, or thinner than 2 l).
std::string OpenShellWarning(const GapReport& gaps, double closingRadius, double offset);

/// The least offset / spacing ratio that keeps the shell whole: the
/// initial profile and the band span 2 XiCells = 4 cells (eq. 2, 5), which
/// the wall of 2 l must hold with room to spare.
constexpr double LeastCellsPerOffset = 3.0;
/// Offset / spacing below LeastCellsPerOffset.
std::string CoarseGridWarning(const Reconstruction& run);
/// The shell did not survive the evolution.
std::string EmptySurfaceWarning(double offset, double spacing);
/// Sheets Inner where the shell has no cavity.
std::string NoInnerSheetWarning();
/// One sheet kept, or the scan surface made, with OutputVolume off.
std::string OneSheetNeedsGridWarning(bool scan);

/// The warnings about the part to print, after it is made: each says what
/// is wrong with the part and what to change.
std::vector<std::string> PartWarnings(const Settings& settings, const Reconstruction& run, const PrintReport& print,
  double surfacePoints);

/// The scan surface's diagonal below this share of the cloud's: it lost
/// most of the scan (ScanWarnings).
constexpr double LeastScanSurfaceShare = 0.5;
/// The warnings about the scan surface (Sheets Scan, nvScanSurface.h): empty
/// (points along a curve), much smaller than the cloud, or farther than the
/// offset distance from half of the points; each says what to change.
std::vector<std::string> ScanWarnings(const Reconstruction& run, const ScanReport& scan);

/// Sheets other than Both with a wall (the part to print is made instead).
std::string SheetsWithWallWarning(const Settings& settings);
/// Drain holes asked for without a wall (WallThickness 0).
std::string DrainHolesWithoutWallWarning(const Settings& settings);
/// A part to print in a distributed run.
std::string PrintDistributedError();
/// One sheet or the scan surface asked for in a distributed run.
std::string OneSheetDistributedWarning();
} // namespace warnings
} // namespace nv

#endif
