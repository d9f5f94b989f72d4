// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvNarrowBand.h"

#include "nvParallel.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>

namespace nv
{

namespace
{

bool IsRed(std::int64_t i, std::int64_t j, std::int64_t k)
{
  return ((i + j + k) & 1) == 0;
}

/// Visits the band nodes of one brick in ascending grid index: fn(i, j, k,
/// n, d), n = i + 8 (j + 8 k) in the brick. Marks the brick's other nodes inside the shell in `inside`, and hands
/// its distances to `visitor`, if any.
template <typename Fn>
void ForEachBandNode(const TruncatedDistance& distance, const Parameters& parameters, std::int64_t brick,
  const BrickVisitor& visitor, double scratch[BrickNodes], std::uint64_t inside[BrickNodes / 64], Fn&& fn)
{
  const Grid& grid = distance.GetGrid();
  const bool whole = parameters.Mode == Domain::WholeDomain;
  const double lower = parameters.OffsetDistance - parameters.HalfBandWidth();
  const double upper = distance.GetReach();
  std::fill(inside, inside + BrickNodes / 64, std::uint64_t(0));
  if (!whole && !visitor && distance.BrickWithin(brick, lower))
  {
    // d <= l - eta/2 on the whole brick (deep inside the shell): no band node
    std::fill(inside, inside + BrickNodes / 64, ~std::uint64_t(0));
    return;
  }
  distance.ComputeBrick(brick, scratch);
  if (visitor)
  {
    visitor(brick, scratch);
  }
  std::int64_t first[3];
  distance.BrickFirstNode(brick, first);
  for (int k = 0; k < BrickSize && first[2] + k < grid.Dims[2]; ++k)
  {
    for (int j = 0; j < BrickSize && first[1] + j < grid.Dims[1]; ++j)
    {
      for (int i = 0; i < BrickSize && first[0] + i < grid.Dims[0]; ++i)
      {
        const int n = i + BrickSize * (j + BrickSize * k);
        const double d = scratch[n];
        if (whole || (lower < d && d < upper))
        {
          fn(first[0] + i, first[1] + j, first[2] + k, n, d);
        }
        else if (d <= lower)
        {
          inside[n / 64] |= std::uint64_t(1) << (n % 64);
        }
      }
    }
  }
}

} // namespace

void NarrowBand::NodesInLayers(LayerRange layers, bool red, std::int64_t& begin, std::int64_t& end) const
{
  const std::int64_t bricksPerLayer = ((this->GridNodes.Dims[0] + BrickSize - 1) >> BrickShift) *
    ((this->GridNodes.Dims[1] + BrickSize - 1) >> BrickShift);
  std::int64_t first, last;
  BricksInLayers(this->Bricks, bricksPerLayer, layers.Begin, layers.End, first, last);
  const std::vector<std::int64_t>& start = red ? this->RedStart : this->BlackStart;
  begin = start[first];
  end = start[last];
}

void NarrowBand::BrickFirstNode(std::int64_t a, std::int64_t ijk[3]) const
{
  const std::int64_t dimX = (this->GridNodes.Dims[0] + BrickSize - 1) >> BrickShift;
  const std::int64_t dimY = (this->GridNodes.Dims[1] + BrickSize - 1) >> BrickShift;
  const std::int64_t brick = this->Bricks[a];
  ijk[0] = (brick % dimX) << BrickShift;
  ijk[1] = ((brick / dimX) % dimY) << BrickShift;
  ijk[2] = (brick / (dimX * dimY)) << BrickShift;
}

std::int64_t NarrowBand::GridIndex(std::int64_t s) const
{
  // The last brick whose range of s's colour starts at or before s.
  const std::vector<std::int64_t>& start = s < this->RedCount ? this->RedStart : this->BlackStart;
  const std::int64_t a = (std::upper_bound(start.begin(), start.end(), s) - start.begin()) - 1;
  std::int64_t first[3], ijk[3];
  this->BrickFirstNode(a, first);
  this->NodeIjk(first, s, ijk);
  return this->GridNodes.Index(ijk[0], ijk[1], ijk[2]);
}

void NarrowBand::OwnedNodes(bool red, std::int64_t& begin, std::int64_t& end) const
{
  if (this->RedStart.empty()) // a band without brick tables: all of it is owned
  {
    begin = red ? 0 : this->RedCount;
    end = red ? this->RedCount : this->Size();
    return;
  }
  this->NodesInLayers(this->OwnedLayers, red, begin, end);
}

NarrowBand BuildNarrowBand(const TruncatedDistance& distance, const Parameters& parameters, Monitor* monitor,
  const Subdomain* part, const BrickVisitor& visitor)
{
  NarrowBand band;
  band.GridNodes = distance.GetGrid();
  const Grid& grid = band.GridNodes;
  const std::int64_t bricksPerLayer = distance.GetBrickDims()[0] * distance.GetBrickDims()[1];
  const Subdomain whole = Subdomain::Whole(distance.GetBrickDims()[2]);
  if (!part)
  {
    part = &whole;
  }

  // Step 1: the bricks to visit, in the computed layers. Whole domain mode
  // visits all of them.
  std::vector<std::int64_t> bricks;
  if (parameters.Mode == Domain::WholeDomain)
  {
    for (std::int64_t b = part->Computed.Begin * bricksPerLayer; b < part->Computed.End * bricksPerLayer; ++b)
    {
      bricks.push_back(b);
    }
  }
  else
  {
    for (std::int64_t b : distance.ReachedBricks())
    {
      if (part->Computed.Contains(b / bricksPerLayer))
      {
        bricks.push_back(b);
      }
    }
  }
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(bricks.size());

  // Distances brick by brick; each brick keeps its band nodes, red and black
  // apart, in ascending grid index. This transient list grows with the band.
  struct Entry
  {
    std::uint16_t Offset; // in the brick
    double Distance;
  };
  struct BrickBand
  {
    std::vector<Entry> Red, Black;
  };
  std::vector<BrickBand> perBrick(static_cast<std::size_t>(numberOfBricks));
  band.Inside.resize(static_cast<std::size_t>(numberOfBricks * BrickNodes / 64));
  const bool done = MonitoredFor(0, numberOfBricks, 16, monitor, [&](std::int64_t begin, std::int64_t end) {
    double scratch[BrickNodes];
    for (std::int64_t a = begin; a < end; ++a)
    {
      BrickBand& out = perBrick[a];
      ForEachBandNode(distance, parameters, bricks[a], visitor, scratch, &band.Inside[a * BrickNodes / 64],
        [&](std::int64_t i, std::int64_t j, std::int64_t k, int n, double d) {
          (IsRed(i, j, k) ? out.Red : out.Black).push_back(Entry{ static_cast<std::uint16_t>(n), d });
        });
    }
  });
  if (!done)
  {
    return NarrowBand{};
  }

  // Step 2: store the band nodes compactly, red ones first, in brick order.
  std::vector<std::int64_t> redStart(static_cast<std::size_t>(numberOfBricks + 1), 0);
  std::vector<std::int64_t> blackStart(static_cast<std::size_t>(numberOfBricks + 1), 0);
  for (std::int64_t a = 0; a < numberOfBricks; ++a)
  {
    redStart[a + 1] = redStart[a] + static_cast<std::int64_t>(perBrick[a].Red.size());
    blackStart[a + 1] = blackStart[a] + static_cast<std::int64_t>(perBrick[a].Black.size());
  }
  band.RedCount = redStart[numberOfBricks];
  const std::int64_t size = band.RedCount + blackStart[numberOfBricks];
  if (size > MaximumBandSize || (parameters.MaximumBandNodes >= 0 && size > parameters.MaximumBandNodes))
  {
    NarrowBand refused;
    refused.RefusedSize = size;
    return refused;
  }
  for (std::int64_t a = 0; a <= numberOfBricks; ++a)
  {
    blackStart[a] += band.RedCount;
  }
  band.Offset.resize(static_cast<std::size_t>(size));
  band.Distance.resize(static_cast<std::size_t>(size));
  ParallelFor(0, numberOfBricks, 64, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      std::int64_t s = redStart[a];
      for (const Entry& e : perBrick[a].Red)
      {
        band.Offset[s] = e.Offset;
        band.Distance[s++] = e.Distance;
      }
      s = blackStart[a];
      for (const Entry& e : perBrick[a].Black)
      {
        band.Offset[s] = e.Offset;
        band.Distance[s++] = e.Distance;
      }
      std::vector<Entry>().swap(perBrick[a].Red);
      std::vector<Entry>().swap(perBrick[a].Black);
    }
  });
  std::vector<BrickBand>().swap(perBrick);

  // Step 3: connect each band node to its six neighbours. Each brick keeps a
  // 512-bit occupancy mask of its band nodes (64 bytes a brick, nothing per
  // node); a neighbour's position in the band is the start of its brick's
  // colour range plus the number of same-coloured band nodes before it.
  band.Bricks = std::move(bricks);
  std::vector<std::int32_t> slotOfBrick(static_cast<std::size_t>(distance.GetNumberOfBricks()), -1);
  for (std::int64_t a = 0; a < numberOfBricks; ++a)
  {
    slotOfBrick[band.Bricks[a]] = static_cast<std::int32_t>(a);
  }
  constexpr int Words = BrickNodes / 64;
  std::vector<std::uint64_t> occupied(static_cast<std::size_t>(numberOfBricks * Words), 0);
  const auto& brickDims = distance.GetBrickDims();
  auto localIndex = [](const std::int64_t ijk[3]) {
    return static_cast<int>((ijk[0] & (BrickSize - 1)) +
      BrickSize * ((ijk[1] & (BrickSize - 1)) + BrickSize * (ijk[2] & (BrickSize - 1))));
  };
  ParallelFor(0, numberOfBricks, 64, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      for (const auto* start : { &redStart, &blackStart })
      {
        for (std::int64_t s = (*start)[a]; s < (*start)[a + 1]; ++s)
        {
          const int n = band.Offset[s];
          occupied[a * Words + n / 64] |= std::uint64_t(1) << (n % 64);
        }
      }
    }
  });
  // Local index n = i + 8 j + 64 k; word w holds k = w. Bits of even i + j + k:
  // rows j alternate between the patterns 0x55 and 0xAA, swapped for odd k.
  const std::uint64_t evenWordMask = 0xAA55AA55AA55AA55ULL; // for k even
  auto sameColourMask = [&](int word, bool red) {
    const std::uint64_t even = (word % 2 == 0) ? evenWordMask : ~evenWordMask;
    return red ? even : ~even;
  };
  // Per brick, colour and word: the same-coloured band nodes in the words
  // before it, so that a neighbour's rank is one look-up and one count.
  std::vector<std::uint16_t> before(static_cast<std::size_t>(numberOfBricks * 2 * Words), 0);
  ParallelFor(0, numberOfBricks, 256, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      for (int colour = 0; colour < 2; ++colour)
      {
        int count = 0;
        for (int w = 0; w < Words; ++w)
        {
          before[(a * 2 + colour) * Words + w] = static_cast<std::uint16_t>(count);
          count += Popcount(occupied[a * Words + w] & sameColourMask(w, colour == 0));
        }
      }
    }
  });
  band.Neighbor.resize(static_cast<std::size_t>(6 * size));
  const double offset = parameters.OffsetDistance;
  // Band node s of the brick whose first node is `first`.
  auto connect = [&](const std::int64_t first[3], std::int64_t s) {
    std::int64_t ijk[3];
    band.NodeIjk(first, s, ijk);
    // phi0 > 0 exactly when d < l (eq. 2).
    const std::uint32_t dirichlet = band.Distance[s] < offset ? band.InsideSlot() : band.OutsideSlot();
    const bool neighbourIsRed = !IsRed(ijk[0], ijk[1], ijk[2]);
    for (int direction = 0; direction < 6; ++direction)
    {
      const int axis = direction / 2;
      std::int64_t n[3] = { ijk[0], ijk[1], ijk[2] };
      n[axis] += (direction % 2) ? 1 : -1;
      std::uint32_t found = dirichlet;
      if (n[axis] >= 0 && n[axis] < grid.Dims[axis])
      {
        const std::int32_t b = slotOfBrick[(n[0] >> BrickShift) +
          brickDims[0] * ((n[1] >> BrickShift) + brickDims[1] * (n[2] >> BrickShift))];
        const int local = localIndex(n);
        const std::uint64_t* mask = b >= 0 ? &occupied[static_cast<std::size_t>(b) * Words] : nullptr;
        if (mask && ((mask[local / 64] >> (local % 64)) & 1))
        {
          const int w = local / 64;
          const std::uint64_t below = (std::uint64_t(1) << (local % 64)) - 1;
          const std::int64_t rank = before[(static_cast<std::size_t>(b) * 2 + (neighbourIsRed ? 0 : 1)) * Words + w] +
            Popcount(mask[w] & below & sameColourMask(w, neighbourIsRed));
          found = static_cast<std::uint32_t>((neighbourIsRed ? redStart[b] : blackStart[b]) + rank);
        }
      }
      band.Neighbor[6 * s + direction] = found;
    }
  };
  ParallelFor(0, numberOfBricks, 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      std::int64_t first[3];
      band.BrickFirstNode(a, first);
      for (std::int64_t s = redStart[a]; s < redStart[a + 1]; ++s)
      {
        connect(first, s);
      }
      for (std::int64_t s = blackStart[a]; s < blackStart[a + 1]; ++s)
      {
        connect(first, s);
      }
    }
  });
  band.RedStart = std::move(redStart);
  band.BlackStart = std::move(blackStart);
  band.OwnedLayers = part->Owned;
  if (monitor)
  {
    monitor->Progress(1.0);
  }
  return band;
}

} // namespace nv
