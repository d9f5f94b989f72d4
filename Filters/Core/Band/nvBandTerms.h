// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The truncated distance's and the narrow band's terms (eq. 5-7), written
// once for the CPU core (TruncatedDistance, NarrowBand's collect and connect passes) and
// the device back end's kernels (Device/nvDeviceKernels.h), as nvPointSort.h
// does for the points' sort. The CPU core scatters each point over its box
// of nodes and the kernels gather each node's points, so what is shared is
// the terms (the box, the squared distance in the order (dz^2 + dy^2) + dx^2,
// the truncation, the covering test, the band test, a neighbour's place),
// not the loops; the loops that both sides run alike (the covering test's
// scan of the buckets, one brick's band nodes) are shared whole.
//
//   BrickShift, BrickSize, BrickNodes      the bricks of 8 x 8 x 8 nodes
//   MulRn, AddRn                           a * b, a + b, each rounded once
//   DistanceConstants, DistanceConstantsOf, SetCoverRadius: in cells, once
//   BrickAt, FirstNodeOf, NodeAtPlace, BrickNodeRange, BrickIndexOf,
//   BucketRange                            bricks and buckets
//   BoxFirst, BoxLast, InBox               the point's box of eq. (7)
//   AxisSquare, AddSquare, BeyondReach, TruncatedOf: d of eq. (6)
//   Larger, CoversBrick, BucketCovers, BrickCovered: the covering test
//   BandBounds, IsRed, InBand, InsideShell, ResetInside, SetBit,
//   ClassifyBrick                          the collect pass's band nodes of a brick
//   AdjacentBrick, NeighbourPlace, DirichletSlot: the connect pass's neighbours
//
// Written twice still, each side's way by design: the distance's loops
// (ComputeBrick scatters each point over its box with a vectorised row
// minimum, DistanceKernel gathers a node's points, a thread a node, with no
// atomic minimum); where the collect pass's band nodes go (growing lists a brick on
// the CPU, counts then a compaction on the device); how the connect pass finds a
// brick's slot and a neighbour's index (a table over the grid's bricks and
// a rank table on the CPU, binary searches, IndexOf, on the device, which
// also finds a node's brick by LastAtOrBelow where the CPU loops brick by
// brick).
//
// The functions are plain C++ for the host compiler and CUDA (NV_HD; no STL
// in them beyond <cmath> and <cstdint>); DistanceConstantsOf runs on the
// host only.
#ifndef nvBandTerms_h
#define nvBandTerms_h

