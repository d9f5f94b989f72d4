// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvTruncatedDistance.h"

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
  const Grid& grid, const double* points, std::int64_t numberOfPoints, double reach)
  : TruncatedDistance(grid, reach)
{
  const std::int64_t bricks = this->GetNumberOfBricks();

  // Counting sort of the points by brick. Coordinates are kept relative to the
  // grid origin, in cells (x - origin) / h, so that far-from-origin clouds
  // keep their precision and the inner loops need no division.
  std::vector<std::int64_t> brickOf(static_cast<std::size_t>(numberOfPoints));
  this->BucketStart.assign(static_cast<std::size_t>(bricks + 1), 0);
  for (std::int64_t p = 0; p < numberOfPoints; ++p)
  {
    double rel[3];
    for (int a = 0; a < 3; ++a)
    {
      rel[a] = (points[3 * p + a] - grid.Origin[a]) / grid.Spacing;
    }
    const std::int64_t b = this->BrickOfPoint(rel, 0) +
      this->BrickDims[0] * (this->BrickOfPoint(rel, 1) + this->BrickDims[1] * this->BrickOfPoint(rel, 2));
    brickOf[static_cast<std::size_t>(p)] = b;
    ++this->BucketStart[static_cast<std::size_t>(b + 1)];
  }
  for (std::int64_t b = 0; b < bricks; ++b)
  {
    this->BucketStart[b + 1] += this->BucketStart[b];
  }
  std::vector<std::int64_t> next(this->BucketStart.begin(), this->BucketStart.end() - 1);
  this->Points.resize(static_cast<std::size_t>(3 * numberOfPoints));
  for (std::int64_t p = 0; p < numberOfPoints; ++p)
  {
    const std::int64_t slot = next[static_cast<std::size_t>(brickOf[p])]++;
    for (int a = 0; a < 3; ++a)
    {
      this->Points[3 * slot + a] = (points[3 * p + a] - grid.Origin[a]) / grid.Spacing;
    }
  }
}

std::int64_t TruncatedDistance::BrickOfPoint(const double p[3], int axis) const
{
  const std::int64_t node = static_cast<std::int64_t>(std::floor(p[axis]));
  return std::min(std::max<std::int64_t>(node >> BrickShift, 0), this->BrickDims[axis] - 1);
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
  // Mark, for every point, the bricks that its box of nodes within reach touches (eq. 7).
  const double reach = this->Reach / this->GridNodes.Spacing; // in cells
  std::vector<unsigned char> reached(static_cast<std::size_t>(this->GetNumberOfBricks()), 0);
  const std::int64_t numberOfPoints = this->GetNumberOfPoints();
  for (std::int64_t p = 0; p < numberOfPoints; ++p)
  {
    std::int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      const double x = this->Points[3 * p + a];
      const std::int64_t first = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil(x - reach)));
      const std::int64_t last =
        std::min<std::int64_t>(this->GridNodes.Dims[a] - 1, static_cast<std::int64_t>(std::floor(x + reach)));
      lo[a] = first >> BrickShift;
      hi[a] = std::max(first, last) >> BrickShift;
    }
    for (std::int64_t bk = lo[2]; bk <= hi[2]; ++bk)
    {
      for (std::int64_t bj = lo[1]; bj <= hi[1]; ++bj)
      {
        for (std::int64_t bi = lo[0]; bi <= hi[0]; ++bi)
        {
          reached[bi + this->BrickDims[0] * (bj + this->BrickDims[1] * bk)] = 1;
        }
      }
    }
  }
  std::vector<std::int64_t> result;
  for (std::size_t b = 0; b < reached.size(); ++b)
  {
    if (reached[b])
    {
      result.push_back(static_cast<std::int64_t>(b));
    }
  }
  return result;
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
