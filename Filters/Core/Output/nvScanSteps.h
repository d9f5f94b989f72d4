// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The steps of the scan surface (MakeScanSurface, nvScanSurface.h) that
// have a file of their own: the surface on an open scan (nvOpenScan.cxx).
// Internal to Output/.
#ifndef nvScanSteps_h
#define nvScanSteps_h

#include "nvGrid.h"
#include "nvSurface.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace nv
{
class Monitor;

namespace scan
{
/// A field on the grid's nodes, read at a place inside the grid: trilinear.
double Trilinear(const Grid& grid, const float* values, const double x[3]);

/// The pieces of the solid S (phi > 0 in `outer`): each node's piece, 0, 1,
/// ... (6-connected), or -1 outside S.
std::vector<std::int32_t> SolidPieces(const Grid& grid, const float* outer, std::int32_t& pieces);

/// The piece of S at x: that of a corner of x's cell inside S (-1: none).
std::int32_t PieceAt(const Grid& grid, const float* outer, const std::vector<std::int32_t>& pieces, const double* x);

/// What the open surface is made from.
struct OpenScanInput
{
  const float* Outer = nullptr;            ///< phi with the cavities filled (S: > 0)
  const std::vector<float>* Distance = nullptr; ///< D, the distance to the outer sheet (inside S)
  const SurfaceMesh* Sheet = nullptr;      ///< the outer sheet (normals out of S)
  const std::vector<std::int32_t>* Pieces = nullptr; ///< SolidPieces
  const std::vector<char>* Open = nullptr; ///< per piece: whether it holds an open scan
  const double* Scan = nullptr;            ///< the scan's points
  std::int64_t ScanPoints = 0;
  double Offset = 0.0;                     ///< l
  double Reach = 0.0;                      ///< how far a triangle looks for points around it
  std::function<void(double, double)> Step; ///< the share of its progress from to (may be empty)
};

/**
 * The surface on the open pieces of S, into `open`: the shell of an open
 * scan is a thick sheet whose outer sheet has two faces, one on each side of
 * the scan, joined around its rim. Each vertex of the outer sheet is told
 * its face: a ray from it into S, against its normal, leaves S through the
 * other face (a normal opposite to its own, after at most 2.6 times the
 * deepest D on the way: across the shell, not along it); the vertices whose
 * ray does so, joined by the sheet's edges, make patches, and the patches
 * at the two ends of the rays take opposite faces (two colours, by
 * breadth-first search over the rays); the vertices left (around the rim)
 * take the face of the nearest patch along the sheet's edges. With D_A and
 * D_B the distances to the two faces' vertices, the surface is
 *
 *     psi = (D_B - D_A) / 2 = 0,
 *
 * the middle between the faces, which is the middle of the points; it is
 * contoured where S is (not across the outer sheet), and the triangles
 * without points all around them go: the middle between the faces goes on
 * beyond the scan's rim, to the rim's half-pipe, where the points nearest
 * to a triangle all lie on one side of it. Its normals point to face B.
 * Returns false if the monitor stopped it.
 */
bool MakeOpenSurface(const Grid& grid, const OpenScanInput& input, SurfaceMesh& open, Monitor* monitor);
} // namespace scan
} // namespace nv

#endif
