// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The part to print (WallThickness w > 0): a hollow solid whose outside lies
// where the scan is and whose wall is w thick. An addition to the paper's
// method, made from its shell.
//
// The shell's outer sheet encloses a solid S: the nodes where phi > 0 once
// its cavities are filled (KeepSheets, Outer). S is the cloud's surface
// pushed out by the offset l, so S eroded by l is the cloud's closing C:
// where the surface is smooth on the scale of l it lies on the scan, where
// a concavity is narrower than l, or a hole was bridged, C spans it. With D
// the distance to the outer sheet, the part is C less C eroded by w:
//
//     f =  min(D - l, l + w - D)   inside S,
//     f = -(l + D)                 outside S,
//
// positive in the material; f = 0 is its outer surface (D = l) and its
// inner surface (D = l + w), a wall of w between them. f is contoured as the
// shell is (ContourBricks), so its normals point out of the material:
// outward on the outer surface, into the cavity on the inner one, as a
// slicer expects. Where the solid is thinner than 2 (l + w) the part is
// solid there.
//
// D is the distance to the outer sheet's vertices (its marching-cubes
// vertices, less than h apart): over a smooth sheet it exceeds the distance
// to the sheet by about s^2 / (8 D) for vertices s apart, under 0.03 h where
// D >= l >= 4 h. f is kept within +-3 h, where the contouring reads it; a
// brick wholly beyond that is one value.
//
// Drain holes: from the lowest points of each cavity kept
// (NumberOfDrainHoles), or from the cavity's points nearest to the
// positions the user gives (the filter's DrainHoles input), by the shortest
// way out through the wall within DrainHoleAngle of the way down
// (DrainHoleAxis, -z by default), never longer than a few walls (not down a
// limb); f = min(f, distance to the hole's surface), so the surface stays
// closed and manifold.
//
// Cavities: a closed part of the surface around a region outside it is a
// cavity; those smaller than MinimumCavityVolume (0: 1 % of the largest)
// are merged into the wall (their surface goes, RemoveSmallPieces), so that
// no sealed pocket traps resin or powder. Loose pieces go as in the shell.
#ifndef nvPrintPart_h
#define nvPrintPart_h

#include "nvGrid.h"
#include "nvParameters.h"
#include "nvPrintSettings.h"
#include "nvSurface.h"

#include <array>
#include <cstdint>
#include <vector>

namespace nv
{
class Monitor;

/// What the part is made of beside the outer sheet: the user's printing
/// settings (nvPrintSettings.h), and the scan it must hold.
struct PartRequest : PrintSettings
{
  const double* Scan = nullptr;        ///< the scan's points, x y z after one another (may be null)
  std::int64_t ScanPoints = 0;
  /// The monitor's stage the part takes: begin and width of the run's
  /// progress; MakePart shares it among its steps.
  double Progress[2] = { 0.0, 1.0 };
};

/// The scan points in one place that the part lost (nearer to one another
/// than LostRegionReach cells): a limb or piece it lacks.
struct LostRegion
{
  std::int64_t Points = 0;
  std::array<double, 3> Center{ { 0.0, 0.0, 0.0 } }; ///< the points' mean
  std::array<double, 3> Size{ { 0.0, 0.0, 0.0 } };   ///< their box's sides
};

/// What the part is: its figures for the print.
struct PrintReport
{
  double MaterialVolume = 0.0;       ///< the material's volume (the part less its cavities)
  double CavityVolume = 0.0;         ///< the kept cavities' volume
  double MinimumWallThickness = 0.0; ///< the least distance from the inner surface to the outer (0: solid)
  std::array<double, 3> ThinnestWallAt{ { 0.0, 0.0, 0.0 } }; ///< where (on the inner surface)
  double MinimumCavityVolume = 0.0;  ///< the volume below which a cavity was merged into the wall
  std::int64_t KeptCavities = 0;
  std::int64_t RemovedCavities = 0;
  std::int64_t RemovedPieces = 0;
  std::int64_t Pieces = 0;     ///< separate pieces of material the part is made of
  std::int64_t DrainHoles = 0; ///< holes drilled from the cavities to the outside
  std::int64_t DrainHolesAsked = 0; ///< the positions given, or NumberOfDrainHoles times the cavities kept
  std::int64_t DrainHolesTooLong = 0; ///< places not drilled: the way out longer than 2 (l + w) + 2 h
  std::int64_t DrainPositionsAway = 0; ///< positions farther than that from every cavity kept
  std::array<double, 3> FirstPositionAway{ { 0.0, 0.0, 0.0 } }; ///< the first of them
  std::int64_t CavitiesWithoutHoles = 0; ///< cavities kept that no hole leaves, where holes were asked for
  std::array<double, 6> Bounds{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } }; ///< the part's xmin, xmax, ymin, ...
  double ShellVolume = 0.0; ///< the shell's material (phi > 0), which the part's is compared with
  /// The scan against the part (CheckScan): a scan point is lost when it
  /// lies farther than LostDistance outside the part's outer surface, beyond
  /// what the closing explains (a point in a concavity narrower than the
  /// offset lies inside the material, as deep as the concavity is narrow).
  std::int64_t ScanPoints = 0;       ///< the points checked
  double LostDistance = 0.0;         ///< the bound: 2 h
  std::int64_t RestoredPoints = 0;   ///< lost points the part got back (material put around them)
  std::int64_t LostPoints = 0;       ///< lost points left after that
  double FarthestLost = 0.0;         ///< how far the farthest lies outside the part
  std::vector<LostRegion> LostRegions; ///< where they are, the most points first
  std::vector<LostRegion> RestoredRegions; ///< where the restored ones are, likewise
};

/// The share of the scan's points up to which lost points are restored
/// (RestoreLostPoints): a limb or a few pieces, not the scan itself (an
/// open scan's closing is empty: the whole scan is lost, and a warning
/// says why instead).
constexpr double RestorableShare = 0.2;

/**
 * Makes the part into `sink`. outer: phi on every node of the grid, once
 * KeepSheets(Outer) filled the cavities (phi > 0: inside the outer sheet).
 * Cavities below request.MinimumCavity are merged into the wall; drain
 * holes are drilled from each cavity kept, at its lowest points along
 * request.Down or nearest to request.DrainPositions: f is made again with them (f = min(f, the distance to the
 * hole's surface)) and contoured again, so the part stays closed. Then the
 * part is checked against request.Scan: material is put back around the
 * points it lost (up to RestorableShare of them), and those still lost are
 * reported. Returns false if the monitor stopped it.
 */
bool MakePart(const Grid& grid, const Parameters& parameters, const float* outer, const PartRequest& request,
  SurfaceSink& sink, Monitor* monitor, PrintReport& report);

} // namespace nv

#endif