#include "nvGrid.h"
#include "nvHostDevice.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace nv
{

constexpr int BrickShift = 3;
constexpr int BrickSize = 1 << BrickShift;               ///< nodes per brick side
constexpr int BrickNodes = BrickSize * BrickSize * BrickSize; ///< 512

/// a * b and a + b, each rounded once: nvcc would otherwise fuse
/// a * b + c into one fused multiply-add, rounded once instead of twice, and
/// the GPU's distances would differ from the CPU core's in the last bit. On
/// the host they are a * b and a + b. With them the GPU's distances should
/// be the CPU core's bit for bit (CUDA's double square root is IEEE's
/// correctly rounded one too), which TestCoreDevice cuda checks on a GPU.
NV_HD inline double MulRn(double a, double b)
{
#if defined(__CUDA_ARCH__)
  return __dmul_rn(a, b);
#else
  return a * b;
#endif
}
NV_HD inline double AddRn(double a, double b)
{
#if defined(__CUDA_ARCH__)
  return __dadd_rn(a, b);
#else
  return a + b;
#endif
}

/// The grid and the reach in cells, as the distance's terms read them:
/// computed once on the host (DistanceConstantsOf), for TruncatedDistance
/// and the device's kernels alike.
struct DistanceConstants
{
  std::int64_t GridDims[3] = { 0, 0, 0 };
  std::int64_t BrickDims[3] = { 0, 0, 0 };
  double Spacing = 0.0;     ///< h
  double Reach = 0.0;       ///< (l + eta/2) / h, in cells
  double Reach2 = 0.0;      ///< Reach^2
  std::int64_t Margin = 0;  ///< ceil(Reach) + 1: the bricks whose points may reach a brick
  double Infinity = 0.0;    ///< +inf, made on the host
  bool TestCover = false;   ///< whether BrickCovered tests anything (radius > 0)
  double Cover2 = 0.0;      ///< the covering radius r^2, r = radius / h (1 - 1e-9)
  std::int64_t CoverMargin = 0; ///< ceil(r) + 1
};

/// The covering test's radius (BrickCovered), world units, into `c`: in
/// cells, with a relative margin so that a node whose computed distance
/// rounds just above the radius is never left out. A radius of 0 (or
/// below) tests nothing.
inline void SetCoverRadius(DistanceConstants& c, double radius)
{
  const double r = radius / c.Spacing * (1.0 - 1e-9);
  c.TestCover = r > 0.0;
  c.Cover2 = c.TestCover ? r * r : 0.0;
  c.CoverMargin = c.TestCover ? static_cast<std::int64_t>(std::ceil(r)) + 1 : 0;
}

/// The constants of `grid`, the reach l + eta/2 and the covering radius
/// (world units; 0: no covering test): everything in cells, node (i, j, k)
/// at (i, j, k), a point at (x - origin) / h.
inline DistanceConstants DistanceConstantsOf(const Grid& grid, double reach, double coverRadius)
{
  DistanceConstants c;
  for (int a = 0; a < 3; ++a)
  {
    c.GridDims[a] = grid.Dims[a];
    c.BrickDims[a] = (grid.Dims[a] + BrickSize - 1) / BrickSize;
  }
  c.Spacing = grid.Spacing;
  c.Reach = reach / grid.Spacing;
  c.Reach2 = c.Reach * c.Reach;
  // A point reaches node i only if |x - i| < reach, so its node index lies
  // within reach + 1 of the node.
  c.Margin = static_cast<std::int64_t>(std::ceil(c.Reach)) + 1;
  c.Infinity = std::numeric_limits<double>::infinity();
  SetCoverRadius(c, coverRadius);
  return c;
}

// ---------------------------------------------------------------------------
// Bricks and buckets: a brick of the grid is also the bucket of the points
// sorted into it (nvPointSort.h).

/// Brick `brick`'s place (bi, bj, bk) in a grid of brickDims bricks.
NV_HD inline void BrickAt(const std::int64_t brickDims[3], std::int64_t brick, std::int64_t at[3])
{
  at[0] = brick % brickDims[0];
  brick /= brickDims[0];
  at[1] = brick % brickDims[1];
  at[2] = brick / brickDims[1];
}

/// The first node (i, j, k) of brick `brick` of a grid of brickDims bricks.
NV_HD inline void FirstNodeOf(const std::int64_t brickDims[3], std::int64_t brick, std::int64_t first[3])
{
  BrickAt(brickDims, brick, first);
  for (int a = 0; a < 3; ++a)
  {
    first[a] *= BrickSize;
  }
}

/// Node (i, j, k) at place n = i' + 8 (j' + 8 k') of the brick whose first
/// node is `first`.
NV_HD inline void NodeAtPlace(const std::int64_t first[3], int n, std::int64_t ijk[3])
{
  ijk[0] = first[0] + (n & (BrickSize - 1));
  ijk[1] = first[1] + ((n >> BrickShift) & (BrickSize - 1));
  ijk[2] = first[2] + (n >> (2 * BrickShift));
}

/// The first node of a brick and its last one within the grid.
NV_HD inline void BrickNodeRange(
  const DistanceConstants& c, std::int64_t brick, std::int64_t first[3], std::int64_t last[3])
{
  FirstNodeOf(c.BrickDims, brick, first);
  for (int a = 0; a < 3; ++a)
  {
    last[a] = (first[a] + BrickSize < c.GridDims[a] ? first[a] + BrickSize : c.GridDims[a]) - 1;
  }
}

/// The index of brick (bi, bj, bk).
NV_HD inline std::int64_t BrickIndexOf(const std::int64_t brickDims[3], std::int64_t bi, std::int64_t bj, std::int64_t bk)
{
  return bi + brickDims[0] * (bj + brickDims[1] * bk);
}

/// The buckets [lo, hi] on each axis, within the grid, of the nodes from
/// `below` - margin to `above` + margin: those whose points may lie within
/// margin - 1 nodes of a node between below and above. For the distance of
/// a brick's nodes below, above = the brick's first and last nodes (of one
/// node: both that node); for a point within reach of every node of the
/// brick, below, above = its last and first nodes.
NV_HD inline void BucketRange(const std::int64_t brickDims[3], const std::int64_t below[3], const std::int64_t above[3],
  std::int64_t margin, std::int64_t lo[3], std::int64_t hi[3])
{
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = (below[a] - margin > 0 ? below[a] - margin : 0) >> BrickShift;
    const std::int64_t up = (above[a] + margin) >> BrickShift;
    hi[a] = up < brickDims[a] - 1 ? up : brickDims[a] - 1;
  }
}

