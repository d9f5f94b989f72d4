// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPartition.h"

#include "nvCommunicator.h"

#include <algorithm>

namespace nv
{

Subdomain Subdomain::Whole(std::int64_t layers)
{
  Subdomain whole;
  whole.Owned = LayerRange{ 0, layers };
  whole.Computed = whole.Owned;
  return whole;
}

Subdomain Subdomain::Around(LayerRange owned, std::int64_t layers)
{
  Subdomain part;
  part.Owned = owned;
  if (!owned.Empty())
  {
    part.Computed = LayerRange{ std::max<std::int64_t>(0, owned.Begin - 1), std::min(layers, owned.End + 1) };
  }
  return part;
}

std::vector<LayerRange> SplitLayers(const std::vector<double>& weights, int parts)
{
  const std::int64_t layers = static_cast<std::int64_t>(weights.size());
  parts = std::max(parts, 1);
  double total = 0.0;
  for (double w : weights)
  {
    total += w;
  }
  // Greedy cut: part p ends once the running weight reaches (p + 1) / parts of
  // the total, but leaves at least one layer to each later part.
  std::vector<LayerRange> ranges(static_cast<std::size_t>(parts));
  std::int64_t begin = 0;
  double running = 0.0;
  for (int p = 0; p < parts; ++p)
  {
    const std::int64_t remainingParts = parts - p - 1;
    const double target = total * (p + 1) / parts;
    std::int64_t end = begin;
    if (p == parts - 1)
    {
      end = layers;
    }
    else
    {
      const std::int64_t latestEnd = std::max(std::min(begin + 1, layers), layers - remainingParts);
      while (end < latestEnd && (end == begin || running + weights[end] <= target || total <= 0.0))
      {
        running += weights[end];
        ++end;
        if (total <= 0.0 && end - begin >= (layers + parts - 1) / parts)
        {
          break; // no weights: equal numbers of layers
        }
      }
    }
    ranges[p] = LayerRange{ begin, end };
    begin = end;
  }
  return ranges;
}

std::vector<double> ExchangePoints(
  Communicator& communicator, const std::vector<double>& xyz, const std::vector<std::array<double, 2>>& zRanges)
{
  // Each destination's points: those of this process within its interval.
  std::vector<std::vector<double>> outgoing(static_cast<std::size_t>(communicator.Size()));
  for (int q = 0; q < communicator.Size(); ++q)
  {
    for (std::size_t p = 0; p + 2 < xyz.size(); p += 3)
    {
      if (zRanges[q][0] <= xyz[p + 2] && xyz[p + 2] <= zRanges[q][1])
      {
        outgoing[q].insert(outgoing[q].end(), &xyz[p], &xyz[p] + 3);
      }
    }
  }
  return communicator.Exchange(outgoing);
}

} // namespace nv
