// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The points sorted into the grid's bricks of 8 x 8 x 8 nodes (a counting
// sort) and the bricks they reach, the collect pass's data structure: written once,
// as kernels over arrays (a point, a brick or a chunk of bricks a call), for
// the CPU core (TruncatedDistance, over the thread pool) and the GPU (the
// device back end's launchers, nvDeviceLauncher.h). The sort's counts and
// slots are atomic, so any number of threads may run each pass; between the
// passes the caller sums the chunks' totals (ChunkStarts).
//
//   BucketPointsKernel   each point's brick, the bricks' counts
//   ChunkSumKernel       the counts of each chunk of ChunkBricks bricks
//   ChunkStarts          where each chunk begins (host)
//   ChunkScanKernel      the buckets' starts, and their free slots
//   ScatterPointsKernel  each point into a free slot of its bucket
//   ReachKernel          the bricks within reach of a point, marked (eq. 7)
//   ChunkSumKernel, ChunkStarts, ReachListKernel: the marked bricks listed
//
// The kernels are plain C++ for the host compiler and CUDA (no STL beyond
// <cmath> and <cstdint>); the host's passes in order are at the end.
#ifndef nvPointSort_h
#define nvPointSort_h

#include "nvBandTerms.h"
#include "nvHostDevice.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace nv
{

/// x += value, atomically, returning x's value before: the counting sort's
/// counts and slots, from many threads at once.
NV_HD inline std::int64_t AtomicAdd(std::int64_t* x, std::int64_t value)
{
#if defined(__CUDA_ARCH__)
  return static_cast<std::int64_t>(atomicAdd(reinterpret_cast<unsigned long long*>(x),
    static_cast<unsigned long long>(value)));
#else
  return __atomic_fetch_add(x, value, __ATOMIC_RELAXED);
#endif
}

/// x = 1 where several threads may write 1 at once: a relaxed atomic store
/// on the host (a plain store there is a data race for the language), a
/// plain one on the GPU.
NV_HD inline void Mark(std::uint8_t* x)
{
#if defined(__CUDA_ARCH__)
  *x = 1;
#else
  __atomic_store_n(x, static_cast<std::uint8_t>(1), __ATOMIC_RELAXED);
#endif
}

/**
 * The cloud and its sort, as both sides hold them. Precision, array by
 * array:
 *
 * - Cloud: double, 3 a point: the points as given, in world coordinates
 *   (read once, then freed).
 * - BrickOf: int64, a point: its brick (RelativePoint).
 * - BucketStart: int64, a grid brick and one more: first the counts, at
 *   b + 1 for brick b, then, summed chunk by chunk, the buckets: the points
 *   of brick b are [BucketStart[b], BucketStart[b + 1]). 64 bits, for
 *   clouds of more than 4.29e9 points.
 * - Next: int64, a grid brick: the next free slot of each bucket while the
 *   points are placed.
 * - Points: double, 3 a point: (x - origin) / h, sorted by brick, the
 *   same bits on both sides (one subtraction and one division, each
 *   correctly rounded). Within a bucket the points lie in the order the
 *   threads placed them, which may differ from run to run: every use of
 *   them (the least distance, whether one covers a brick, the bricks
 *   reached) is the same in any order. Double, so that a point 4096 cells
 *   from the origin keeps its place to 1e-12 cells (float: 2.4e-4).
 * - Reached: uint8, a grid brick: 1 where a point's box of eq. (7) touches
 *   it.
 * - ChunkCount, ChunkFirst: int64, a chunk of ChunkBricks grid bricks: the
 *   chunks' sums (of counts, or of reached bricks) and, summed on the host,
 *   where each chunk's part begins.
 * - ReachList: int64, the reached bricks in ascending order.
 */
struct PointArrays
{
  std::int64_t NumberOfPoints = 0;
  std::int64_t NumberOfBricks = 0;
  const double* Cloud = nullptr;
  std::int64_t* BrickOf = nullptr;
  std::int64_t* BucketStart = nullptr;
  std::int64_t* Next = nullptr;
  double* Points = nullptr;
  std::uint8_t* Reached = nullptr;
  std::int64_t* ChunkCount = nullptr;
  const std::int64_t* ChunkFirst = nullptr;
  std::int64_t* ReachList = nullptr;
};

/// The bricks a thread sums or lists in the sort's chunked sums.
constexpr std::int64_t ChunkBricks = 256;

/// The grid's box and bricks, computed once on the host.
struct PointConstants
{
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Spacing = 0.0;                    ///< h
  std::int64_t GridDims[3] = { 0, 0, 0 };
  std::int64_t BrickDims[3] = { 0, 0, 0 };
  double Reach = 0.0;                      ///< (l + eta/2) / h, in cells
};

/// The end of chunk c's bricks [c ChunkBricks, end).
NV_HD inline std::int64_t ChunkEnd(const PointArrays& A, std::int64_t c)
{
  return (c + 1) * ChunkBricks < A.NumberOfBricks ? (c + 1) * ChunkBricks : A.NumberOfBricks;
}

/// Point p relative to the grid's origin, in cells, and its brick: the
/// brick of the node below it on each axis, clamped into the grid (a point
/// on the box's far faces goes to the last brick).
NV_HD inline std::int64_t RelativePoint(const PointArrays& A, const PointConstants& C, std::int64_t p, double rel[3])
{
  std::int64_t at[3];
  for (int a = 0; a < 3; ++a)
  {
    rel[a] = (A.Cloud[3 * p + a] - C.Origin[a]) / C.Spacing;
    const std::int64_t brick = static_cast<std::int64_t>(::floor(rel[a])) >> 3;
    at[a] = brick < 0 ? 0 : (brick > C.BrickDims[a] - 1 ? C.BrickDims[a] - 1 : brick);
  }
  return at[0] + C.BrickDims[0] * (at[1] + C.BrickDims[1] * at[2]);
}

/// Point p's brick, and its count (BucketStart[b + 1], cleared before).
struct BucketPointsKernel
{
  PointArrays A;
  PointConstants C;
  NV_HD void operator()(std::int64_t p) const
  {
    double rel[3];
    const std::int64_t b = RelativePoint(A, C, p, rel);
    A.BrickOf[p] = b;
    AtomicAdd(A.BucketStart + b + 1, 1);
  }
};

/// The sum of chunk c's values (Values[b] over its bricks b): the counts
/// (BucketStart + 1) or the reached bricks' marks (Reached).
template <typename T>
struct ChunkSumKernel
{
  PointArrays A;
  const T* Values;
  NV_HD void operator()(std::int64_t c) const
  {
    const std::int64_t end = ChunkEnd(A, c);
    std::int64_t sum = 0;
    for (std::int64_t b = c * ChunkBricks; b < end; ++b)
    {
      sum += Values[b];
    }
    A.ChunkCount[c] = sum;
  }
};

/// Chunk c's counts summed into BucketStart from ChunkFirst[c] on, and the
/// buckets' free slots (Next) set to their starts.
struct ChunkScanKernel
{
  PointArrays A;
  NV_HD void operator()(std::int64_t c) const
  {
    const std::int64_t end = ChunkEnd(A, c);
    std::int64_t sum = A.ChunkFirst[c];
    for (std::int64_t b = c * ChunkBricks; b < end; ++b)
    {
      A.Next[b] = sum;
      sum += A.BucketStart[b + 1];
      A.BucketStart[b + 1] = sum;
    }
    if (c == 0)
    {
      A.BucketStart[0] = 0;
    }
  }
};

/// Point p into the next free slot of its bucket.
struct ScatterPointsKernel
{
  PointArrays A;
  PointConstants C;
  NV_HD void operator()(std::int64_t p) const
  {
    double rel[3];
    RelativePoint(A, C, p, rel);
    const std::int64_t slot = AtomicAdd(A.Next + A.BrickOf[p], 1);
    for (int a = 0; a < 3; ++a)
    {
      A.Points[3 * slot + a] = rel[a];
    }
  }
};

/// The bricks that sorted point p's box of nodes within reach touches
/// (eq. 7), marked (marks of 1 from several threads at once).
struct ReachKernel
{
  PointArrays A;
  PointConstants C;
  NV_HD void operator()(std::int64_t p) const
  {
    std::int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      const double x = A.Points[3 * p + a];
      const std::int64_t up = BoxFirst(x, C.Reach);
      const std::int64_t down = BoxLast(x, C.Reach);
      const std::int64_t first = up > 0 ? up : 0;
      const std::int64_t last = down < C.GridDims[a] - 1 ? down : C.GridDims[a] - 1;
      lo[a] = first >> 3;
      hi[a] = (first > last ? first : last) >> 3;
    }
    for (std::int64_t bk = lo[2]; bk <= hi[2]; ++bk)
    {
      for (std::int64_t bj = lo[1]; bj <= hi[1]; ++bj)
      {
        for (std::int64_t bi = lo[0]; bi <= hi[0]; ++bi)
        {
          Mark(A.Reached + bi + C.BrickDims[0] * (bj + C.BrickDims[1] * bk));
        }
      }
    }
  }
};

