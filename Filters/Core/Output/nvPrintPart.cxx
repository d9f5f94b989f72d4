// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPrintPart.h"

#include "nvNearestPoints.h"
#include "nvParallel.h"
#include "nvPieces.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

namespace nv
{
namespace
{
/// The share of the largest cavity below which a cavity is merged into the
/// wall when MinimumCavityVolume is 0.
constexpr double AutomaticCavityShare = 0.01;
/// The bound of the scan's check, in cells (PrintReport::LostDistance): the
/// part's vertices lie within a cell of one another, and its outer surface
/// within about half a cell of the closing; twice a cell covers both.
constexpr double LostDistanceCells = 2.0;
/// The radius of the material put back around a lost point and the rods
/// that join it to its neighbours (Restoration), in cells: a limb two cells
/// thick at least, which the grid holds.
constexpr double LostRadiusCells = 2.0;
/// Lost points nearer than this many cells are one region (LostRegions).
constexpr double LostRegionReach = 4.0;

/// A node's distance and nearest vertex as one number: the distance's bits
/// (a float >= 0, whose bits order as its values do) above the vertex's
/// index. The least key is the nearest vertex, the lower index on a tie.
using NearestKey = std::uint64_t;
constexpr NearestKey NoKey = ~NearestKey(0);

NearestKey MakeKey(float distance, std::int64_t vertex)
{
  std::uint32_t bits;
  std::memcpy(&bits, &distance, sizeof bits);
  return (NearestKey(bits) << 32) | NearestKey(static_cast<std::uint32_t>(vertex));
}

float KeyDistance(NearestKey key)
{
  const std::uint32_t bits = static_cast<std::uint32_t>(key >> 32);
  float distance;
  std::memcpy(&distance, &bits, sizeof distance);
  return distance;
}

std::int64_t KeyVertex(NearestKey key)
{
  return static_cast<std::int64_t>(key & 0xffffffffu);
}

/// Lowers a node's key to `key` if that is less; whether it did.
bool Lower(std::atomic<NearestKey>& node, NearestKey key)
{
  NearestKey now = node.load(std::memory_order_relaxed);
  while (key < now)
  {
    if (node.compare_exchange_weak(now, key, std::memory_order_relaxed))
    {
      return true;
    }
  }
  return false;
}

/// D on the nodes inside S (the outer phi > 0) up to `cap`, and outside S
/// near the sheet; `cap` elsewhere. Each vertex of the sheet gives the nodes
/// within two cells of it their distance to it; from those, the nearest
/// vertex moves inward node by node, to the 26 neighbours, nearest first (a
/// closest-point propagation: a node's nearest vertex is, but for rare
/// ties, one of its neighbours'). "Nearest first" by buckets h / 8 wide
/// (Dial's queue). The nodes of a bucket are swept in parallel, in rounds:
/// a round sweeps the nodes whose key is still the one they were queued
/// with when it begins, and lowers their neighbours' keys (an atomic least,
/// whose outcome no order changes); the nodes it lowered are the next
/// round's, in this bucket or a later one. So the result is the same on
/// every run and for any number of threads. Empty if the monitor (may be
/// null) asked to stop between rounds.
std::vector<float> SheetDistance(
  const Grid& grid, const float* outer, const std::vector<double>& sheet, double cap, Monitor* monitor)
{
  const std::int64_t nodes = grid.NumberOfNodes();
  const double h = grid.Spacing;
  const float far = static_cast<float>(cap);
  std::vector<std::atomic<NearestKey>> keys(static_cast<std::size_t>(nodes));
  ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t n = begin; n < end; ++n)
    {
      keys[n].store(NoKey, std::memory_order_relaxed);
    }
  });
  // The squared distance from a node to a vertex.
  auto squared = [&](const std::int64_t ijk[3], std::int64_t v) {
    const double* y = &sheet[3 * static_cast<std::size_t>(v)];
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double d = grid.Origin[a] + static_cast<double>(ijk[a]) * h - y[a];
      d2 += d * d;
    }
    return d2;
  };
  auto keyOf = [&](double d2, std::int64_t v) { return MakeKey(static_cast<float>(std::sqrt(d2)), v); };
  // The seeds: every node within two cells of a vertex.
  const std::int64_t vertices = static_cast<std::int64_t>(sheet.size() / 3);
  StoppableFor(0, vertices, 256, monitor, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      std::int64_t low[3], high[3], ijk[3];
      for (int a = 0; a < 3; ++a)
      {
        const std::int64_t c = static_cast<std::int64_t>(std::floor((sheet[3 * v + a] - grid.Origin[a]) / h));
        low[a] = std::max<std::int64_t>(0, c - 1);
        high[a] = std::min(grid.Dims[a] - 1, c + 2);
      }
      for (ijk[2] = low[2]; ijk[2] <= high[2]; ++ijk[2])
      {
        for (ijk[1] = low[1]; ijk[1] <= high[1]; ++ijk[1])
        {
          for (ijk[0] = low[0]; ijk[0] <= high[0]; ++ijk[0])
          {
            const NearestKey key = keyOf(squared(ijk, v), v);
            if (KeyDistance(key) < far)
            {
              Lower(keys[grid.Index(ijk[0], ijk[1], ijk[2])], key);
            }
          }
        }
      }
    }
  });
  // The queue: a node and its key when queued, in buckets h / 8 wide.
  struct Entry
  {
    std::int64_t Node;
    NearestKey Key;
  };
  const double width = h / 8.0;
  const std::size_t buckets = static_cast<std::size_t>(cap / width) + 2;
  auto bucket = [&](NearestKey key) {
    return std::min(buckets - 1, static_cast<std::size_t>(KeyDistance(key) / width));
  };
  std::vector<std::vector<Entry>> queue(buckets);
  for (std::int64_t n = 0; n < nodes; ++n)
  {
    const NearestKey key = keys[n].load(std::memory_order_relaxed);
    if (key != NoKey && outer[n] > 0.0f)
    {
      queue[bucket(key)].push_back({ n, key });
    }
  }
  constexpr std::int64_t Chunk = 512; // entries a task sweeps
  std::vector<char> current;
  std::vector<std::vector<Entry>> lowered;
  for (std::size_t b = 0; b < buckets; ++b)
  {
    while (!queue[b].empty())
    {
      if (StopAsked(monitor))
      {
        return {};
      }
      std::vector<Entry> round;
      round.swap(queue[b]);
      const std::int64_t count = static_cast<std::int64_t>(round.size());
      // Whether each entry is still its node's key (read before the round writes).
      current.assign(round.size(), 0);
      ParallelFor(0, count, Chunk, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t e = begin; e < end; ++e)
        {
          current[e] = keys[round[e].Node].load(std::memory_order_relaxed) == round[e].Key;
        }
      });
      const std::int64_t chunks = (count + Chunk - 1) / Chunk;
      lowered.assign(static_cast<std::size_t>(chunks), {});
      ParallelFor(0, chunks, 1, [&](std::int64_t first, std::int64_t last) {
        for (std::int64_t c = first; c < last; ++c)
        {
          for (std::int64_t e = c * Chunk; e < std::min(count, (c + 1) * Chunk); ++e)
          {
            if (!current[e])
            {
              continue; // lowered since it was queued: its newer entry carries it
            }
            const std::int64_t v = KeyVertex(round[e].Key);
            std::int64_t ijk[3], around[3];
            grid.Ijk(round[e].Node, ijk);
            for (around[2] = std::max<std::int64_t>(0, ijk[2] - 1);
                 around[2] <= std::min(grid.Dims[2] - 1, ijk[2] + 1); ++around[2])
            {
              for (around[1] = std::max<std::int64_t>(0, ijk[1] - 1);
                   around[1] <= std::min(grid.Dims[1] - 1, ijk[1] + 1); ++around[1])
              {
                for (around[0] = std::max<std::int64_t>(0, ijk[0] - 1);
                     around[0] <= std::min(grid.Dims[0] - 1, ijk[0] + 1); ++around[0])
                {
                  const std::int64_t m = grid.Index(around[0], around[1], around[2]);
                  const NearestKey now = keys[m].load(std::memory_order_relaxed);
                  if (!(outer[m] > 0.0f) || KeyVertex(now) == v)
                  {
                    continue;
                  }
                  // Clearly farther than the node's vertex now: cannot win
                  // (keys only fall), whatever the other threads do.
                  const double d2 = squared(around, v), nd = KeyDistance(now);
                  if (now != NoKey && d2 > nd * nd * (1.0 + 1e-6))
                  {
                    continue;
                  }
                  const NearestKey key = keyOf(d2, v);
                  if (KeyDistance(key) < far && Lower(keys[m], key))
                  {
                    lowered[c].push_back({ m, key });
                  }
                }
              }
            }
          }
        }
      });
      for (const std::vector<Entry>& entries : lowered)
      {
        for (const Entry& entry : entries)
        {
          queue[std::max(b, bucket(entry.Key))].push_back(entry);
        }
      }
    }
    std::vector<Entry>().swap(queue[b]);
  }
  std::vector<float> distance(static_cast<std::size_t>(nodes));
  ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t n = begin; n < end; ++n)
    {
      const NearestKey key = keys[n].load(std::memory_order_relaxed);
      distance[n] = key == NoKey ? far : KeyDistance(key);
    }
  });
  return distance;
}

