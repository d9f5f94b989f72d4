// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The distance D from the nodes inside the outer sheet to its vertices
// (SheetDistance, nvPartSteps.h): a closest-point propagation.
#include "nvPartSteps.h"

#include "nvParallel.h"

#include <atomic>
#include <cstring>

namespace nv
{
namespace part
{
namespace
{
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
} // namespace

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
} // namespace part
} // namespace nv
