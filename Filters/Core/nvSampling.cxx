// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvSampling.h"

#include "nvCommunicator.h"
#include "nvGrid.h"
#include "nvParallel.h"
#include "nvReconstruction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace nv
{
namespace
{
/// Sorts v: fixed chunks sorted in parallel, then merged pairwise (the
/// result is the sorted sequence, whatever the threads).
template <typename T>
void ParallelSort(std::vector<T>& v)
{
  constexpr std::int64_t Chunks = 8;
  const std::int64_t n = static_cast<std::int64_t>(v.size());
  auto bound = [&](std::int64_t c) { return v.begin() + static_cast<std::ptrdiff_t>(n * c / Chunks); };
  ParallelFor(0, Chunks, 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t c = begin; c < end; ++c)
    {
      std::sort(bound(c), bound(c + 1));
    }
  });
  for (std::int64_t width = 1; width < Chunks; width *= 2)
  {
    ParallelFor(0, Chunks / (2 * width), 1, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t m = begin; m < end; ++m)
      {
        const std::int64_t first = 2 * width * m;
        std::inplace_merge(bound(first), bound(first + width), bound(first + 2 * width));
      }
    });
  }
}

/// Points sorted into cubic cells of a hashed grid, for nearest-neighbour queries.
class CellIndex
{
public:
  CellIndex(const std::vector<double>& xyz, double cellSize)
    : Xyz(xyz)
    , Size(cellSize)
  {
    const std::int64_t n = static_cast<std::int64_t>(xyz.size() / 3);
    for (int a = 0; a < 3; ++a)
    {
      this->Low[a] = std::numeric_limits<double>::max();
      for (std::int64_t p = 0; p < n; ++p)
      {
        this->Low[a] = std::min(this->Low[a], xyz[3 * p + a]);
      }
    }
    // Points in cell order; each occupied cell's range in an open-addressing table.
    std::vector<std::pair<std::uint64_t, std::int64_t>> keyed(static_cast<std::size_t>(n));
    ParallelFor(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t p = begin; p < end; ++p)
      {
        std::int64_t c[3];
        this->CellOf(&xyz[3 * p], c);
        keyed[p] = { Key(c), p };
      }
    });
    ParallelSort(keyed);
    this->Order.resize(keyed.size());
    this->Sorted.resize(xyz.size());
    ParallelFor(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t q = begin; q < end; ++q)
      {
        this->Order[q] = keyed[q].second;
        std::copy(&xyz[3 * keyed[q].second], &xyz[3 * keyed[q].second] + 3, &this->Sorted[3 * q]);
      }
    });
    std::size_t cells = 0;
    for (std::size_t q = 0; q < keyed.size(); ++q)
    {
      cells += (q == 0 || keyed[q].first != keyed[q - 1].first) ? 1 : 0;
    }
    std::size_t slots = 16;
    while (slots < 2 * cells)
    {
      slots *= 2;
    }
    this->Slots.assign(slots, Slot{});
    for (std::size_t q = 0; q < keyed.size();)
    {
      std::size_t end = q;
      while (end < keyed.size() && keyed[end].first == keyed[q].first)
      {
        ++end;
      }
      std::size_t s = Hash(keyed[q].first) & (slots - 1);
      while (this->Slots[s].Count)
      {
        s = (s + 1) & (slots - 1);
      }
      this->Slots[s] = { keyed[q].first, static_cast<std::int64_t>(q), static_cast<std::int64_t>(end - q) };
      q = end;
    }
  }

  /// The nearest point to point p at a distance > 0, and that distance
  /// (infinite when every point coincides with p).
  std::pair<double, std::int64_t> Nearest(std::int64_t p) const
  {
    const double* x = &this->Xyz[3 * p];
    std::int64_t c[3];
    this->CellOf(x, c);
    double best = std::numeric_limits<double>::infinity();
    std::int64_t partner = -1;
    // How far p lies inside its cell from each face, less a margin for the
    // rounding of the cell's bounds (a cell is skipped only when every point
    // in it is surely farther than the best so far).
    const double margin = 1e-9 * this->Size;
    double below[3], above[3];
    for (int a = 0; a < 3; ++a)
    {
      const double low = this->Low[a] + static_cast<double>(c[a]) * this->Size;
      below[a] = x[a] - low - margin;
      above[a] = low + this->Size - x[a] - margin;
    }
    // The gap along one axis between p and the cell `step` cells away.
    auto gap = [&](int a, std::int64_t step) {
      const double g = step < 0 ? below[a] + static_cast<double>(-step - 1) * this->Size
                                : (step > 0 ? above[a] + static_cast<double>(step - 1) * this->Size : 0.0);
      return g > 0.0 ? g * g : 0.0;
    };
    // Rings of cells around p's cell: ring r holds every point closer than
    // r cells, so the search ends once the best distance is within that.
    for (std::int64_t r = 0; r <= MaximumRing; ++r)
    {
      for (std::int64_t dk = -r; dk <= r; ++dk)
        for (std::int64_t dj = -r; dj <= r; ++dj)
          for (std::int64_t di = -r; di <= r; ++di)
          {
            if (std::max({ std::abs(di), std::abs(dj), std::abs(dk) }) != r)
            {
              continue; // inner rings were searched already
            }
            if (gap(0, di) + gap(1, dj) + gap(2, dk) > best)
            {
              continue; // every point of that cell is farther than the best (ties are kept)
            }
            const std::int64_t cell[3] = { c[0] + di, c[1] + dj, c[2] + dk };
            const Slot* slot = this->Find(Key(cell));
            for (std::int64_t q = slot ? slot->First : 0; slot && q < slot->First + slot->Count; ++q)
            {
              const double* y = &this->Sorted[3 * q];
              const double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]);
              if (d2 > 0.0 && d2 <= best)
              {
                const std::int64_t other = this->Order[q];
                if (d2 < best || other < partner)
                {
                  best = d2;
                  partner = other;
                }
              }
            }
          }
      if (partner >= 0 && std::sqrt(best) <= static_cast<double>(r) * this->Size)
      {
        return { std::sqrt(best), partner };
      }
    }
    return { std::numeric_limits<double>::infinity(), -1 };
  }

  /// The points in cell order: queries in this order find their cells' points in the cache.
  const std::vector<std::int64_t>& CellOrder() const { return this->Order; }

  /// Rings searched before giving up (partner -1): the caller searches such
  /// points again with larger cells.
  static constexpr std::int64_t MaximumRing = 4;