/// A drain hole: the nodes within Radius of the segment from A (inside a
/// cavity) to B (outside the part) are no material.
struct Drill
{
  double A[3], B[3];
  double Radius;

  /// The distance from x to the hole's surface, negative inside the hole.
  double Signed(const double x[3]) const
  {
    double ab[3], ax[3], along = 0.0, length = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      ab[a] = this->B[a] - this->A[a];
      ax[a] = x[a] - this->A[a];
      along += ab[a] * ax[a];
      length += ab[a] * ab[a];
    }
    const double t = length > 0.0 ? std::min(1.0, std::max(0.0, along / length)) : 0.0;
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double r = ax[a] - t * ab[a];
      d2 += r * r;
    }
    return std::sqrt(d2) - this->Radius;
  }
};

/// Material put back around the scan points the part lost: a rod of
/// `radius` along the segment from each scan point within `reach` of a lost
/// one (itself included) to each of its nearest scan points within `reach`:
/// the rods join a lost limb's points to one another, and its ends to the
/// part. As a drain hole is a rod of no material. The rods are listed by the bricks they reach.
class Restoration
{
public:
  Restoration(const Grid& grid, const double* scan, std::int64_t scanPoints, const std::vector<std::int64_t>& lost,
    double radius, double reach)
    : Radius(radius)
    , BrickDims(BrickDimensions(grid))
  {
    // The points to join: the lost ones, and the held ones within reach of
    // one (a lost limb's ends, where the part's pieces may stop short of
    // one another although each holds the points near it).
    const NearestPoints all(scan, scanPoints);
    std::vector<double> lostXyz;
    for (std::int64_t p : lost)
    {
      lostXyz.insert(lostXyz.end(), scan + 3 * p, scan + 3 * p + 3);
    }
    this->LostPoints.reset(new NearestPoints(lostXyz.data(), static_cast<std::int64_t>(lost.size())));
    const NearestPoints& lostPoints = *this->LostPoints;
    std::vector<char> joined(static_cast<std::size_t>(scanPoints), 0);
    ParallelFor(0, scanPoints, 1024, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t p = begin; p < end; ++p)
      {
        joined[p] = lostPoints.Distance(scan + 3 * p, reach) < reach;
      }
    });
    std::vector<std::array<double, 3>> near;
    const double side = BrickSize * grid.Spacing, margin = radius + 3.0 * grid.Spacing;
    for (std::int64_t p = 0; p < scanPoints; ++p)
    {
      if (!joined[p])
      {
        continue;
      }
      const double* x = scan + 3 * p;
      all.Nearest(x, NeighboursJoined, reach, near);
      for (const std::array<double, 3>& y : near)
      {
        Drill rod;
        std::copy(x, x + 3, rod.A);
        std::copy(y.begin(), y.end(), rod.B);
        rod.Radius = radius;
        const std::int32_t index = static_cast<std::int32_t>(this->Rods.size());
        this->Rods.push_back(rod);
        std::int64_t low[3], high[3];
        for (int a = 0; a < 3; ++a)
        {
          const double lo = std::min(rod.A[a], rod.B[a]) - margin, hi = std::max(rod.A[a], rod.B[a]) + margin;
          low[a] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((lo - grid.Origin[a]) / side)));
          high[a] = std::min(this->BrickDims[a] - 1,
            static_cast<std::int64_t>(std::floor((hi - grid.Origin[a]) / side)));
        }
        for (std::int64_t k = low[2]; k <= high[2]; ++k)
        {
          for (std::int64_t j = low[1]; j <= high[1]; ++j)
          {
            for (std::int64_t i = low[0]; i <= high[0]; ++i)
            {
              this->ByBrick.emplace_back(i + this->BrickDims[0] * (j + this->BrickDims[1] * k), index);
            }
          }
        }
      }
    }
    std::sort(this->ByBrick.begin(), this->ByBrick.end());
    this->ByBrick.erase(std::unique(this->ByBrick.begin(), this->ByBrick.end()), this->ByBrick.end());
  }

  /// Whether a rod reaches brick b.
  bool Reaches(std::int64_t b) const
  {
    const auto found = std::lower_bound(this->ByBrick.begin(), this->ByBrick.end(), std::make_pair(b, std::int32_t(0)));
    return found != this->ByBrick.end() && found->first == b;
  }

  /// The material's f at x in brick b: the radius less the distance to the
  /// nearest rod (> 0 inside one).
  double Value(std::int64_t b, const double x[3]) const
  {
    double value = -std::numeric_limits<double>::infinity();
    for (auto r = std::lower_bound(this->ByBrick.begin(), this->ByBrick.end(), std::make_pair(b, std::int32_t(0)));
         r != this->ByBrick.end() && r->first == b; ++r)
    {
      value = std::max(value, -this->Rods[r->second].Signed(x));
    }
    return value;
  }

  /// Whether x lies within `reach` of a lost point.
  bool NearLost(const double* x, double reach) const { return this->LostPoints->Distance(x, reach) < reach; }

  double Radius;

