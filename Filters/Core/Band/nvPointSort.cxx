// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPointSort.h"

#include "nvGrid.h"
#include "nvParallel.h"

#include <algorithm>

namespace nv
{
namespace
{
constexpr std::int64_t PointGrain = 4096; ///< points a task

/// kernel(i) for i in [begin, end), `grain` a task, over the thread pool;
/// false if the monitor (may be null) asked to stop between rounds.
template <typename Kernel>
bool ForEach(std::int64_t begin, std::int64_t end, std::int64_t grain, const Kernel& kernel, Monitor* monitor = nullptr)
{
  return StoppableFor(begin, end, grain, monitor, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t i = first; i < last; ++i)
    {
      kernel(i);
    }
  });
}

std::int64_t NumberOfChunks(const PointArrays& a)
{
  return (a.NumberOfBricks + ChunkBricks - 1) / ChunkBricks;
}

PointArrays ArraysOf(const PointConstants& constants, std::int64_t numberOfPoints)
{
  PointArrays a;
  a.NumberOfPoints = numberOfPoints;
  a.NumberOfBricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
  return a;
}
} // namespace

std::int64_t ChunkStarts(const std::vector<std::int64_t>& sums, std::vector<std::int64_t>& first)
{
  first.resize(sums.size());
  std::int64_t total = 0;
  for (std::size_t c = 0; c < sums.size(); ++c)
  {
    first[c] = total;
    total += sums[c];
  }
  return total;
}

PointConstants PointConstantsOf(const Grid& grid, double reach)
{
  PointConstants constants;
  for (int a = 0; a < 3; ++a)
  {
    constants.Origin[a] = grid.Origin[a];
    constants.GridDims[a] = grid.Dims[a];
    constants.BrickDims[a] = (grid.Dims[a] + 7) / 8;
  }
  constants.Spacing = grid.Spacing;
  constants.Reach = reach / grid.Spacing;
  return constants;
}

bool SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants, double* points,
  std::int64_t* bucketStart, Monitor* monitor)
{
  PointArrays a = ArraysOf(constants, numberOfPoints);
  std::vector<std::int64_t> brickOf(static_cast<std::size_t>(numberOfPoints));
  std::vector<std::int64_t> next(static_cast<std::size_t>(a.NumberOfBricks));
  std::vector<std::int64_t> sums(static_cast<std::size_t>(NumberOfChunks(a))), first;
  std::fill(bucketStart, bucketStart + a.NumberOfBricks + 1, std::int64_t(0));
  a.Cloud = cloud;
  a.BrickOf = brickOf.data();
  a.BucketStart = bucketStart;
  a.Next = next.data();
  a.Points = points;
  a.ChunkCount = sums.data();
  if (!ForEach(0, numberOfPoints, PointGrain, BucketPointsKernel{ a, constants }, monitor))
  {
    return false;
  }
  ForEach(0, NumberOfChunks(a), 16, ChunkSumKernel<std::int64_t>{ a, a.BucketStart + 1 });
  ChunkStarts(sums, first);
  a.ChunkFirst = first.data();
  ForEach(0, NumberOfChunks(a), 16, ChunkScanKernel{ a });
  return ForEach(0, numberOfPoints, PointGrain, ScatterPointsKernel{ a, constants }, monitor);
}

std::vector<std::int64_t> ListReachedBricks(
  const double* points, std::int64_t numberOfPoints, const PointConstants& constants)
{
  PointArrays a = ArraysOf(constants, numberOfPoints);
  std::vector<std::uint8_t> marks(static_cast<std::size_t>(a.NumberOfBricks), 0);
  std::vector<std::int64_t> sums(static_cast<std::size_t>(NumberOfChunks(a))), first;
  a.Points = const_cast<double*>(points); // read only by these kernels
  a.Reached = marks.data();
  a.ChunkCount = sums.data();
  ForEach(0, numberOfPoints, PointGrain, ReachKernel{ a, constants });
  ForEach(0, NumberOfChunks(a), 16, ChunkSumKernel<std::uint8_t>{ a, a.Reached });
  std::vector<std::int64_t> reached(static_cast<std::size_t>(ChunkStarts(sums, first)));
  a.ChunkFirst = first.data();
  a.ReachList = reached.data();
  ForEach(0, NumberOfChunks(a), 16, ReachListKernel{ a });
  return reached;
}

} // namespace nv
