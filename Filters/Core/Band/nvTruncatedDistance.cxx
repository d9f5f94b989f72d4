// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvTruncatedDistance.h"

#include "nvPointSort.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nv
{

TruncatedDistance::TruncatedDistance(const Grid& grid, double reach)
  : GridNodes(grid)
  , Reach(reach)
{
  for (int a = 0; a < 3; ++a)
  {
    this->BrickDims[a] = (grid.Dims[a] + BrickSize - 1) / BrickSize;
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
  ijk[0] = (brick % this->BrickDims[0]) * BrickSize;
  brick /= this->BrickDims[0];
  ijk[1] = (brick % this->BrickDims[1]) * BrickSize;
  ijk[2] = (brick / this->BrickDims[1]) * BrickSize;
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
  // In cells, with a relative margin so that a node whose computed distance
  // rounds just above the radius is never left out.
  const double r = radius / this->GridNodes.Spacing * (1.0 - 1e-9);
  if (!(r > 0.0))
  {
    return false;
  }
  const double r2 = r * r;
  std::int64_t first[3], last[3];
  this->BrickFirstNode(brick, first);
  for (int a = 0; a < 3; ++a)
  {
    last[a] = std::min<std::int64_t>(first[a] + BrickSize, this->GridNodes.Dims[a]) - 1;
  }
  // The farthest node of the brick from x is a corner.
  auto coversBrick = [&](const double* x) {
    double far2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double far = std::max(std::fabs(x[a] - first[a]), std::fabs(x[a] - last[a]));
      far2 += far * far;
    }
    return far2 <= r2;
  };
  auto scanBucket = [&](std::int64_t bucket) {
    for (std::int64_t p = this->BucketStart[bucket]; p < this->BucketStart[bucket + 1]; ++p)
    {
      if (coversBrick(&this->Points[3 * p]))
      {
        return true;
      }
    }
    return false;
  };
  if (scanBucket(brick))
  {
    return true;
  }
  // A covering point is within r of the brick's nodes: in the buckets around.
  const std::int64_t margin = static_cast<std::int64_t>(std::ceil(r)) + 1;
  std::int64_t lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max<std::int64_t>(0, last[a] - margin) >> BrickShift;
    hi[a] = std::min<std::int64_t>(this->BrickDims[a] - 1, (first[a] + margin) >> BrickShift);
  }
  for (std::int64_t bk = lo[2]; bk <= hi[2]; ++bk)
  {
    for (std::int64_t bj = lo[1]; bj <= hi[1]; ++bj)
    {
      for (std::int64_t bi = lo[0]; bi <= hi[0]; ++bi)
      {
        const std::int64_t bucket = bi + this->BrickDims[0] * (bj + this->BrickDims[1] * bk);
        if (bucket != brick && scanBucket(bucket))
        {
          return true;
        }
      }
    }
  }
  return false;
}

void TruncatedDistance::ComputeBrick(std::int64_t brick, double distance[BrickNodes]) const
{
  // Everything in cells: node (i, j, k) sits at (i, j, k), points at x / h.
  const double h = this->GridNodes.Spacing;
  const double reach = this->Reach / h;
  const double reach2 = reach * reach;
  const double infinity = std::numeric_limits<double>::infinity();

  std::int64_t first[3], last[3];
  this->BrickFirstNode(brick, first);
  for (int a = 0; a < 3; ++a)
  {
    last[a] = std::min<std::int64_t>(first[a] + BrickSize, this->GridNodes.Dims[a]) - 1;
  }

  // Squared distances first; the square root is taken once per node at the end.
  double d2[BrickNodes];
  std::fill(d2, d2 + BrickNodes, infinity);

  // Buckets whose points may reach this brick: a point reaches node i only if
  // |x - i| < reach, so its node index lies within reach + 1 of the brick.
  const std::int64_t margin = static_cast<std::int64_t>(std::ceil(reach)) + 1;
  std::int64_t bucketLo[3], bucketHi[3];
  for (int a = 0; a < 3; ++a)
  {
    bucketLo[a] = std::max<std::int64_t>(0, first[a] - margin) >> BrickShift;
    bucketHi[a] = std::min<std::int64_t>(this->BrickDims[a] - 1, (last[a] + margin) >> BrickShift);
  }

  for (std::int64_t bk = bucketLo[2]; bk <= bucketHi[2]; ++bk)
  {
    for (std::int64_t bj = bucketLo[1]; bj <= bucketHi[1]; ++bj)
    {
      for (std::int64_t bi = bucketLo[0]; bi <= bucketHi[0]; ++bi)
      {
        const std::int64_t bucket = bi + this->BrickDims[0] * (bj + this->BrickDims[1] * bk);
        for (std::int64_t p = this->BucketStart[bucket]; p < this->BucketStart[bucket + 1]; ++p)
        {
          const double* x = &this->Points[3 * p];
          // The point's box of nodes (eq. 7), clipped to this brick.
          std::int64_t lo[3], hi[3];
          bool empty = false;
          for (int a = 0; a < 3; ++a)
          {
            lo[a] = std::max(first[a], static_cast<std::int64_t>(std::ceil(x[a] - reach)));
            hi[a] = std::min(last[a], static_cast<std::int64_t>(std::floor(x[a] + reach)));
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
            const double dx = static_cast<double>(i) - x[0];
            dx2[i - lo[0]] = dx * dx;
          }
          const int rowLength = static_cast<int>(hi[0] - lo[0] + 1);
          for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
          {
            const double dz = static_cast<double>(k) - x[2];
            const double dz2 = dz * dz;
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            {
              const double dy = static_cast<double>(j) - x[1];
              const double dyz2 = dz2 + dy * dy;
              if (dyz2 >= reach2)
              {
                continue;
              }
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
    distance[n] = d2[n] < reach2 ? std::sqrt(d2[n]) * h : infinity;
  }
}

} // namespace nv