private:
  std::unique_ptr<NearestPoints> LostPoints; ///< the lost points
  /// The nearest scan points a lost point is joined to (itself among them).
  static constexpr int NeighboursJoined = 16;
  std::array<std::int64_t, 3> BrickDims;
  std::vector<Drill> Rods;
  std::vector<std::pair<std::int64_t, std::int32_t>> ByBrick; ///< (brick, rod), ascending
};

/// A value at a place, trilinear between the nodes of its cell (the nearest
/// cell for a place beyond the grid), whose values node(i, j, k) gives.
template <class NodeValue>
double Trilinear(const Grid& grid, const double x[3], const NodeValue& node)
{
  std::int64_t c[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double u = (x[a] - grid.Origin[a]) / grid.Spacing;
    c[a] = std::min(grid.Dims[a] - 2, std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(u))));
    t[a] = std::min(1.0, std::max(0.0, u - static_cast<double>(c[a])));
  }
  double value = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = corner >> 2;
    const double weight = (di ? t[0] : 1.0 - t[0]) * (dj ? t[1] : 1.0 - t[1]) * (dk ? t[2] : 1.0 - t[2]);
    value += weight * node(c[0] + di, c[1] + dj, c[2] + dk);
  }
  return value;
}

/// The inner surface's field at a node inside S, positive in the wall:
/// l + w - D; or, with a closing distance c, the distance beyond c from the
/// cavity eroded by c (E: D > l + w + c), so that the cavity is E grown back
/// by c (an opening: its creases rounded with radius c, and the parts of it
/// narrower than 2 c gone). G: each node's distance to E's surface.
struct InnerField
{
  const std::vector<float>& D;
  const std::vector<float>* G; ///< null without a closing distance
  double Deep;                 ///< l + w
  double Closing;              ///< c

  double operator()(std::int64_t n) const
  {
    if (!this->G)
    {
      return this->Deep - this->D[n];
    }
    const double g = (*this->G)[n];
    return this->D[n] > this->Deep + this->Closing ? -(this->Closing + g) : g - this->Closing;
  }
};

/// A node array as a brick field, for contouring (every brick varies;
/// beyond the grid, `outside`).
class NodeField : public BrickField
{
public:
  NodeField(const Grid& grid, const std::vector<float>& values, float outside)
    : TheGrid(grid)
    , Nodes(values)
    , Outside(outside)
    , BrickDims(BrickDimensions(grid))
  {
  }

  void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const override
  {
    const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
    uniform.assign(static_cast<std::size_t>(perLayer), this->Outside);
    varying.resize(static_cast<std::size_t>(perLayer));
    for (std::int64_t b = 0; b < perLayer; ++b)
    {
      varying[b] = layer * perLayer + b;
    }
  }

  void Values(std::int64_t brick, float values[BrickNodes]) const override
  {
    const Grid& grid = this->TheGrid;
    const std::int64_t first[3] = { (brick % this->BrickDims[0]) * BrickSize,
      ((brick / this->BrickDims[0]) % this->BrickDims[1]) * BrickSize,
      (brick / (this->BrickDims[0] * this->BrickDims[1])) * BrickSize };
    for (int k = 0; k < BrickSize; ++k)
    {
      for (int j = 0; j < BrickSize; ++j)
      {
        for (int i = 0; i < BrickSize; ++i)
        {
          const std::int64_t x = first[0] + i, y = first[1] + j, z = first[2] + k;
          values[i + BrickSize * (j + BrickSize * k)] = x < grid.Dims[0] && y < grid.Dims[1] && z < grid.Dims[2]
            ? this->Nodes[grid.Index(x, y, z)]
            : this->Outside;
        }
      }
    }
  }

private:
  const Grid& TheGrid;
  const std::vector<float>& Nodes;
  float Outside;
  std::array<std::int64_t, 3> BrickDims;
};