// ---------------------------------------------------------------------------
// The truncated distance of eq. (6), in cells.

/// The point's box of nodes within reach (eq. 7) on one axis:
/// BoxFirst(x) <= i <= BoxLast(x), i.e. ceil(x - reach) <= i <= floor(x + reach).
NV_HD inline std::int64_t BoxFirst(double x, double reach)
{
  return static_cast<std::int64_t>(::ceil(x - reach));
}
NV_HD inline std::int64_t BoxLast(double x, double reach)
{
  return static_cast<std::int64_t>(::floor(x + reach));
}

/// Whether node i (an integer, as a double) lies in the point's box on one
/// axis: the test of BoxFirst(x) <= i <= BoxLast(x) without the rounding
/// functions (library calls on x86-64's baseline), since for an integer i,
/// ceil(y) <= i exactly when y <= i, and i <= floor(y) when i <= y.
NV_HD inline bool InBox(double x, double reach, double i)
{
  return x - reach <= i && i <= x + reach;
}

/// (i - x)^2 on one axis, i a node's index.
NV_HD inline double AxisSquare(double i, double x)
{
  const double d = i - x;
  return MulRn(d, d);
}

/// sum + (i - x)^2: the squared distance summed in the order
/// (dz^2 + dy^2) + dx^2, the same bits on both sides.
NV_HD inline double AddSquare(double sum, double i, double x)
{
  return AddRn(sum, AxisSquare(i, x));
}

/// Whether a partial squared distance (dz^2 + dy^2 of a row of nodes)
/// is already at or beyond the reach: no node of the row is reached.
NV_HD inline bool BeyondReach(double d2, const DistanceConstants& c)
{
  return d2 >= c.Reach2;
}

/// d of eq. (6) in world units from the least squared distance d2 in
/// cells: sqrt(d2) h, truncated to +infinity at or beyond the reach.
NV_HD inline double TruncatedOf(double d2, const DistanceConstants& c)
{
  return d2 < c.Reach2 ? MulRn(::sqrt(d2), c.Spacing) : c.Infinity;
}

// ---------------------------------------------------------------------------
// The covering test: whether one point lies within r (Cover2 = r^2) of every
// node of a brick, so that d <= r on the whole brick.

/// std::max(a, b), which is not device code: b when a < b, else a. By
/// reference as std::max, so that the host compiler makes it one max
/// instruction, as it does std::max.
NV_HD inline const double& Larger(const double& a, const double& b)
{
  return a < b ? b : a;
}

/// Whether point x lies within r of every node of [first, last]: the
/// farthest of them from x is a corner.
NV_HD inline bool CoversBrick(
  const DistanceConstants& c, const double* x, const std::int64_t first[3], const std::int64_t last[3])
{
  double far2 = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    const double far = Larger(::fabs(x[a] - static_cast<double>(first[a])), ::fabs(x[a] - static_cast<double>(last[a])));
    far2 = AddRn(far2, MulRn(far, far));
  }
  return far2 <= c.Cover2;
}

