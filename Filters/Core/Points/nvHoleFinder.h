// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The hole finder of the gap closing (nvGapClosing.h states the measure):
// the points sorted into cells for the searches within a radius, the
// thinned cloud the holes are looked for in, and the search for the empty
// discs. Internal to Points/: the bridging (nvGapClosing.cxx) calls it.
#ifndef nvHoleFinder_h
#define nvHoleFinder_h

#include "nvGapClosing.h"
#include "nvParallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace nv
{
namespace holes
{
/// The holes are looked for among one point per cube of this side (in l).
constexpr double ThinCells = 0.5;
/// Rounds of bridging points; each about halves the empty discs left.
constexpr int MaximumRounds = 3;

/// The points (relative to the grid's origin) sorted into cubic cells
/// anchored at the origin, for the searches within a radius.
class PointCells
{
public:
  /// canonical: each cell's points sorted by their coordinates (below).
  PointCells(const Grid& grid, double cellSize, const std::vector<double>& rel, bool canonical = true)
    : Points(rel)
  {
    // The cells cover the grid's box (every point lies in it); at most
    // about 2^22 of them, whatever the offset, the same on every process.
    double extent[3], volume = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      extent[a] = std::max(1.0, static_cast<double>(grid.Dims[a] - 1)) * grid.Spacing;
      volume *= extent[a];
    }
    this->Size = std::max(cellSize, std::cbrt(volume / 4194304.0));
    std::int64_t cells = 1;
    for (int a = 0; a < 3; ++a)
    {
      this->Dims[a] = static_cast<std::int64_t>(extent[a] / this->Size) + 1;
      cells *= this->Dims[a];
    }
    // The points by cell, in ascending order within each (a sort of the
    // pairs (cell, point), in parallel), and where each cell's begin.
    const std::int64_t n = static_cast<std::int64_t>(rel.size() / 3);
    std::vector<std::pair<std::int64_t, std::int64_t>> keyed(static_cast<std::size_t>(n));
    ParallelFor(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t p = begin; p < end; ++p)
      {
        std::int64_t c[3];
        this->CellOf(&rel[3 * p], c);
        keyed[p] = { c[0] + this->Dims[0] * (c[1] + this->Dims[1] * c[2]), p };
      }
    });
    ParallelSort(keyed);
    this->Order.resize(static_cast<std::size_t>(n));
    this->Start.resize(static_cast<std::size_t>(cells + 1));
    ParallelFor(0, n + 1, 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t i = begin; i < end; ++i)
      {
        // Position i begins the cells after the previous point's, up to its own.
        const std::int64_t from = i == 0 ? 0 : keyed[i - 1].first + 1;
        const std::int64_t to = i == n ? cells : keyed[i].first;
        for (std::int64_t c = from; c <= to; ++c)
        {
          this->Start[c] = i;
        }
        if (i < n)
        {
          this->Order[i] = keyed[i].second;
        }
      }
    });
    // Each cell's points by their coordinates: the searches then visit the
    // points in an order that does not depend on the order they came in
    // (distributed runs hold them in another), and every sum over them
    // comes out the same.
    if (canonical)
    {
      const auto before = [&rel](std::int64_t a, std::int64_t b) {
        return std::lexicographical_compare(&rel[3 * a], &rel[3 * a] + 3, &rel[3 * b], &rel[3 * b] + 3);
      };
      ParallelFor(0, cells, 4096, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t c = begin; c < end; ++c)
        {
          std::sort(this->Order.begin() + this->Start[c], this->Order.begin() + this->Start[c + 1], before);
        }
      });
    }
    // The coordinates in that order, side by side: a search reads a cell's
    // points from one stretch of memory.
    this->Sorted.resize(3 * static_cast<std::size_t>(n));
    ParallelFor(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t i = begin; i < end; ++i)
      {
        std::copy(&rel[3 * this->Order[i]], &rel[3 * this->Order[i]] + 3, &this->Sorted[3 * i]);
      }
    });
  }

  /// The number of points sorted.
  std::size_t NumberOfPoints() const { return this->Order.size(); }

  /// Calls fn(q, y) for every point q (at y) within `radius` of the place
  /// x, cell by cell in the cells' order (rows of cells along x, by y, then
  /// z), each cell's points in their order. The cells that lie wholly beyond
  /// the radius are skipped (a margin of 1e-9 cells keeps every cell a
  /// rounding could put a point within it), which leaves the order the same.
  template <typename Fn>
  void ForEachWithin(const double x[3], double radius, Fn&& fn) const
  {
    std::int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((x[a] - radius) / this->Size)));
      hi[a] = std::min(this->Dims[a] - 1, static_cast<std::int64_t>(std::floor((x[a] + radius) / this->Size)));
    }
    const double r2 = radius * radius;
    const double margin = 1e-9 * this->Size;
    // How far x lies outside cell c's slab along one axis (0 inside it).
    const auto outside = [&](int a, std::int64_t c) {
      const double below = static_cast<double>(c) * this->Size - margin - x[a];
      const double above = x[a] - static_cast<double>(c + 1) * this->Size - margin;
      return std::max(0.0, std::max(below, above));
    };
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
    {
      const double dz = outside(2, k);
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      {
        const double dy = outside(1, j);
        const double rest = r2 - dy * dy - dz * dz;
        if (rest < 0.0)
        {
          continue; // the row's cells lie beyond the radius
        }
        const double along = std::sqrt(rest) + margin;
        const std::int64_t first =
          std::max(lo[0], static_cast<std::int64_t>(std::floor((x[0] - along) / this->Size)));
        const std::int64_t last =
          std::min(hi[0], static_cast<std::int64_t>(std::floor((x[0] + along) / this->Size)));
        if (first > last)
        {
          continue;
        }
        const std::int64_t row = this->Dims[0] * (j + this->Dims[1] * k);
        for (std::int64_t s = this->Start[row + first]; s < this->Start[row + last + 1]; ++s)
        {
          const double* y = &this->Sorted[3 * s];
          const double dx = y[0] - x[0], dy2 = y[1] - x[1], dz2 = y[2] - x[2];
          if (dx * dx + dy2 * dy2 + dz2 * dz2 <= r2)
          {
            fn(this->Order[s], y);
          }
        }
      }
    }
  }