/// f of the header, clamped to +-Clamp, brick by brick: a value per brick
/// where f is beyond +-Clamp on all of it, else its nodes' values.
class PartField : public BrickField
{
public:
  /// restored: material put back (f = max(f, its value)), before the
  /// holes are drilled.
  PartField(const Grid& grid, const float* outer, const std::vector<float>& distance, double offset,
    const InnerField& innerField, const std::vector<Drill>& drills = {}, const Restoration* restored = nullptr)
    : BrickDims(BrickDimensions(grid))
  {
    const float clamp = static_cast<float>(3.0 * grid.Spacing);
    const std::int64_t bricks = this->BrickDims[0] * this->BrickDims[1] * this->BrickDims[2];
    this->Uniform.assign(static_cast<std::size_t>(bricks), -clamp);
    std::vector<std::vector<float>> values(static_cast<std::size_t>(bricks));
    ParallelFor(0, bricks, 16, [&](std::int64_t begin, std::int64_t end) {
      std::vector<float> mine(BrickNodes);
      for (std::int64_t b = begin; b < end; ++b)
      {
        const std::int64_t first[3] = { (b % this->BrickDims[0]) * BrickSize,
          ((b / this->BrickDims[0]) % this->BrickDims[1]) * BrickSize,
          (b / (this->BrickDims[0] * this->BrickDims[1])) * BrickSize };
        bool above = true, below = true;
        const bool restoring = restored && restored->Reaches(b);
        for (int k = 0; k < BrickSize; ++k)
        {
          for (int j = 0; j < BrickSize; ++j)
          {
            for (int i = 0; i < BrickSize; ++i)
            {
              const std::int64_t x = first[0] + i, y = first[1] + j, z = first[2] + k;
              float f = -clamp;
              if (x < grid.Dims[0] && y < grid.Dims[1] && z < grid.Dims[2])
              {
                const std::int64_t n = grid.Index(x, y, z);
                const double d = distance[n];
                const double inside = std::min(d - offset, innerField(n));
                double value = outer[n] > 0.0f ? inside : -(offset + d);
                const double at[3] = { grid.Origin[0] + static_cast<double>(x) * grid.Spacing,
                  grid.Origin[1] + static_cast<double>(y) * grid.Spacing,
                  grid.Origin[2] + static_cast<double>(z) * grid.Spacing };
                if (restoring && value < clamp)
                {
                  value = std::max(value, restored->Value(b, at));
                }
                if (!drills.empty() && value > -clamp)
                {
                  for (const Drill& drill : drills)
                  {
                    value = std::min(value, drill.Signed(at)); // the hole less the material
                  }
                }
                f = static_cast<float>(std::max<double>(-clamp, std::min<double>(clamp, value)));
              }
              mine[i + BrickSize * (j + BrickSize * k)] = f;
              above = above && f >= clamp;
              below = below && f <= -clamp;
            }
          }
        }
        if (above || below)
        {
          this->Uniform[b] = above ? clamp : -clamp;
        }
        else
        {
          values[b] = mine;
        }
      }
    });
    for (std::int64_t b = 0; b < bricks; ++b)
    {
      if (!values[b].empty())
      {
        this->Varying.push_back(b);
        this->Stored.insert(this->Stored.end(), values[b].begin(), values[b].end());
      }
    }
  }

  void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const override
  {
    const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
    uniform.assign(this->Uniform.begin() + layer * perLayer, this->Uniform.begin() + (layer + 1) * perLayer);
    const auto first = std::lower_bound(this->Varying.begin(), this->Varying.end(), layer * perLayer);
    const auto last = std::lower_bound(first, this->Varying.end(), (layer + 1) * perLayer);
    varying.assign(first, last);
  }

  void Values(std::int64_t brick, float values[BrickNodes]) const override
  {
    const auto found = std::lower_bound(this->Varying.begin(), this->Varying.end(), brick);
    if (found != this->Varying.end() && *found == brick)
    {
      const float* stored = &this->Stored[(found - this->Varying.begin()) * BrickNodes];
      std::copy(stored, stored + BrickNodes, values);
    }
    else
    {
      std::fill(values, values + BrickNodes, this->Uniform[brick]);
    }
  }

  /// f at a place, trilinear between the nodes of its cell (clamped to
  /// +-3 h as stored).
  double At(const Grid& grid, const double x[3]) const
  {
    return Trilinear(grid, x, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
      const std::int64_t brick =
        (i >> BrickShift) + this->BrickDims[0] * ((j >> BrickShift) + this->BrickDims[1] * (k >> BrickShift));
      const auto found = std::lower_bound(this->Varying.begin(), this->Varying.end(), brick);
      if (found == this->Varying.end() || *found != brick)
      {
        return static_cast<double>(this->Uniform[brick]);
      }
      const std::int64_t within =
        (i & (BrickSize - 1)) + BrickSize * ((j & (BrickSize - 1)) + BrickSize * (k & (BrickSize - 1)));
      return static_cast<double>(this->Stored[(found - this->Varying.begin()) * BrickNodes + within]);
    });
  }

private:
  std::array<std::int64_t, 3> BrickDims;
  std::vector<float> Uniform;        ///< per brick: its value where it does not vary
  std::vector<std::int64_t> Varying; ///< the bricks where f is within +-3 h, ascending
  std::vector<float> Stored;         ///< their nodes' values, BrickNodes each
};

/// A node array's value at a place, trilinear between the nodes of its cell.
double ValueAt(const Grid& grid, const float* values, const double x[3])
{
  return Trilinear(grid, x, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<double>(values[grid.Index(i, j, k)]);
  });
}

/// The least distance from a vertex of the inner surface (D > l + w / 2)
/// to a vertex of the outer surface; 0 without an inner surface. Stops
/// early when the monitor (may be null) asks (the caller asks it again).
double MinimumWall(const Grid& grid, const SurfaceArrays& part, const std::vector<float>& distance, double offset,
  double wall, std::array<double, 3>& where, Monitor* monitor)
{
  const std::int64_t n = part.NumberOfPoints;
  std::vector<char> inner(static_cast<std::size_t>(n), 0);
  const double split = offset + 0.5 * wall;
  ParallelFor(0, n, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      inner[p] = ValueAt(grid, distance.data(), part.Points + 3 * p) > split;
    }
  });
  std::vector<double> outerPoints, innerPoints;
  for (std::int64_t p = 0; p < n; ++p)
  {
    std::vector<double>& to = inner[p] ? innerPoints : outerPoints;
    to.insert(to.end(), part.Points + 3 * p, part.Points + 3 * p + 3);
  }
  if (innerPoints.empty() || outerPoints.empty())
  {
    return 0.0;
  }
  const NearestPoints outside(outerPoints.data(), static_cast<std::int64_t>(outerPoints.size() / 3));
  const double far = 2.0 * (offset + wall) + 4.0 * grid.Spacing;
  const std::int64_t count = static_cast<std::int64_t>(innerPoints.size() / 3);
  // The least, and the first inner vertex that has it (the same for any
  // number of threads).
  std::pair<double, std::int64_t> least{ std::numeric_limits<double>::infinity(), 0 };
  std::mutex lock;
  StoppableFor(0, count, 1024, monitor, [&](std::int64_t begin, std::int64_t end) {
    std::pair<double, std::int64_t> mine{ std::numeric_limits<double>::infinity(), 0 };
    for (std::int64_t p = begin; p < end; ++p)
    {
      mine = std::min(mine, std::make_pair(outside.Distance(&innerPoints[3 * p], far), p));
    }
    const std::lock_guard<std::mutex> guard(lock);
    least = std::min(least, mine);
  });
  std::copy(&innerPoints[3 * least.second], &innerPoints[3 * least.second] + 3, where.begin());
  return least.first;
}
/// A hole's way out of S from x (a point in a cavity) along the unit
/// vector d, for a hole of `radius`: marched in steps of h / 2, looking at
/// the hole's axis and 8 points around it on its rim. Length is the way's
/// length to where the whole cross-section has left S, Material what of it
/// has any of the cross-section in material, after the cavity that x is in
/// (a second cavity on the way counts as material: the hole would cut
/// through its wall too); infinite beyond `longest`. A hole that runs
/// beside a limb, cutting into it, runs long and is refused.
struct WayOut
{
  double Direction[3] = { 0.0, 0.0, 0.0 };
  double Length = 0.0;
  double Material = std::numeric_limits<double>::infinity();
};

