// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The truncated unsigned distance of eq. (6), computed only where it matters.
//
// The paper loops over the points and, for each, over the box of nodes within
// l + eta/2 (eq. 7), keeping the minimum in a dense array. Here the grid is cut
// into bricks of 8x8x8 nodes and the points are sorted into the bricks; the
// distance of one brick's nodes is computed on demand from the points of the
// neighbouring bricks. Nothing is stored per grid node: memory grows with the
// number of points and of bricks, and bricks are independent, so they run in
// parallel with identical results for any thread count.
#ifndef nvTruncatedDistance_h
#define nvTruncatedDistance_h

#include "nvBandTerms.h"
#include "nvGrid.h"
#include "nvBits.h"

#include <array>
#include <cstdint>
#include <vector>

namespace nv
{
class Monitor;

class TruncatedDistance
{
public:
  /**
   * points: numberOfPoints xyz triples in world coordinates, all inside the
   * grid's box. reach: l + eta/2; distances at or beyond it are truncated.
   */
  TruncatedDistance(
    const Grid& grid, const double* points, std::int64_t numberOfPoints, double reach, Monitor* monitor = nullptr);
  /**
   * The grid and the reach only, without points: for a source that sorts and
   * holds the points itself (the device back end, nvDeviceDistance.h), which
   * gives the distances and the bricks reached. ComputeBrick, BrickWithin
   * and ReachedBricks must not be called on it.
   */
  TruncatedDistance(const Grid& grid, double reach);

  const Grid& GetGrid() const { return this->GridNodes; }
  double GetReach() const { return this->Reach; }
  /// The grid and the reach in cells (nvBandTerms.h), with the covering
  /// radius `coverRadius` (world units; 0: none), as the device's kernels
  /// read them too.
  DistanceConstants GetConstants(double coverRadius = 0.0) const
  {
    DistanceConstants c = this->Constants;
    SetCoverRadius(c, coverRadius);
    return c;
  }
  std::int64_t GetNumberOfPoints() const { return static_cast<std::int64_t>(this->Points.size() / 3); }

  const std::array<std::int64_t, 3>& GetBrickDims() const { return this->BrickDims; }
  std::int64_t GetNumberOfBricks() const { return this->BrickDims[0] * this->BrickDims[1] * this->BrickDims[2]; }
  /// First node (i, j, k) of a brick.
  void BrickFirstNode(std::int64_t brick, std::int64_t ijk[3]) const;

  /// Bricks holding at least one node within reach of a point, in ascending order.
  std::vector<std::int64_t> ReachedBricks() const;

  /**
   * The distance d of eq. (6) at the BrickNodes nodes of a brick, indexed
   * i + 8 (j + 8 k) from the brick's first node. Nodes whose nearest point is
   * at or beyond the reach, and nodes past the grid's end, get +infinity.
   */
  void ComputeBrick(std::int64_t brick, double distance[BrickNodes]) const;

  /**
   * Whether one point lies within `radius` (world units) of every node of the
   * brick, so that d <= radius on the whole brick: then no node of the brick
   * can be a band node with d > radius, and its distances need not be
   * computed. Cheap: it stops at the first such point, and looks at the
   * brick's own points first.
   */
  bool BrickWithin(std::int64_t brick, double radius) const;

private:
  Grid GridNodes;
  double Reach;
  std::array<std::int64_t, 3> BrickDims;
  DistanceConstants Constants;           ///< without a covering radius
  std::vector<double> Points;            ///< relative to the grid origin, sorted by brick
  std::vector<std::int64_t> BucketStart; ///< points of brick b: [BucketStart[b], BucketStart[b+1])
};

/**
 * The index range [first, last) of `bricks` (ascending brick indices, hence
 * ordered by brick layer) that lie in brick layers [layerBegin, layerEnd).
 */
void BricksInLayers(const std::vector<std::int64_t>& bricks,
  std::int64_t bricksPerLayer, std::int64_t layerBegin, std::int64_t layerEnd, std::int64_t& first,
  std::int64_t& last);

} // namespace nv

#endif