private:
  struct Slot
  {
    std::uint64_t Key = 0;
    std::int64_t First = 0;
    std::int64_t Count = 0;
  };
  void CellOf(const double* x, std::int64_t c[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      c[a] = static_cast<std::int64_t>(std::floor((x[a] - this->Low[a]) / this->Size));
    }
  }
  static std::uint64_t Key(const std::int64_t c[3])
  {
    // 21 bits per axis (cells are offset by one so that ring neighbours at -1 fit).
    const std::uint64_t mask = (1u << 21) - 1;
    return (static_cast<std::uint64_t>(c[0] + 1) & mask) | ((static_cast<std::uint64_t>(c[1] + 1) & mask) << 21) |
      ((static_cast<std::uint64_t>(c[2] + 1) & mask) << 42);
  }
  static std::size_t Hash(std::uint64_t key)
  {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return static_cast<std::size_t>(key);
  }
  const Slot* Find(std::uint64_t key) const
  {
    const std::size_t mask = this->Slots.size() - 1;
    for (std::size_t s = Hash(key) & mask; this->Slots[s].Count; s = (s + 1) & mask)
    {
      if (this->Slots[s].Key == key)
      {
        return &this->Slots[s];
      }
    }
    return nullptr;
  }

  const std::vector<double>& Xyz;
  double Size;
  double Low[3];
  std::vector<std::int64_t> Order; ///< the points in cell order
  std::vector<double> Sorted;      ///< their coordinates in that order (a cell's points side by side)
  std::vector<Slot> Slots;
};

/// The nearest point to point p at a distance > 0, by looking at every point.
std::pair<double, std::int64_t> NearestByScan(const std::vector<double>& xyz, std::int64_t p)
{
  double best = std::numeric_limits<double>::infinity();
  std::int64_t partner = -1;
  for (std::int64_t q = 0; q < static_cast<std::int64_t>(xyz.size() / 3); ++q)
  {
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      d2 += (xyz[3 * p + a] - xyz[3 * q + a]) * (xyz[3 * p + a] - xyz[3 * q + a]);
    }
    if (d2 > 0.0 && d2 < best)
    {
      best = d2;
      partner = q;
    }
  }
  return { std::sqrt(best), partner };
}