template <typename Cavity>
WayOut WayAlong(const Grid& grid, const float* outer, const Cavity& cavity, const double x[3], const double d[3],
  double radius, double longest)
{
  const double h = grid.Spacing;
  WayOut way;
  std::copy(d, d + 3, way.Direction);
  // Two unit vectors across d.
  const int least = std::fabs(d[0]) <= std::fabs(d[1]) && std::fabs(d[0]) <= std::fabs(d[2]) ? 0
    : std::fabs(d[1]) <= std::fabs(d[2])                                                   ? 1
                                                                                            : 2;
  double e1[3] = { 0.0, 0.0, 0.0 }, e2[3];
  e1[least] = 1.0;
  const double along = e1[0] * d[0] + e1[1] * d[1] + e1[2] * d[2];
  double norm = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    e1[a] -= along * d[a];
    norm += e1[a] * e1[a];
  }
  for (int a = 0; a < 3; ++a)
  {
    e1[a] /= std::sqrt(norm);
  }
  e2[0] = d[1] * e1[2] - d[2] * e1[1];
  e2[1] = d[2] * e1[0] - d[0] * e1[2];
  e2[2] = d[0] * e1[1] - d[1] * e1[0];
  // What lies at p: -1 outside S, 0 in a cavity, 1 in material.
  const auto at = [&](const double p[3]) {
    std::int64_t ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = static_cast<std::int64_t>(std::floor((p[a] - grid.Origin[a]) / h + 0.5));
      if (ijk[a] < 0 || ijk[a] >= grid.Dims[a])
      {
        return -1;
      }
    }
    const std::int64_t n = grid.Index(ijk[0], ijk[1], ijk[2]);
    return outer[n] <= 0.0f ? -1 : cavity(n) ? 0 : 1;
  };
  double t = 0.0, material = 0.0;
  bool leaving = true; // the axis still in x's cavity
  for (;; t += 0.5 * h)
  {
    int most = -1; // the most the cross-section meets: -1 outside S, 0 a cavity, 1 material
    for (int k = -1; k < 8 && most < 1; ++k)
    {
      const double angle = 2.0 * 3.14159265358979323846 * k / 8.0;
      const double r = k < 0 ? 0.0 : radius;
      double p[3];
      for (int a = 0; a < 3; ++a)
      {
        p[a] = x[a] + t * d[a] + r * (std::cos(angle) * e1[a] + std::sin(angle) * e2[a]);
      }
      const int here = at(p);
      leaving = leaving && !(k < 0 && here != 0);
      most = std::max(most, here);
    }
    if (most < 0)
    {
      break; // the whole cross-section out of S
    }
    material += leaving || most == 0 ? 0.0 : 0.5 * h;
    if (material > longest + h)
    {
      return way; // too long
    }
  }
  way.Length = t;
  way.Material = material;
  return way;
}

/// The shortest way out of S from x: among the directions within `angle`
/// (radians) of `down`, the one through the least material (WayAlong),
/// tried on rings of 0, 1/4, ... 4/4 of the angle, 12 directions on each
/// ring but the first; straight down first, so that it wins unless another
/// is shorter by more than a cell.
template <typename Cavity>
WayOut ShortestWayOut(const Grid& grid, const float* outer, const Cavity& cavity, const double x[3], DrainAxis down,
  double angle, double radius, double longest)
{
  const int axis = static_cast<int>(down) / 2;
  const double sign = static_cast<int>(down) % 2 == 0 ? -1.0 : 1.0;
  const int across[2] = { (axis + 1) % 3, (axis + 2) % 3 };
  WayOut best;
  const int rings = angle > 0.0 ? 4 : 0;
  for (int ring = 0; ring <= rings; ++ring)
  {
    const double tilt = rings > 0 ? angle * ring / rings : 0.0;
    for (int turn = 0; turn < (ring == 0 ? 1 : 12); ++turn)
    {
      const double around = 2.0 * 3.14159265358979323846 * turn / 12.0;
      double d[3];
      d[axis] = sign * std::cos(tilt);
      d[across[0]] = std::sin(tilt) * std::cos(around);
      d[across[1]] = std::sin(tilt) * std::sin(around);
      const WayOut way = WayAlong(grid, outer, cavity, x, d, radius, std::min(longest, best.Material));
      if (way.Material < best.Material - grid.Spacing) // shorter by more than a cell: not the grid's noise
      {
        best = way;
      }
    }
  }
  return best;
}

