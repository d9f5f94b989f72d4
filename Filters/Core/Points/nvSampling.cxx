// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvSampling.h"

#include "nvCommunicator.h"
#include "nvGrid.h"
#include "nvParallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <sstream>

namespace nv
{
namespace
{

/// A question about a point's nearest neighbour in another process's
/// slab, or its answer, as it travels between processes (6 doubles, in
/// Communicator::Exchange's arrays): the asked point or the nearest one
/// found, the distance (the asker's nearest so far, or the one found), and
/// the asking process and its point.
struct NearestRecord
{
  double Where[3];
  double Distance;
  std::int64_t Asker;
  std::int64_t Point;

  static constexpr std::size_t Size = 6;
  static std::int64_t Count(const std::vector<double>& values)
  {
    return static_cast<std::int64_t>(values.size() / Size);
  }
  static NearestRecord At(const std::vector<double>& values, std::int64_t i)
  {
    const double* v = &values[Size * static_cast<std::size_t>(i)];
    return { { v[0], v[1], v[2] }, v[3], static_cast<std::int64_t>(v[4]), static_cast<std::int64_t>(v[5]) };
  }
  void AppendTo(std::vector<double>& values) const
  {
    values.insert(values.end(), { this->Where[0], this->Where[1], this->Where[2], this->Distance,
                                  static_cast<double>(this->Asker), static_cast<double>(this->Point) });
  }
};
/// Whether point a comes before point b in lexicographic order (x, then y, then z).
bool Before(const double* a, const double* b)
{
  return std::lexicographical_compare(a, a + 3, b, b + 3);
}

/// Points sorted into cubic cells of a hashed grid, for nearest-neighbour queries.
class CellIndex
{
public:
  /// monitor (may be null): asked to stop during the sort; then Stopped().
  CellIndex(const std::vector<double>& xyz, double cellSize, Monitor* monitor = nullptr)
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
    if (!ParallelSort(keyed, monitor))
    {
      this->Incomplete = true;
      return;
    }
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

  /// Whether the monitor stopped the index before it was complete.
  bool Stopped() const { return this->Incomplete; }

  /// The nearest point to x at a distance > 0 (x may be one of the points,
  /// or another), and that distance; partner -1 when there is none within
  /// MaximumRing rings.
  std::pair<double, std::int64_t> Nearest(const double* x) const
  {
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
                // Ties go to the lowest coordinates: the same partner
                // whatever the points' order and whichever process looks.
                if (d2 < best || Before(y, &this->Xyz[3 * partner]))
                {
                  best = d2;
                  partner = this->Order[q];
                }
              }
            }
          }
      // (Strictly within: a point as near as the best may lie in the next ring.)
      if (partner >= 0 && std::sqrt(best) < static_cast<double>(r) * this->Size)
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
  bool Incomplete = false;
  double Low[3];
  std::vector<std::int64_t> Order; ///< the points in cell order
  std::vector<double> Sorted;      ///< their coordinates in that order (a cell's points side by side)
  std::vector<Slot> Slots;
};

/// The nearest point to x at a distance > 0, by looking at every point.
std::pair<double, std::int64_t> NearestByScan(const std::vector<double>& xyz, const double* x)
{
  double best = std::numeric_limits<double>::infinity();
  std::int64_t partner = -1;
  for (std::int64_t q = 0; q < static_cast<std::int64_t>(xyz.size() / 3); ++q)
  {
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      d2 += (x[a] - xyz[3 * q + a]) * (x[a] - xyz[3 * q + a]);
    }
    if (d2 > 0.0 && (d2 < best || (d2 == best && Before(&xyz[3 * q], &xyz[3 * partner]))))
    {
      best = d2;
      partner = q;
    }
  }
  return { std::sqrt(best), partner };
}

/// A cell size near the typical spacing: the cloud is taken as a surface,
/// whose area is estimated by the cells of a coarse grid that it occupies.
/// monitor (may be null): asked to stop during the sort; 0 if it did.
double CellSizeFor(const std::vector<double>& xyz, Monitor* monitor)
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
  if (!ParallelSort(keys, monitor))
  {
    return 0.0;
  }
  const double occupied = static_cast<double>(std::unique(keys.begin(), keys.end()) - keys.begin());
  // Area ~ occupied * coarse^2, spacing ~ sqrt(area / n); two spacings per
  // cell, so that most nearest neighbours are in the 27 cells around a point.
  return 2.0 * coarse * std::sqrt(occupied / static_cast<double>(n));
}