/// Whether a point of bucket `bucket` covers [first, last].
NV_HD inline bool BucketCovers(const DistanceConstants& c, const double* points, const std::int64_t* bucketStart,
  std::int64_t bucket, const std::int64_t first[3], const std::int64_t last[3])
{
  for (std::int64_t p = bucketStart[bucket]; p < bucketStart[bucket + 1]; ++p)
  {
    if (CoversBrick(c, points + 3 * p, first, last))
    {
      return true;
    }
  }
  return false;
}

/// Whether one of the sorted points (points: 3 a point, in cells, bucket b's
/// [bucketStart[b], bucketStart[b + 1])) lies within r of every node of
/// `brick`; false when c tests nothing (TestCover). Cheap: it stops at the
/// first such point, and looks at the brick's own points first, the
/// likeliest to cover it. Any order of the points gives the same answer.
NV_HD inline bool BrickCovered(
  const DistanceConstants& c, const double* points, const std::int64_t* bucketStart, std::int64_t brick)
{
  if (!c.TestCover)
  {
    return false;
  }
  std::int64_t first[3], last[3];
  BrickNodeRange(c, brick, first, last);
  if (BucketCovers(c, points, bucketStart, brick, first, last))
  {
    return true;
  }
  // A covering point is within r of the brick's nodes, its last one
  // included: in the buckets around.
  std::int64_t lo[3], hi[3];
  BucketRange(c.BrickDims, last, first, c.CoverMargin, lo, hi);
  for (std::int64_t bk = lo[2]; bk <= hi[2]; ++bk)
  {
    for (std::int64_t bj = lo[1]; bj <= hi[1]; ++bj)
    {
      for (std::int64_t bi = lo[0]; bi <= hi[0]; ++bi)
      {
        const std::int64_t bucket = BrickIndexOf(c.BrickDims, bi, bj, bk);
        if (bucket != brick && BucketCovers(c, points, bucketStart, bucket, first, last))
        {
          return true;
        }
      }
    }
  }
  return false;
}

// ---------------------------------------------------------------------------
// The collect pass: the band's nodes of one brick.

/// The band's bounds: l - eta/2 < d < l + eta/2 (|phi0| < 1 - delta), or
/// every node in Domain::WholeDomain mode.
struct BandBounds
{
  double Lower = 0.0; ///< l - eta/2
  double Upper = 0.0; ///< the reach l + eta/2, world units
  bool Whole = false; ///< Domain::WholeDomain: every node in the grid
};

/// Whether node (i, j, k) is red (i + j + k even) in the red-black order.
NV_HD inline bool IsRed(std::int64_t i, std::int64_t j, std::int64_t k)
{
  return ((i + j + k) & 1) == 0;
}

/// Whether a node of distance d is a band node.
NV_HD inline bool InBand(const BandBounds& b, double d)
{
  return b.Whole || (b.Lower < d && d < b.Upper);
}

/// Whether a node off the band lies inside the shell, d <= l - eta/2
/// (NarrowBand::Inside's bits).
NV_HD inline bool InsideShell(const BandBounds& b, double d)
{
  return d <= b.Lower;
}

/// A brick's Inside bits (8 words) before its nodes are classified: all
/// set for a covered brick (d <= l - eta/2 on all of it), else none.
NV_HD inline void ResetInside(std::uint64_t* inside, bool covered)
{
  for (int w = 0; w < BrickNodes / 64; ++w)
  {
    inside[w] = covered ? ~std::uint64_t(0) : std::uint64_t(0);
  }
}

/// Sets bit n of a brick's mask of 512 bits (8 words).
NV_HD inline void SetBit(std::uint64_t* mask, int n)
{
  mask[n / 64] |= std::uint64_t(1) << (n % 64);
}

/**
 * The nodes of one brick (first node `first`) within the grid whose
 * distances `d` (BrickNodes, n = i + 8 (j + 8 k)) are known, in ascending
 * n: fn(n, red, d[n]) for each band node; the bits of the others inside
 * the shell set in `inside` (8 words, cleared by the caller; null: not
 * set).
 */