/// The drain holes (DrainHoles): the cavities are the regions of nodes
/// inside S where the inner field is not positive (6-connected) whose
/// volume is at least `minimumVolume` (the cavities kept). Each hole starts
/// at a point of a cavity: at the kept cavity's node nearest to each of
/// request.DrainPositions where those are given, else at each cavity's
/// lowest points along request.Down, request.DrainHoles of them at least
/// three diameters apart (from one another and from the places tried). A
/// position outside the cavities (on the scan, in the wall) gives the
/// hole's way: straight from that node through the position and on out of
/// S. Otherwise the hole leaves by the shortest way out of S within
/// request.DrainAngle of request.Down (ShortestWayOut). It runs to 2 h past
/// the outside, unless its way runs through more than 2 (l + w) + 2 h of
/// material (down a limb: within 60 degrees of the wall's normal the way
/// through the wall and the offset is shorter): those are not made. The report counts what was asked and why holes were
/// not made.
std::vector<Drill> DrainHoles(const Grid& grid, const float* outer, const InnerField& inner, double offset,
  double wall, double minimumVolume, double radius, const PartRequest& request, PrintReport& report)
{
  const double longest = 2.0 * (offset + wall) + 2.0 * grid.Spacing;
  const std::int64_t nodes = grid.NumberOfNodes();
  const double h = grid.Spacing;
  const DrainAxis down = request.Down;
  const double angle = request.DrainAngle * 3.14159265358979323846 / 180.0;
  const int axis = static_cast<int>(down) / 2;               // the axis down is along,
  const int sign = static_cast<int>(down) % 2 == 0 ? -1 : 1; // which way along it,
  const int across[2] = { (axis + 1) % 3, (axis + 2) % 3 };  // and the plane across it
  const std::size_t positions = request.DrainPositions.size() / 3;
  auto cavity = [&](std::int64_t n) { return outer[n] > 0.0f && inner(n) <= 0.0; };
  auto place = [&](std::int64_t n, double x[3]) {
    std::int64_t ijk[3];
    grid.Ijk(n, ijk);
    for (int a = 0; a < 3; ++a)
    {
      x[a] = grid.Origin[a] + static_cast<double>(ijk[a]) * h;
    }
  };
  std::vector<Drill> drills;
  std::vector<char> drilled; // per kept cavity: whether a hole leaves it
  // Drills a hole from x out of S, if its way is short enough: towards
  // `toward` where that is given and not x, else by the shortest way out.
  auto drill = [&](const double x[3], std::size_t cavityIndex, const double* toward) {
    double d[3] = { 0.0, 0.0, 0.0 }, length = 0.0;
    for (int a = 0; toward && a < 3; ++a)
    {
      d[a] = toward[a] - x[a];
      length += d[a] * d[a];
    }
    length = std::sqrt(length);
    for (int a = 0; a < 3; ++a)
    {
      d[a] = length > 0.5 * h ? d[a] / length : 0.0;
    }
    const WayOut way = length > 0.5 * h ? WayAlong(grid, outer, cavity, x, d, radius, longest)
                                        : ShortestWayOut(grid, outer, cavity, x, down, angle, radius, longest);
    if (way.Material > longest)
    {
      ++report.DrainHolesTooLong; // down a limb, or through a wall at a slant: not here
      return false;
    }
    Drill made;
    for (int a = 0; a < 3; ++a)
    {
      made.A[a] = x[a] - radius * way.Direction[a];
      made.B[a] = x[a] + (way.Length + 2.0 * h + radius) * way.Direction[a];
    }
    made.Radius = radius;
    drills.push_back(made);
    drilled[cavityIndex] = 1;
    return true;
  };
  // Per position: the nearest node of a kept cavity (squared distance, node, cavity).
  std::vector<std::tuple<double, std::int64_t, std::size_t>> nearest(
    positions, std::make_tuple(std::numeric_limits<double>::infinity(), std::int64_t(-1), std::size_t(0)));
  std::vector<std::int32_t> label(static_cast<std::size_t>(nodes), -1);
  std::vector<std::int64_t> region;
  std::int32_t next = 0;
  // Nodes in ascending order, z slowest: a region's first node is its lowest.
  for (std::int64_t start = 0; start < nodes; ++start)
  {
    if (label[start] >= 0 || !cavity(start))
    {
      continue;
    }
    region.assign(1, start);
    label[start] = next;
    for (std::size_t head = 0; head < region.size(); ++head)
    {
      std::int64_t ijk[3];
      grid.Ijk(region[head], ijk);
      for (int a = 0; a < 3; ++a)
      {
        for (int step : { -1, 1 })
        {
          std::int64_t to[3] = { ijk[0], ijk[1], ijk[2] };
          to[a] += step;
          if (to[a] < 0 || to[a] >= grid.Dims[a])
          {
            continue;
          }
          const std::int64_t m = grid.Index(to[0], to[1], to[2]);
          if (label[m] < 0 && cavity(m))
          {
            label[m] = next;
            region.push_back(m);
          }
        }
      }
    }
    ++next;
    if (static_cast<double>(region.size()) * h * h * h < minimumVolume)
    {
      continue; // merged into the wall
    }
    const std::size_t kept = drilled.size();
    drilled.push_back(0);
    if (positions > 0)
    {
      for (std::size_t p = 0; p < positions; ++p)
      {
        const double* at = &request.DrainPositions[3 * p];
        for (std::int64_t n : region)
        {
          double x[3], d2 = 0.0;
          place(n, x);
          for (int a = 0; a < 3; ++a)
          {
            d2 += (x[a] - at[a]) * (x[a] - at[a]);
          }
          if (d2 < std::get<0>(nearest[p]))
          {
            nearest[p] = std::make_tuple(d2, n, kept);
          }
        }
      }
      continue;
    }
    // The lowest points of the cavity's surface: below a node, about its
    // depth in the cavity (-inner) under it; the region sorted by that
    // height (then its node order).
    const auto height = [&](std::int64_t n) {
      std::int64_t ijk[3];
      grid.Ijk(n, ijk);
      return -sign * (grid.Origin[axis] + static_cast<double>(ijk[axis]) * h) + inner(n);
    };
    std::vector<std::pair<double, std::int64_t>> lowest; // (height, node), each height made once
    lowest.reserve(region.size());
    for (std::int64_t n : region)
    {
      lowest.emplace_back(height(n), n);
    }
    std::stable_sort(lowest.begin(), lowest.end(),
      [](const std::pair<double, std::int64_t>& u, const std::pair<double, std::int64_t>& v) { return u.first < v.first; });
    std::vector<std::array<double, 3>> tops; // the holes' tops and the places tried, which the next keep away from
    int made = 0;
    for (const auto& entry : lowest)
    {
      if (made == request.DrainHoles)
      {
        break;
      }
      std::array<double, 3> x;
      place(entry.second, x.data());
      bool apart = true;
      for (const auto& t : tops)
      {
        const double du = t[across[0]] - x[across[0]], dv = t[across[1]] - x[across[1]];
        apart = apart && du * du + dv * dv >= 36.0 * radius * radius;
      }
      if (!apart)
      {
        continue;
      }
      tops.push_back(x);
      made += drill(x.data(), kept, nullptr) ? 1 : 0;
    }
  }
  report.DrainHolesAsked =
    positions > 0 ? static_cast<std::int64_t>(positions) : request.DrainHoles * static_cast<std::int64_t>(drilled.size());
  for (std::size_t p = 0; p < positions; ++p)
  {
    const double* at = &request.DrainPositions[3 * p];
    if (std::get<1>(nearest[p]) < 0 || std::sqrt(std::get<0>(nearest[p])) > longest)
    {
      if (report.DrainPositionsAway++ == 0)
      {
        std::copy(at, at + 3, report.FirstPositionAway.begin());
      }
      continue;
    }
    double x[3];
    place(std::get<1>(nearest[p]), x);
    drill(x, std::get<2>(nearest[p]), at);
  }
  report.CavitiesWithoutHoles = static_cast<std::int64_t>(std::count(drilled.begin(), drilled.end(), 0));
  return drills;
}