/// Chunk c's reached bricks, ascending, into ReachList from ChunkFirst[c] on.
struct ReachListKernel
{
  PointArrays A;
  NV_HD void operator()(std::int64_t c) const
  {
    const std::int64_t end = ChunkEnd(A, c);
    std::int64_t at = A.ChunkFirst[c];
    for (std::int64_t b = c * ChunkBricks; b < end; ++b)
    {
      if (A.Reached[b])
      {
        A.ReachList[at++] = b;
      }
    }
  }
};

// ---------------------------------------------------------------------------
// On the host (nvPointSort.cxx): the passes above in order, over the thread
// pool (nvParallel.h), for TruncatedDistance and the host launcher.

struct Grid;

/// Where each chunk's part begins (PointArrays::ChunkFirst) from the
/// chunks' sums, summed in order; returns their total.
std::int64_t ChunkStarts(const std::vector<std::int64_t>& sums, std::vector<std::int64_t>& first);

class Monitor;

/// The constants of `grid` and the reach (l + eta/2, world units), in
/// cells as the kernels read them.
PointConstants PointConstantsOf(const Grid& grid, double reach);

/// The counting sort of `cloud` (numberOfPoints xyz triples, world
/// coordinates) into `points` (3 a point, relative, sorted by brick) and
/// `bucketStart` (a brick of the grid and one more), both allocated by the
/// caller. False, the sort unfinished, if the monitor (may be null) asked
/// to stop between the passes' rounds (a sort of millions takes a second).
bool SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants, double* points,
  std::int64_t* bucketStart, Monitor* monitor = nullptr);

/// The bricks that the sorted `points` reach (eq. 7), ascending.
std::vector<std::int64_t> ListReachedBricks(
  const double* points, std::int64_t numberOfPoints, const PointConstants& constants);

} // namespace nv

#endif
