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
// Drain holes (NumberOfDrainHoles): from the lowest points of each cavity
// kept, straight down through the wall (down: DrainHoleAxis, -z by
// default), f = min(f, distance to the hole's surface), so the surface
// stays closed and manifold.
//
// Cavities: a closed part of the surface around a region outside it is a
// cavity; those smaller than MinimumCavityVolume (0: 1 % of the largest)
// are merged into the wall (their surface goes, RemoveSmallPieces), so that
// no sealed pocket traps resin or powder. Loose pieces go as in the shell.
#ifndef nvPrintPart_h
#define nvPrintPart_h

#include "nvGrid.h"
#include "nvParameters.h"
#include "nvSurface.h"

#include <array>
#include <cstdint>

namespace nv
{
class Monitor;

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

/// What the part is: its figures for the print.
struct PrintReport
{
  double MaterialVolume = 0.0;       ///< the material's volume (the part less its cavities)
  double CavityVolume = 0.0;         ///< the kept cavities' volume
  double MinimumWallThickness = 0.0; ///< the least distance from the inner surface to the outer (0: solid)
  double MinimumCavityVolume = 0.0;  ///< the volume below which a cavity was merged into the wall
  std::int64_t KeptCavities = 0;
  std::int64_t RemovedCavities = 0;
  std::int64_t RemovedPieces = 0;
  std::int64_t DrainHoles = 0; ///< holes drilled from the cavities to the outside
  std::array<double, 6> Bounds{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } }; ///< the part's xmin, xmax, ymin, ...
};

/**
 * Makes the part into `sink`. outer: phi on every node of the grid, once
 * KeepSheets(Outer) filled the cavities (phi > 0: inside the outer sheet).
 * wall: w; minimumCavity: cavities below it are merged into the wall (0:
 * below 1 % of the largest). drainHoles: holes drilled from each cavity
 * kept, at its lowest points along `down`, of diameter drainDiameter (0:
 * 2 w, at least 4 h): f is made again with them (f = min(f, the distance
 * to the hole's surface)) and contoured again, so the part stays closed.
 * Returns false if the monitor stopped it.
 */
bool MakePart(const Grid& grid, const Parameters& parameters, const float* outer, double wall, double minimumCavity,
  int drainHoles, double drainDiameter, DrainAxis down, SurfaceSink& sink, Monitor* monitor, PrintReport& report);

} // namespace nv

#endif