/// The scan's lost points (PrintReport): those farther than
/// report.LostDistance outside the part beyond what the closing explains,
/// |D - l| for a point at D from the outer sheet (D = l on a surface smooth
/// at the offset's scale; a point in a concavity narrower than l is inside
/// the material, at D - l from its outer surface or less). The distance to
/// the part is to its nearest vertex. Points deeper than `cap` (D unknown),
/// and points where a drain hole was drilled, are not checked. Sets
/// report.FarthestLost; the points' indices, ascending.
std::vector<std::int64_t> LostPoints(const Grid& grid, const float* outer, const PartField& field,
  const SurfaceArrays& part, const std::vector<float>& distance, double offset, double cap, const PartRequest& request,
  const std::vector<Drill>& drills, PrintReport& report, Monitor* monitor)
{
  const std::int64_t n = request.Scan ? request.ScanPoints : 0;
  const NearestPoints vertices(part.Points, part.NumberOfPoints);
  const double bound = report.LostDistance, h = grid.Spacing;
  std::vector<float> beyond(static_cast<std::size_t>(n), 0.0f); // how far outside, beyond the bound
  StoppableFor(0, n, 1024, monitor, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      const double* x = request.Scan + 3 * p;
      const bool insideShell = ValueAt(grid, outer, x) > 0.0;
      // D, or none outside the outer sheet (the shell itself lost the point:
      // nothing explains a distance).
      const double d = insideShell ? ValueAt(grid, distance.data(), x) : offset;
      bool drilled = false;
      for (const Drill& drill : drills)
      {
        drilled = drilled || drill.Signed(x) < bound;
      }
      if (d >= cap - h || drilled)
      {
        continue;
      }
      // Inside f's material (restored material among it), a point is as
      // deep as f says, up to its clamp.
      const double explained = std::max(std::abs(d - offset), field.At(grid, x)) + bound;
      const double nearest = vertices.Distance(x, std::numeric_limits<double>::infinity());
      if (nearest > explained)
      {
        beyond[p] = static_cast<float>(nearest - std::abs(d - offset));
      }
    }
  });
  std::vector<std::int64_t> lost;
  report.FarthestLost = 0.0;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (beyond[p] > 0.0f)
    {
      lost.push_back(p);
      report.FarthestLost = std::max(report.FarthestLost, static_cast<double>(beyond[p]));
    }
  }
  return lost;
}

/// The lost points in regions: points in cells of side `reach` that touch
/// (26 neighbours) are one region; the regions, the most points first.
std::vector<LostRegion> LostRegions(const double* scan, const std::vector<std::int64_t>& lost, double reach)
{
  const std::int64_t n = static_cast<std::int64_t>(lost.size());
  if (n == 0)
  {
    return {};
  }
  using Cell = std::array<std::int64_t, 3>;
  std::vector<std::pair<Cell, std::int64_t>> cells(static_cast<std::size_t>(n)); // (cell, index into lost)
  for (std::int64_t i = 0; i < n; ++i)
  {
    const double* x = scan + 3 * lost[i];
    cells[i] = { { static_cast<std::int64_t>(std::floor(x[0] / reach)),
                   static_cast<std::int64_t>(std::floor(x[1] / reach)),
                   static_cast<std::int64_t>(std::floor(x[2] / reach)) },
      i };
  }
  std::sort(cells.begin(), cells.end());
  std::vector<std::int64_t> parent(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i)
  {
    parent[i] = i;
  }
  const auto root = [&](std::int64_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  for (std::int64_t i = 0; i < n; ++i)
  {
    const Cell& c = cells[i].first;
    for (std::int64_t dz = -1; dz <= 1; ++dz)
    {
      for (std::int64_t dy = -1; dy <= 1; ++dy)
      {
        for (std::int64_t dx = -1; dx <= 1; ++dx)
        {
          const Cell other{ { c[0] + dx, c[1] + dy, c[2] + dz } };
          const auto found = std::lower_bound(cells.begin(), cells.end(), std::make_pair(other, std::int64_t(0)));
          if (found != cells.end() && found->first == other)
          {
            parent[root(i)] = root(found - cells.begin());
          }
        }
      }
    }
  }
  std::vector<std::int64_t> regionOf(static_cast<std::size_t>(n), -1);
  std::vector<LostRegion> regions;
  std::vector<std::array<double, 6>> boxes;
  for (std::int64_t i = 0; i < n; ++i)
  {
    const std::int64_t r = root(i);
    if (regionOf[r] < 0)
    {
      regionOf[r] = static_cast<std::int64_t>(regions.size());
      regions.emplace_back();
      boxes.push_back({ { std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() } });
    }
    LostRegion& region = regions[regionOf[r]];
    std::array<double, 6>& box = boxes[regionOf[r]];
    const double* x = scan + 3 * lost[cells[i].second];
    ++region.Points;
    for (int a = 0; a < 3; ++a)
    {
      region.Center[a] += x[a];
      box[2 * a] = std::min(box[2 * a], x[a]);
      box[2 * a + 1] = std::max(box[2 * a + 1], x[a]);
    }
  }
  for (std::size_t r = 0; r < regions.size(); ++r)
  {
    for (int a = 0; a < 3; ++a)
    {
      regions[r].Center[a] /= static_cast<double>(regions[r].Points);
      regions[r].Size[a] = boxes[r][2 * a + 1] - boxes[r][2 * a];
    }
  }
  std::stable_sort(regions.begin(), regions.end(),
    [](const LostRegion& u, const LostRegion& v) { return u.Points > v.Points; });
  return regions;
}
} // namespace