template <typename Fn>
NV_HD inline void ClassifyBrick(const std::int64_t gridDims[3], const std::int64_t first[3], const double* d,
  const BandBounds& bounds, std::uint64_t* inside, Fn&& fn)
{
  for (int k = 0; k < BrickSize && first[2] + k < gridDims[2]; ++k)
  {
    for (int j = 0; j < BrickSize && first[1] + j < gridDims[1]; ++j)
    {
      for (int i = 0; i < BrickSize && first[0] + i < gridDims[0]; ++i)
      {
        const int n = i + BrickSize * (j + BrickSize * k);
        if (InBand(bounds, d[n]))
        {
          fn(n, IsRed(first[0] + i, first[1] + j, first[2] + k), d[n]);
        }
        else if (inside && InsideShell(bounds, d[n]))
        {
          SetBit(inside, n);
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// The connect pass: the neighbour table.

/// The brick across face `direction` (-x, +x, -y, +y, -z, +z) of the brick
/// at `at` (BrickAt), or -1 past the grid's end.
NV_HD inline std::int64_t AdjacentBrick(const std::int64_t brickDims[3], const std::int64_t at[3], int direction)
{
  std::int64_t next[3] = { at[0], at[1], at[2] };
  const int axis = direction / 2;
  next[axis] += (direction % 2) ? 1 : -1;
  const bool inGrid = next[axis] >= 0 && next[axis] < brickDims[axis];
  return inGrid ? BrickIndexOf(brickDims, next[0], next[1], next[2]) : -1;
}

/// The place of node n's neighbour in `direction`: n -/+ 1, 8 or 64 in its
/// brick, or, where the node lies on that face of the brick (across set),
/// a side's length back, in the brick across the face.
NV_HD inline int NeighbourPlace(int n, int direction, bool& across)
{
  constexpr int Last = BrickSize - 1;
  const int axis = direction / 2;
  const bool up = direction % 2 == 1;
  const int at = (n >> (BrickShift * axis)) & Last; // i, j or k in the brick
  const int step = 1 << (BrickShift * axis);        // 1, 8 or 64
  across = up ? at == Last : at == 0;
  return n + (up ? step : -step) * (across ? -Last : 1);
}

/// The Dirichlet slot of a node of distance d off whose neighbour the band
/// ends (eq. 5), in a band of `size` nodes: phi = +1 at slot size when
/// phi0 > 0, i.e. d < l (eq. 2), else phi = -1 at slot size + 1.
NV_HD inline std::uint32_t DirichletSlot(double d, double offset, std::int64_t size)
{
  return static_cast<std::uint32_t>(d < offset ? size : size + 1);
}

// Searches of the band's ascending arrays (its bricks, a brick's nodes of
// one colour), for the device's kernels and the CPU's surface alike.

/// The index of `value` in the ascending values [begin, end) of `sorted`,
/// or -1 when it is not there (a binary search: std::lower_bound is not
/// device code).
template <typename T>
NV_HD inline std::int64_t IndexOf(const T* sorted, std::int64_t begin, std::int64_t end, T value)
{
  const std::int64_t last = end;
  while (begin < end) // the first index whose value is not below `value`
  {
    const std::int64_t middle = begin + (end - begin) / 2;
    if (sorted[middle] < value)
    {
      begin = middle + 1;
    }
    else
    {
      end = middle;
    }
  }
  return begin < last && sorted[begin] == value ? begin : -1;
}

/// The last index i < count with sorted[i] <= value, or -1 (sorted
/// ascending).
NV_HD inline std::int64_t LastAtOrBelow(const std::int64_t* sorted, std::int64_t count, std::int64_t value)
{
  std::int64_t begin = 0, end = count; // the answer is begin - 1 once they meet
  while (begin < end)
  {
    const std::int64_t middle = begin + (end - begin) / 2;
    if (sorted[middle] <= value)
    {
      begin = middle + 1;
    }
    else
    {
      end = middle;
    }
  }
  return begin - 1;
}

} // namespace nv

#endif
