// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target for the truncated distance and the narrow band (eq. 6, 7
// and the paper's band construction: collect, store, connect). The input bytes choose the offset, xi, the
// spacing, the domain mode and up to 200 points; the target checks the band
// against brute force and its neighbour indices for consistency, and aborts
// on any violation.
#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
void Require(bool condition)
{
  if (!condition)
  {
    std::abort();
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 4 + 6)
  {
    return 0;
  }
  nv::Parameters p;
  p.Spacing = 0.05 + 0.01 * (data[0] % 20);
  p.OffsetDistance = p.Spacing * (0.25 + 0.25 * (data[1] % 24));
  p.XiCells = 1.0 + 0.5 * (data[2] % 7);
  p.Domain = (data[3] & 1) ? nv::Domain::WholeDomain : nv::Domain::NarrowBand;
  std::vector<double> points;
  for (std::size_t at = 4; at + 6 <= size && points.size() < 600; at += 6)
  {
    for (int a = 0; a < 3; ++a)
    {
      std::int16_t v;
      std::memcpy(&v, data + at + 2 * a, 2);
      points.push_back(v / 16384.0); // within [-2, 2)
    }
  }
  const std::int64_t count = static_cast<std::int64_t>(points.size() / 3);
  double bounds[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (std::int64_t i = 0; i < count; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], points[3 * i + a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], points[3 * i + a]);
    }
  }
  const nv::Grid grid = nv::MakeGrid(bounds, p.Spacing, nv::GridPadding(p.Reach(), p.Spacing));
  if (grid.NumberOfNodes() > 200000)
  {
    return 0;
  }
  const nv::TruncatedDistance distance(grid, points.data(), count, p.Reach());
  const nv::NarrowBand band = nv::BuildNarrowBand(distance, p);

  const double lower = p.OffsetDistance - p.HalfBandWidth();
  const double upper = p.Reach();
  std::int64_t expected = 0;
  std::vector<std::int64_t> slotOfNode(static_cast<std::size_t>(grid.NumberOfNodes()), -1);
  for (std::int64_t s = 0; s < band.Size(); ++s)
  {
    Require(band.GridIndex(s) >= 0 && band.GridIndex(s) < grid.NumberOfNodes());
    Require(slotOfNode[band.GridIndex(s)] < 0); // no node twice
    slotOfNode[band.GridIndex(s)] = s;
  }
  for (std::int64_t k = 0; k < grid.Dims[2]; ++k)
    for (std::int64_t j = 0; j < grid.Dims[1]; ++j)
      for (std::int64_t i = 0; i < grid.Dims[0]; ++i)
      {
        double best = std::numeric_limits<double>::infinity();
        for (std::int64_t q = 0; q < count; ++q)
        {
          const double dx = grid.Origin[0] + i * grid.Spacing - points[3 * q];
          const double dy = grid.Origin[1] + j * grid.Spacing - points[3 * q + 1];
          const double dz = grid.Origin[2] + k * grid.Spacing - points[3 * q + 2];
          best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
        }
        const std::int64_t s = slotOfNode[grid.Index(i, j, k)];
        const bool clearlyIn = lower + 1e-9 < best && best < upper - 1e-9;
        const bool clearlyOut = best < lower - 1e-9 || best > upper + 1e-9;
        if (p.Domain == nv::Domain::WholeDomain)
        {
          Require(s >= 0);
        }
        else if (clearlyIn)
        {
          Require(s >= 0);
        }
        else if (clearlyOut)
        {
          Require(s < 0);
        }
        if (s >= 0 && best < upper - 1e-9)
        {
          Require(std::fabs(band.Distance[s] - best) < 1e-9);
        }
        expected += s >= 0;
      }
  Require(expected == band.Size());
  // Neighbour indices: in range, and mutual between band nodes.
  for (std::int64_t s = 0; s < band.Size(); ++s)
  {
    for (int direction = 0; direction < 6; ++direction)
    {
      const std::uint32_t n = band.Neighbor[6 * s + direction];
      Require(n <= band.OutsideSlot());
      if (n < band.InsideSlot())
      {
        Require(band.Neighbor[6 * n + (direction ^ 1)] == static_cast<std::uint32_t>(s));
      }
    }
  }
  return 0;
}