bool MakePart(const Grid& grid, const Parameters& parameters, const float* outer, const PartRequest& request,
  SurfaceSink& sink, Monitor* monitor, PrintReport& report)
{
  const double l = parameters.OffsetDistance, h = grid.Spacing, wall = request.Wall;
  // The progress of the steps, as shares of the request's stage, about as
  // their time goes (the distance D is the longest).
  const auto step = [&](double from, double to) {
    if (monitor)
    {
      monitor->Stage(request.Progress[0] + from * request.Progress[1], (to - from) * request.Progress[1]);
    }
  };
  step(0.0, 0.1);
  // The outer sheet: phi = 0 with the cavities filled.
  SurfaceMesh sheet;
  const DenseField field(grid, outer, 0, grid.Dims[2], parameters);
  if (!ContourBricks(grid, field, sheet, 0, -1, monitor))
  {
    return false;
  }
  // The part's surfaces, f = 0.
  const double closing = request.CavityClosing;
  const double cap = l + wall + closing + 4.0 * h;
  step(0.1, 0.5);
  const std::vector<float> distance = SheetDistance(grid, outer, sheet.Points, cap, monitor);
  if (monitor && monitor->Aborted())
  {
    return false;
  }
  // With a closing distance c: G, the distance to the surface of the cavity
  // eroded by c (E, D > l + w + c), from E's surface's vertices.
  std::vector<float> grown;
  if (closing > 0.0)
  {
    SurfaceMesh eroded;
    {
      std::vector<float> depth(distance.size());
      const float deepest = static_cast<float>(l + wall + closing);
      ParallelFor(0, grid.NumberOfNodes(), 1 << 16, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t n = begin; n < end; ++n)
        {
          depth[n] = outer[n] > 0.0f ? distance[n] - deepest : -deepest;
        }
      });
      if (!ContourBricks(grid, NodeField(grid, depth, -deepest), eroded, 0, -1, nullptr))
      {
        return false;
      }
    }
    grown = SheetDistance(grid, outer, eroded.Points, closing + 4.0 * h, monitor);
    if (StopAsked(monitor))
    {
      return false;
    }
  }
  const InnerField inner{ distance, closing > 0.0 ? &grown : nullptr, l + wall, closing };
  step(0.5, 0.7);
  std::vector<Drill> drills;
  // Contours f (with the holes drilled and the lost points' material put
  // back, as asked) into the sink, and removes its loose pieces and small
  // cavities: the cavities below `minimumCavity` (0: a share of the
  // largest), the pieces below a ball of 2 l unless `supported` keeps them.
  PieceLimits limits;
  limits.Piece = SmallPieceVolume(l);
  limits.SpareLargest = false; // slivers of an open scan's closing are no part
  std::unique_ptr<PartField> part;
  const auto contour = [&](const Restoration* restored, double minimumCavity) {
    part.reset(); // one at a time
    part.reset(new PartField(grid, outer, distance, l, inner, drills, restored));
    SurfaceArrays none = sink.View();
    none.NumberOfPoints = none.NumberOfTriangles = 0;
    sink.Truncate(none);
    if (!ContourBricks(grid, *part, sink, 0, -1, monitor))
    {
      return false;
    }
    limits.Void = minimumCavity;
    limits.VoidShare = minimumCavity > 0.0 ? 0.0 : AutomaticCavityShare;
    const RemovedPieces removed = RemoveSmallPieces(sink, limits, grid, nullptr, 0, 0);
    report.MaterialVolume = removed.Volume;
    report.CavityVolume = removed.CavityVolume;
    report.MinimumCavityVolume = removed.VoidLimit;
    report.KeptCavities = removed.Cavities;
    report.RemovedCavities = removed.Voids;
    report.RemovedPieces = removed.Pieces;
    report.Pieces = removed.KeptPieces;
    return true;
  };
  if (!contour(nullptr, request.MinimumCavity))
  {
    return false;
  }
  // The wall as made, before the holes cut through it.
  report.MinimumWallThickness =
    report.KeptCavities > 0 ? MinimumWall(grid, sink.View(), distance, l, wall, report.ThinnestWallAt, monitor) : 0.0;
  if (StopAsked(monitor))
  {
    return false;
  }
  step(0.7, 0.85);
  if ((request.DrainHoles > 0 || !request.DrainPositions.empty()) && report.KeptCavities > 0)
  {
    // Again with the holes: the kept cavities now open to the outside, the
    // merged ones go as before (by the same volume).
    const double radius =
      0.5 * (request.DrainDiameter > 0.0 ? request.DrainDiameter : std::max(2.0 * wall, 4.0 * h));
    drills = DrainHoles(grid, outer, inner, l, wall, report.MinimumCavityVolume, radius, request, report);
    const double cavity = report.MinimumCavityVolume, cavityVolume = report.CavityVolume;
    const std::int64_t kept = report.KeptCavities;
    if (!contour(nullptr, cavity))
    {
      return false;
    }
    report.CavityVolume = cavityVolume; // the cavities are open now: the volumes before
    report.KeptCavities = kept;
    report.DrainHoles = static_cast<std::int64_t>(drills.size());
  }
  // The scan against the part: material around the points it lost, where
  // they are a limb or a piece and not the scan (RestorableShare), then
  // what is still lost.
  step(0.85, 1.0);
  report.LostDistance = LostDistanceCells * h;
  report.ScanPoints = request.Scan ? request.ScanPoints : 0;
  std::vector<std::int64_t> lost =
    LostPoints(grid, outer, *part, sink.View(), distance, l, cap, request, drills, report, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  if (!lost.empty() && static_cast<double>(lost.size()) <= RestorableShare * static_cast<double>(request.ScanPoints))
  {
    const Restoration restored(grid, request.Scan, request.ScanPoints, lost, LostRadiusCells * h, 2.0 * l);
    const double reach = (LostRadiusCells + 1.0) * h;
    limits.Supported = [&](const double* x) { return restored.NearLost(x, reach); };
    const double cavityVolume = report.CavityVolume;
    const std::int64_t kept = report.KeptCavities;
    if (!contour(&restored, report.MinimumCavityVolume))
    {
      return false;
    }
    if (!drills.empty())
    {
      report.CavityVolume = cavityVolume;
      report.KeptCavities = kept;
    }
    const std::vector<std::int64_t> left =
      LostPoints(grid, outer, *part, sink.View(), distance, l, cap, request, drills, report, monitor);
    if (StopAsked(monitor))
    {
      return false;
    }
    std::vector<std::int64_t> back; // the lost points held now
    std::set_difference(lost.begin(), lost.end(), left.begin(), left.end(), std::back_inserter(back));
    report.RestoredPoints = static_cast<std::int64_t>(back.size());
    report.RestoredRegions = LostRegions(request.Scan, back, LostRegionReach * h);
    lost = left;
  }
  report.LostPoints = static_cast<std::int64_t>(lost.size());
  report.LostRegions = LostRegions(request.Scan, lost, LostRegionReach * h);
  const SurfaceArrays arrays = sink.View();
  for (std::int64_t p = 0; p < arrays.NumberOfPoints; ++p)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double x = arrays.Points[3 * p + a];
      report.Bounds[2 * a] = p == 0 ? x : std::min(report.Bounds[2 * a], x);
      report.Bounds[2 * a + 1] = p == 0 ? x : std::max(report.Bounds[2 * a + 1], x);
    }
  }
  return !(monitor && monitor->Aborted());
}

} // namespace nv
