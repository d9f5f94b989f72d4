// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvTruncatedDistance.h"

#include "nvPointSort.h"

#include <algorithm>

namespace nv
{

TruncatedDistance::TruncatedDistance(const Grid& grid, double reach)
  : GridNodes(grid)
  , Reach(reach)
  , Constants(DistanceConstantsOf(grid, reach, 0.0))
{
  for (int a = 0; a < 3; ++a)
  {
    this->BrickDims[a] = this->Constants.BrickDims[a];
  }
}

TruncatedDistance::TruncatedDistance(
  const Grid& grid, const double* points, std::int64_t numberOfPoints, double reach, Monitor* monitor)
  : TruncatedDistance(grid, reach)
{
  // Counting sort of the points by brick (nvPointSort.h, on the threads).
  // Coordinates are kept relative to the grid origin, in cells
  // (x - origin) / h, so that far-from-origin clouds keep their precision
  // and the inner loops need no division.
  this->Points.resize(static_cast<std::size_t>(3 * numberOfPoints));
  this->BucketStart.resize(static_cast<std::size_t>(this->GetNumberOfBricks() + 1));
  if (!SortPoints(
        points, numberOfPoints, PointConstantsOf(grid, reach), this->Points.data(), this->BucketStart.data(), monitor))
  {
    this->Points.clear(); // stopped: no points (the caller asks the monitor, and goes no further)
    std::fill(this->BucketStart.begin(), this->BucketStart.end(), std::int64_t(0));
  }
}

void TruncatedDistance::BrickFirstNode(std::int64_t brick, std::int64_t ijk[3]) const
{
  FirstNodeOf(this->Constants.BrickDims, brick, ijk);
}

std::vector<std::int64_t> TruncatedDistance::ReachedBricks() const
{
  // Mark, for every point, the bricks that its box of nodes within reach
  // touches (eq. 7), and list them (nvPointSort.h, on the threads).
  return ListReachedBricks(
    this->Points.data(), this->GetNumberOfPoints(), PointConstantsOf(this->GridNodes, this->Reach));
}

void BricksInLayers(const std::vector<std::int64_t>& bricks, std::int64_t bricksPerLayer,
  std::int64_t layerBegin, std::int64_t layerEnd, std::int64_t& first, std::int64_t& last)
{
  first = std::lower_bound(bricks.begin(), bricks.end(), layerBegin * bricksPerLayer) - bricks.begin();
  last = std::lower_bound(bricks.begin(), bricks.end(), layerEnd * bricksPerLayer) - bricks.begin();
}

bool TruncatedDistance::BrickWithin(std::int64_t brick, double radius) const
{
  // The covering test of nvBandTerms.h, as the device's CoveredKernel.
  return BrickCovered(this->GetConstants(radius), this->Points.data(), this->BucketStart.data(), brick);
}

void TruncatedDistance::ComputeBrick(std::int64_t brick, double distance[BrickNodes]) const
{
  // Everything in cells: node (i, j, k) sits at (i, j, k), points at x / h
  // (nvBandTerms.h's terms, which the device's DistanceKernel reads too).
  const DistanceConstants c = this->Constants;
  const double reach = c.Reach;

  std::int64_t first[3], last[3];
  BrickNodeRange(c, brick, first, last);

  // Squared distances first; the square root is taken once per node at the end.
  double d2[BrickNodes];
  std::fill(d2, d2 + BrickNodes, c.Infinity);

  // Buckets whose points may reach this brick: a point reaches node i only if
  // |x - i| < reach, so its node index lies within reach + 1 of the brick.
  std::int64_t bucketLo[3], bucketHi[3];
  BucketRange(c.BrickDims, first, last, c.Margin, bucketLo, bucketHi);

  for (std::int64_t bk = bucketLo[2]; bk <= bucketHi[2]; ++bk)
  {
    for (std::int64_t bj = bucketLo[1]; bj <= bucketHi[1]; ++bj)
    {
      for (std::int64_t bi = bucketLo[0]; bi <= bucketHi[0]; ++bi)
      {
        const std::int64_t bucket = BrickIndexOf(c.BrickDims, bi, bj, bk);
        for (std::int64_t p = this->BucketStart[bucket]; p < this->BucketStart[bucket + 1]; ++p)
        {
          const double* x = &this->Points[3 * p];
          // The point's box of nodes (eq. 7), clipped to this brick.
          std::int64_t lo[3], hi[3];
          bool empty = false;
          for (int a = 0; a < 3; ++a)
          {
            lo[a] = std::max(first[a], BoxFirst(x[a], reach));
            hi[a] = std::min(last[a], BoxLast(x[a], reach));
            empty = empty || lo[a] > hi[a];
          }
          if (empty)
          {
            continue;
          }
          // dx^2 along the row, computed once per point and brick.
          double dx2[BrickSize];
          for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
          {
            dx2[i - lo[0]] = AxisSquare(static_cast<double>(i), x[0]);
          }
          const int rowLength = static_cast<int>(hi[0] - lo[0] + 1);
          for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
          {
            const double dz2 = AxisSquare(static_cast<double>(k), x[2]);
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            {
              const double dyz2 = AddSquare(dz2, static_cast<double>(j), x[1]);
              if (BeyondReach(dyz2, c))
              {
                continue;
              }
              // (dz^2 + dy^2) + dx^2, as AddSquare (a + b on the host).
              double* row = d2 + ((j - first[1]) + BrickSize * (k - first[2])) * BrickSize + (lo[0] - first[0]);
              for (int i = 0; i < rowLength; ++i)
              {
                row[i] = std::min(row[i], dyz2 + dx2[i]);
              }
            }
          }
        }
      }
    }
  }

  for (int n = 0; n < BrickNodes; ++n)
  {
    distance[n] = TruncatedOf(d2[n], c);
  }
}

} // namespace nv
