// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The surface on the scan (Sheets SCAN_SURFACE): one closed surface through
// the middle of the points, from the shell, without normals. An addition to
// the paper's method, made from its shell as the part to print is.
//
// The shell's outer sheet encloses a solid S (the nodes where phi > 0 once
// its cavities are filled). With D the distance to the outer sheet, S
// eroded by l, {D > l}, is the cloud's closing C (nvPrintPart.h): on a clean
// scan its surface lies on the points. On a noisy scan the outer sheet lies
// l beyond the points' outer envelope, so C's surface follows the envelope,
// not the middle of the points. The points tell how far below C's surface
// their middle is: each point's depth is D(p) - l (trilinear in D), and the
// local depth s(x) is the median depth of the points near x (per cell of a
// coarse grid of side l, averaged over the 27 cells around, weighted by
// their points). The scan surface is f = 0 with
//
//     f = D - l - s(x)    inside S,     f = -(D + l + s(x))   outside S,
//
// positive inside the object, contoured as the part is (normals outward).
// On a clean scan s is about 0 (C's surface; where the outer sheet drifted
// inward by its curvature the points lie outside C and s < 0 brings the
// surface back to them); under noise s is the envelope's distance to the
// points' middle. s is kept within [-(l - h), l]: the surface stays inside
// the outer sheet and at most 2 l deep.
//
// Open scans: S is then the shell itself (it encloses no cavity), whose
// middle is the scan, at D <= l: f stays near or below 0 and the closed
// surface is empty or in shreds; under noise it is a thin slab through the
// points' middle, thinner than their spread. Those pieces of S get the open
// surface instead: the middle between the outer sheet's two faces, one on
// each side of the scan, cut at the scan's rim (nvScanSteps.h). Points along
// a curve get none; the report tells (its points far from the surface, its
// size against the cloud's) and the run warns (nvRunWarnings.h).
#ifndef nvScanSurface_h
#define nvScanSurface_h

#include "nvGrid.h"
#include "nvParameters.h"
#include "nvSurface.h"

#include <array>
#include <cstdint>

namespace nv
{
class Monitor;

/// What the scan surface is, and how far the scan's points lie from it.
struct ScanReport
{
  double Volume = 0.0;        ///< the volume it encloses (signed: normals outward)
  std::int64_t Pieces = 0;    ///< its closed pieces
  std::int64_t OpenPieces = 0; ///< its open pieces (on open scans)
  std::int64_t RemovedPieces = 0; ///< loose pieces removed (smaller than a ball of 2 l)
  std::int64_t RemovedVoids = 0;  ///< voids removed (smaller than a ball of l)
  std::int64_t Points = 0;    ///< the scan's points measured
  double MeanDistance = 0.0;  ///< the mean distance of the points to the surface, in cells (h)
  double Distance95 = 0.0;    ///< its 95th percentile, in cells
  double MedianDistance = 0.0; ///< its median, in cells
  double MedianDepth = 0.0;   ///< the median of s over the points: the points' middle below C's surface, in cells
  std::array<double, 6> Bounds{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } }; ///< xmin, xmax, ymin, ... (all 0 when empty)
};

/**
 * Makes the scan surface into `sink`: closed pieces (normals outward), then
 * open ones. outer: phi on every node of the grid
 * once KeepSheets(Outer) filled its cavities (phi > 0: inside the outer
 * sheet); scan: the scan's points (x y z after one another). With
 * removeSmallPieces, loose pieces smaller than a ball of 2 l and voids
 * smaller than a ball of l go, as the shell's do (nvPieces.h). Returns false
 * if the monitor stopped it. progress: the begin and width of the run's
 * progress it takes; it shares them among its steps.
 */
bool MakeScanSurface(const Grid& grid, const Parameters& parameters, const float* outer, const double* scan,
  std::int64_t scanPoints, bool removeSmallPieces, SurfaceSink& sink, Monitor* monitor, ScanReport& report,
  const double progress[2]);

} // namespace nv

#endif