/**
 * For each query q of `pending` (a point at queries[3 q ...]), the nearest
 * point among `points` at a distance > 0: searched in cells near the typical
 * spacing, queries without a neighbour within a few cells again with cells
 * four times larger, and the last few against every point. nearest and
 * partner (an index into points) are indexed by query. The queries may be
 * the points themselves. The first pass, which answers almost every query,
 * reports its progress to the monitor (may be null) and stops when it asks:
 * then false, and the figures are incomplete.
 */
bool FindNearest(const std::vector<double>& points, const std::vector<double>& queries,
  std::vector<std::int64_t> pending, std::vector<double>& nearest, std::vector<std::int64_t>& partner,
  Monitor* monitor = nullptr)
{
  // Once a cell spans the box of the points and the queries together, a
  // query not answered within MaximumRing rings has no distinct neighbour
  // (the points themselves lie in their own box already).
  double bounds[6];
  PointBounds(points, bounds);
  if (&queries != &points)
  {
    double around[6];
    PointBounds(queries, around);
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], around[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], around[2 * a + 1]);
    }
  }
  const double side = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const bool selves = &points == &queries && pending.size() == points.size() / 3;
  // The first pass's index asks the monitor to stop while it sorts the
  // points (seconds for millions), as the pass itself does.
  const double first = CellSizeFor(points, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  for (double cell = first; pending.size() > 1000; cell *= 4.0)
  {
    const CellIndex index(points, cell, monitor);
    if (index.Stopped())
    {
      return false;
    }
    // The points themselves at first in cell order (neighbours one after the other).
    const std::vector<std::int64_t>& order = selves && pending.size() == points.size() / 3 ? index.CellOrder() : pending;
    const bool done =
      MonitoredFor(0, static_cast<std::int64_t>(order.size()), 1024, monitor, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t i = begin; i < end; ++i)
        {
          const std::int64_t q = order[i];
          const auto found = index.Nearest(&queries[3 * q]);
          nearest[q] = found.first;
          partner[q] = found.second;
        }
      });
    if (!done)
    {
      return false;
    }
    monitor = nullptr; // the passes after it answer few queries
    std::vector<std::int64_t> left;
    for (std::int64_t q : pending)
    {
      if (partner[q] < 0)
      {
        left.push_back(q);
      }
    }
    pending.swap(left);
    if (cell >= side)
    {
      pending.clear(); // one cell held every point: these have no distinct neighbour
    }
  }
  ParallelFor(0, static_cast<std::int64_t>(pending.size()), 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i)
    {
      const auto found = NearestByScan(points, &queries[3 * pending[i]]);
      nearest[pending[i]] = found.first;
      partner[pending[i]] = found.second;
    }
  });
  return true;
}

/// The k-th smallest (from 0) of all processes' values, all >= 0: found by
/// halving the range of their bit patterns (which order non-negative doubles
/// as the values do), one global count per halving. `values` is sorted.
double GlobalKth(const std::vector<double>& values, std::int64_t k, Communicator& communicator)
{
  auto bits = [](double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::uint64_t low = 0, high = bits(communicator.MaxAll(values.empty() ? 0.0 : values.back()));
  while (low < high)
  {
    const std::uint64_t middle = low + (high - low) / 2;
    double t;
    std::memcpy(&t, &middle, sizeof t);
    double count = static_cast<double>(std::upper_bound(values.begin(), values.end(), t) - values.begin());
    communicator.SumAll(&count, 1);
    if (count >= static_cast<double>(k + 1))
    {
      high = middle;
    }
    else
    {
      low = middle + 1;
    }
  }
  double value;
  std::memcpy(&value, &low, sizeof value);
  return value;
}

/// The index of quantile q among `count` sorted values.
std::int64_t QuantileIndex(double q, std::int64_t count)
{
  return std::min(count - 1, static_cast<std::int64_t>(q * static_cast<double>(count - 1) + 0.5));
}

} // namespace

//------------------------------------------------------------------------------
bool Sampling::Measure(const std::vector<double>& xyz, Communicator* communicator, Monitor* monitor)
{
  const auto start = std::chrono::steady_clock::now();
  const bool done = communicator && communicator->Size() > 1 ? this->MeasureDistributed(xyz, *communicator, monitor)
                                                             : this->MeasureHere(xyz, monitor);
  this->Time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return done;
}