/// A cell size near the typical spacing: the cloud is taken as a surface,
/// whose area is estimated by the cells of a coarse grid that it occupies.
double CellSizeFor(const std::vector<double>& xyz)
{
  const std::int64_t n = static_cast<std::int64_t>(xyz.size() / 3);
  double bounds[6];
  PointBounds(xyz, bounds);
  const double side = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  // About n^(1/2) / 4 cells along the longest side (capped by the key's 21
  // bits): coarse enough that a surface's points fill its cells many times over.
  const double coarse = side / std::min(1.0e6, std::max(1.0, 0.25 * std::sqrt(static_cast<double>(n))));
  if (!(coarse > 0.0))
  {
    return 1.0;
  }
  std::vector<std::uint64_t> keys(static_cast<std::size_t>(n));
  ParallelFor(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      std::uint64_t key = 0;
      for (int a = 0; a < 3; ++a)
      {
        key = (key << 21) | static_cast<std::uint64_t>((xyz[3 * p + a] - bounds[2 * a]) / coarse);
      }
      keys[p] = key;
    }
  });
  ParallelSort(keys);
  const double occupied = static_cast<double>(std::unique(keys.begin(), keys.end()) - keys.begin());
  // Area ~ occupied * coarse^2, spacing ~ sqrt(area / n); two spacings per
  // cell, so that most nearest neighbours are in the 27 cells around a point.
  return 2.0 * coarse * std::sqrt(occupied / static_cast<double>(n));
}
} // namespace

//------------------------------------------------------------------------------
void Sampling::Measure(const std::vector<double>& xyz, Communicator* communicator)
{
  this->Points = communicator && communicator->Size() > 1 ? communicator->Gather(xyz, 0) : xyz;
  this->Nearest.clear();
  this->Partner.clear();
  double figures[3] = { 0.0, 0.0, 0.0 }; // points, median, 99.9th percentile
  if (!communicator || communicator->Rank() == 0)
  {
    const std::int64_t n = static_cast<std::int64_t>(this->Points.size() / 3);
    this->Nearest.assign(static_cast<std::size_t>(n), 0.0);
    this->Partner.assign(static_cast<std::size_t>(n), -1);
    double bounds[6];
    const bool finite = PointBounds(this->Points, bounds) < 0; // else the run refuses the points
    if (n > 1 && finite)
    {
      // Points without a neighbour within a few cells are searched again
      // with cells four times larger, and the last few of them one by one.
      std::vector<std::int64_t> pending(static_cast<std::size_t>(n));
      std::iota(pending.begin(), pending.end(), 0);
      const double side = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
      for (double cell = CellSizeFor(this->Points); pending.size() > 1000; cell *= 4.0)
      {
        const CellIndex index(this->Points, cell);
        // All the points at first, in cell order (neighbours one after the other).
        const std::vector<std::int64_t>& queries =
          pending.size() == static_cast<std::size_t>(n) ? index.CellOrder() : pending;
        ParallelFor(0, static_cast<std::int64_t>(queries.size()), 1024, [&](std::int64_t begin, std::int64_t end) {
          for (std::int64_t q = begin; q < end; ++q)
          {
            const auto nearest = index.Nearest(queries[q]);
            this->Nearest[queries[q]] = nearest.first;
            this->Partner[queries[q]] = nearest.second;
          }
        });
        std::vector<std::int64_t> left;
        for (std::int64_t p : pending)
        {
          if (this->Partner[p] < 0)
          {
            left.push_back(p);
          }
        }
        pending.swap(left);
        if (cell >= side)
        {
          pending.clear(); // one cell held every point: these have no distinct neighbour
        }
      }
      ParallelFor(0, static_cast<std::int64_t>(pending.size()), 1, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t q = begin; q < end; ++q)
        {
          const auto nearest = NearestByScan(this->Points, pending[q]);
          this->Nearest[pending[q]] = nearest.first;
          this->Partner[pending[q]] = nearest.second;
        }
      });
      // Quantiles of the finite distances (a point whose every neighbour
      // coincides with it has none).
      std::vector<double> sorted;
      sorted.reserve(this->Nearest.size());
      for (double d : this->Nearest)
      {
        if (std::isfinite(d))
        {
          sorted.push_back(d);
        }
      }
      if (!sorted.empty())
      {
        auto quantile = [&](double q) {
          const std::size_t k = std::min(sorted.size() - 1, static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) + 0.5));
          std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
          return sorted[k];
        };
        figures[1] = quantile(0.5);
        figures[2] = quantile(0.999);
      }
    }
    figures[0] = static_cast<double>(n);
  }
  if (communicator && communicator->Size() > 1)
  {
    communicator->SumAll(figures, 3); // only process 0 holds non-zero figures
  }
  this->Stats.Points = static_cast<std::int64_t>(figures[0]);
  this->Stats.MedianSpacing = figures[1];
  this->Stats.WideSpacing = figures[2];
}