private:
  void CellOf(const double x[3], std::int64_t c[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      c[a] = std::min(this->Dims[a] - 1, std::max<std::int64_t>(0, static_cast<std::int64_t>(x[a] / this->Size)));
    }
  }

  const std::vector<double>& Points;
  double Size = 1.0;
  std::int64_t Dims[3] = { 1, 1, 1 };
  std::vector<std::int64_t> Start; ///< points of cell c: Order[Start[c] .. Start[c + 1])
  std::vector<std::int64_t> Order;
  std::vector<double> Sorted; ///< the coordinates of Order[i] at 3 i
};

/// One point per cube of side `size` anchored at the grid's origin (the
/// one with the lowest coordinates, whatever order the points came in): the
/// cloud the holes are looked for in. A dense cloud has thousands of points
/// within 2 l of each; one per l / 4 keeps the empty discs near l and wider
/// (no point lies farther than sqrt(3) l / 4 from the one kept in its cube).
std::vector<double> Thin(const Grid& grid, const std::vector<double>& rel, double size);

/// The holes found, each with the point that sees it, in ascending point order.
using Found = std::vector<std::pair<std::int64_t, Hole>>;

/// Looks at points [0, n) of rel (or only those marked in `look`) for holes
/// (HoleFinder::Examine); cells: rel's; all(): the cells of allRel (every
/// point), made only when a point needs them (a cloud without holes never
/// does). With `suspects`, first the cheap test of each point, whose outcome
/// it gets. False if the monitor stopped it.
bool FindHoles(const PointCells& cells, const std::vector<double>& rel, const std::function<const PointCells&()>& all,
  const std::vector<double>& allRel, double offset, double threshold, double limit, const std::vector<char>* look,
  std::vector<char>* suspects, Found& found, Monitor* monitor);
} // namespace holes
} // namespace nv

#endif