bool Sampling::MeasureHere(const std::vector<double>& xyz, Monitor* monitor)
{
  // The caller's points are measured where they are: no copy of the cloud
  // is made, and only the figures are kept.
  this->Held = 0;
  const std::int64_t n = static_cast<std::int64_t>(xyz.size() / 3);
  std::vector<double> nearest(static_cast<std::size_t>(n), 0.0);
  std::vector<std::int64_t> partner(static_cast<std::size_t>(n), -1);
  this->Stats = SamplingStatistics{};
  this->Stats.Points = n;
  double bounds[6];
  if (n < 2 || PointBounds(xyz, bounds) >= 0) // non-finite: the run refuses the points
  {
    return true;
  }
  std::vector<std::int64_t> every(static_cast<std::size_t>(n));
  std::iota(every.begin(), every.end(), 0);
  if (!FindNearest(xyz, xyz, std::move(every), nearest, partner, monitor))
  {
    return false;
  }
  std::vector<std::int64_t>().swap(partner);
  // Quantiles of the finite distances (a point whose every neighbour
  // coincides with it has none).
  std::vector<double> sorted;
  sorted.reserve(nearest.size());
  for (double d : nearest)
  {
    if (std::isfinite(d))
    {
      sorted.push_back(d);
    }
  }
  if (!sorted.empty())
  {
    auto quantile = [&](double q) {
      const auto k = static_cast<std::ptrdiff_t>(QuantileIndex(q, static_cast<std::int64_t>(sorted.size())));
      std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
      return sorted[static_cast<std::size_t>(k)];
    };
    this->Stats.MedianSpacing = quantile(0.5);
    this->Stats.WideSpacing = quantile(0.999);
  }
  return true;
}