//------------------------------------------------------------------------------
GapReport Sampling::Gaps(double offset, Communicator* communicator) const
{
  // figures: gaps, gap points, largest, its centre (x, y, z)
  double figures[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  if (!communicator || communicator->Rank() == 0)
  {
    std::vector<std::int64_t> gapPoints;
    std::int64_t widest = -1;
    for (std::size_t p = 0; p < this->Nearest.size(); ++p)
    {
      if (this->Nearest[p] > offset)
      {
        gapPoints.push_back(static_cast<std::int64_t>(p));
        // The widest gap; ties go to the lowest coordinates (independent of the points' order).
        if (widest < 0 || this->Nearest[p] > this->Nearest[widest] ||
          (this->Nearest[p] == this->Nearest[widest] &&
            std::lexicographical_compare(&this->Points[3 * p], &this->Points[3 * p + 3], &this->Points[3 * widest],
              &this->Points[3 * widest + 3])))
        {
          widest = static_cast<std::int64_t>(p);
        }
      }
    }
    // Groups: gap points closer than 2 l to each other (union-find over a
    // grid of cells 2 l wide; there are few gap points).
    std::vector<std::int64_t> parent(gapPoints.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](std::int64_t a) {
      while (parent[a] != a)
      {
        a = parent[a] = parent[parent[a]];
      }
      return a;
    };
    std::vector<double> gapXyz;
    for (std::int64_t p : gapPoints)
    {
      gapXyz.insert(gapXyz.end(), &this->Points[3 * p], &this->Points[3 * p + 3]);
    }
    const double reach = 2.0 * offset;
    for (std::size_t a = 0; a < gapPoints.size(); ++a)
    {
      for (std::size_t b = a + 1; b < gapPoints.size() && gapPoints.size() < 20000; ++b)
      {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          d2 += (gapXyz[3 * a + c] - gapXyz[3 * b + c]) * (gapXyz[3 * a + c] - gapXyz[3 * b + c]);
        }
        if (d2 < reach * reach)
        {
          parent[root(static_cast<std::int64_t>(a))] = root(static_cast<std::int64_t>(b));
        }
      }
    }
    std::int64_t groups = 0;
    for (std::size_t a = 0; a < parent.size(); ++a)
    {
      groups += root(static_cast<std::int64_t>(a)) == static_cast<std::int64_t>(a) ? 1 : 0;
    }
    figures[0] = static_cast<double>(groups);
    figures[1] = static_cast<double>(gapPoints.size());
    if (widest >= 0)
    {
      figures[2] = this->Nearest[widest];
      const std::int64_t other = this->Partner[widest];
      for (int c = 0; c < 3; ++c)
      {
        figures[3 + c] = other >= 0 ? 0.5 * (this->Points[3 * widest + c] + this->Points[3 * other + c])
                                    : this->Points[3 * widest + c];
      }
    }
  }
  if (communicator && communicator->Size() > 1)
  {
    communicator->SumAll(figures, 6);
  }
  GapReport report;
  report.Gaps = static_cast<std::int64_t>(figures[0]);
  report.GapPoints = static_cast<std::int64_t>(figures[1]);
  report.LargestGap = figures[2];
  report.LargestGapCenter = { { figures[3], figures[4], figures[5] } };
  return report;
}

} // namespace nv
