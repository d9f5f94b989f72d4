// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPieces.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <vector>

namespace nv
{

double SmallPieceVolume(double offset)
{
  const double radius = 2.0 * offset;
  return 4.0 / 3.0 * M_PI * radius * radius * radius;
}

double SmallVoidVolume(double offset)
{
  return 4.0 / 3.0 * M_PI * offset * offset * offset;
}

bool FlipRegion(const Grid& grid, float* phi, std::int64_t kBegin, std::int64_t layers, const double point[3],
  bool inside, double maximumVolume)
{
  const std::int64_t nx = grid.Dims[0], ny = grid.Dims[1];
  auto sideOf = [&](std::int64_t n) { return phi[n] > 0.0f; };
  // The seed: the corner of the point's cell on the region's side, nearest to it.
  std::int64_t cell[3];
  for (int a = 0; a < 3; ++a)
  {
    const std::int64_t extent = a == 2 ? layers : grid.Dims[a];
    const double x = (point[a] - grid.Origin[a]) / grid.Spacing - (a == 2 ? kBegin : 0);
    cell[a] = std::min<std::int64_t>(std::max<std::int64_t>(static_cast<std::int64_t>(std::floor(x)), 0), extent - 2);
  }
  std::int64_t seed = -1;
  double nearest = 1e300;
  for (int corner = 0; corner < 8; ++corner)
  {
    const std::int64_t ijk[3] = { cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + (corner >> 2) };
    const std::int64_t n = ijk[0] + nx * (ijk[1] + ny * ijk[2]);
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double x = grid.Origin[a] + (ijk[a] + (a == 2 ? kBegin : 0)) * grid.Spacing - point[a];
      d2 += x * x;
    }
    if (sideOf(n) == inside && d2 < nearest)
    {
      nearest = d2;
      seed = n;
    }
  }
  if (seed < 0)
  {
    return false;
  }
  // Breadth-first search of the region, given up beyond maximumVolume.
  const std::int64_t limit =
    static_cast<std::int64_t>(maximumVolume / (grid.Spacing * grid.Spacing * grid.Spacing)) + 1;
  std::vector<std::int64_t> region{ seed };
  std::unordered_set<std::int64_t> visited{ seed };
  for (std::size_t head = 0; head < region.size(); ++head)
  {
    if (static_cast<std::int64_t>(region.size()) > limit)
    {
      return false;
    }
    const std::int64_t n = region[head];
    const std::int64_t i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
    const std::int64_t neighbours[6] = { i > 0 ? n - 1 : -1, i < nx - 1 ? n + 1 : -1, j > 0 ? n - nx : -1,
      j < ny - 1 ? n + nx : -1, k > 0 ? n - nx * ny : -1, k < layers - 1 ? n + nx * ny : -1 };
    for (std::int64_t m : neighbours)
    {
      if (m >= 0 && sideOf(m) == inside && visited.insert(m).second)
      {
        region.push_back(m);
      }
    }
  }
  for (std::int64_t n : region)
  {
    // Outside values are negative or 0, inside values positive.
    phi[n] = inside ? -phi[n] : (phi[n] == 0.0f ? 1e-6f : -phi[n]);
  }
  return true;
}

} // namespace nv