//------------------------------------------------------------------------------
bool Sampling::MeasureDistributed(const std::vector<double>& xyz, Communicator& communicator, Monitor* monitor)
{
  // Each process measures the points of one slab of z, which it receives
  // from all processes; a point whose nearest neighbour in the slab is
  // farther than a face of the slab is asked of the processes whose slabs
  // lie within that distance, which answer with their nearest point to it.
  // Every distance is then exact, and the figures are the serial run's,
  // while no process holds more than its slab (and the partners of its
  // points found elsewhere).
  const int size = communicator.Size(), rank = communicator.Rank();
  this->Stats = SamplingStatistics{};
  double bounds[6];
  const bool finite = PointBounds(xyz, bounds) < 0;
  double figures[3] = { finite ? 0.0 : 1.0, xyz.empty() ? -std::numeric_limits<double>::infinity() : -bounds[4],
    xyz.empty() ? -std::numeric_limits<double>::infinity() : bounds[5] };
  communicator.MaxAll(figures, 3);
  double total = static_cast<double>(xyz.size() / 3);
  communicator.SumAll(&total, 1);
  this->Stats.Points = static_cast<std::int64_t>(total);
  this->Held = 0;
  if (figures[0] > 0.0 || total < 2.0)
  {
    return true; // non-finite points (the run refuses them), or nothing to measure
  }

  // 1. Slabs of about equal counts, from a histogram of z.
  const double zLow = -figures[1], zHigh = figures[2];
  const int bins = 256 * size;
  std::vector<double> histogram(static_cast<std::size_t>(bins), 0.0);
  auto binOf = [&](double z) {
    const double f = zHigh > zLow ? (z - zLow) / (zHigh - zLow) : 0.0;
    return std::min(bins - 1, std::max(0, static_cast<int>(f * bins)));
  };
  for (std::size_t p = 0; p + 2 < xyz.size(); p += 3)
  {
    histogram[static_cast<std::size_t>(binOf(xyz[p + 2]))] += 1.0;
  }
  communicator.SumAll(histogram.data(), bins);
  std::vector<double> faces(static_cast<std::size_t>(size) + 1); // slab q: [faces[q], faces[q + 1])
  faces.front() = -std::numeric_limits<double>::infinity();
  faces.back() = std::numeric_limits<double>::infinity();
  double below = 0.0;
  int bin = 0;
  for (int q = 1; q < size; ++q)
  {
    while (bin < bins && below + histogram[static_cast<std::size_t>(bin)] <= total * q / size)
    {
      below += histogram[static_cast<std::size_t>(bin++)];
    }
    faces[static_cast<std::size_t>(q)] = zLow + (zHigh - zLow) * bin / bins;
  }
  auto owner = [&](double z) {
    return static_cast<int>(std::upper_bound(faces.begin() + 1, faces.end() - 1, z) - (faces.begin() + 1));
  };

  // 2. Each slab's points to its process.
  std::vector<std::vector<double>> slabPoints(static_cast<std::size_t>(size));
  for (std::size_t p = 0; p + 2 < xyz.size(); p += 3)
  {
    auto& to = slabPoints[static_cast<std::size_t>(owner(xyz[p + 2]))];
    to.insert(to.end(), &xyz[p], &xyz[p] + 3);
  }
  const std::vector<double> points = communicator.Exchange(slabPoints);
  std::vector<std::vector<double>>().swap(slabPoints);
  const std::int64_t owned = static_cast<std::int64_t>(points.size() / 3);
  this->Held = owned;
  std::vector<double> nearest(static_cast<std::size_t>(owned), std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> partner(static_cast<std::size_t>(owned), -1);
  std::vector<std::int64_t> every(static_cast<std::size_t>(owned));
  std::iota(every.begin(), every.end(), 0);
  const bool stopped = owned > 1 && !FindNearest(points, points, std::move(every), nearest, partner, monitor);
  if (communicator.MaxAll(stopped ? 1.0 : 0.0) > 0.0) // every process stops, or none
  {
    return false;
  }

  // 3. Points whose nearest neighbour may lie in another slab (a point as
  // near lies within the distance in z, possibly on the next slab's face)
  // are asked of the processes whose slabs lie that near; each answers with
  // its nearest point, and the nearest answer, ties to the lowest
  // coordinates, wins. Questions and answers travel as NearestRecords.
  std::vector<std::vector<double>> asks(static_cast<std::size_t>(size));
  for (std::int64_t p = 0; p < owned; ++p)
  {
    const double* x = &points[3 * p];
    const double d = nearest[p];
    for (int q = 0; q < size; ++q)
    {
      if (q != rank && faces[q] <= x[2] + d && x[2] - d < faces[q + 1])
      {
        NearestRecord{ { x[0], x[1], x[2] }, d, rank, p }.AppendTo(asks[q]);
      }
    }
  }
  const std::vector<double> questions = communicator.Exchange(asks);
  const std::int64_t asked = NearestRecord::Count(questions);
  std::vector<double> where(3 * static_cast<std::size_t>(asked));
  for (std::int64_t i = 0; i < asked; ++i)
  {
    const NearestRecord question = NearestRecord::At(questions, i);
    std::copy(question.Where, question.Where + 3, &where[3 * i]);
  }
  std::vector<double> found(static_cast<std::size_t>(asked), std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> foundPoint(static_cast<std::size_t>(asked), -1);
  if (owned > 0 && asked > 0)
  {
    std::vector<std::int64_t> all(static_cast<std::size_t>(asked));
    std::iota(all.begin(), all.end(), 0);
    FindNearest(points, where, std::move(all), found, foundPoint);
  }
  std::vector<std::vector<double>> answers(static_cast<std::size_t>(size));
  for (std::int64_t i = 0; i < asked; ++i)
  {
    const NearestRecord question = NearestRecord::At(questions, i);
    if (foundPoint[i] >= 0 && found[i] <= question.Distance)
    {
      const double* y = &points[3 * foundPoint[i]];
      NearestRecord{ { y[0], y[1], y[2] }, found[i], question.Asker, question.Point }.AppendTo(
        answers[static_cast<std::size_t>(question.Asker)]);
    }
  }
  const std::vector<double> replies = communicator.Exchange(answers);
  for (std::int64_t i = 0; i < NearestRecord::Count(replies); ++i)
  {
    const NearestRecord reply = NearestRecord::At(replies, i);
    nearest[reply.Point] = std::min(nearest[reply.Point], reply.Distance);
  }

  // 4. The quantiles of all processes' finite distances.
  std::vector<double> sorted;
  for (double d : nearest)
  {
    if (std::isfinite(d))
    {
      sorted.push_back(d);
    }
  }
  ParallelSort(sorted);
  double count = static_cast<double>(sorted.size());
  communicator.SumAll(&count, 1);
  if (count > 0.0)
  {
    const std::int64_t finiteCount = static_cast<std::int64_t>(count);
    this->Stats.MedianSpacing = GlobalKth(sorted, QuantileIndex(0.5, finiteCount), communicator);
    this->Stats.WideSpacing = GlobalKth(sorted, QuantileIndex(0.999, finiteCount), communicator);
  }
  return true;
}

std::int64_t PointBounds(const std::vector<double>& xyz, double bounds[6])
{
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = std::numeric_limits<double>::max();
    bounds[2 * a + 1] = -std::numeric_limits<double>::max();
  }
  for (std::size_t p = 0; p + 2 < xyz.size(); p += 3)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double x = xyz[p + a];
      if (!std::isfinite(x))
      {
        return static_cast<std::int64_t>(p / 3);
      }
      bounds[2 * a] = std::min(bounds[2 * a], x);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], x);
    }
  }
  return -1;
}

void GlobalBounds(Communicator& communicator, double bounds[6])
{
  // Maxima of (-xmin, xmax, -ymin, ...).
  double box[6];
  for (int a = 0; a < 6; ++a)
  {
    box[a] = a % 2 ? bounds[a] : -bounds[a];
  }
  communicator.MaxAll(box, 6);
  for (int a = 0; a < 6; ++a)
  {
    bounds[a] = a % 2 ? box[a] : -box[a];
  }
}

} // namespace nv
