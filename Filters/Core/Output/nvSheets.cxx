// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvSheets.h"

#include "nvParallel.h"

#include <cstdint>
#include <vector>

namespace nv
{

std::int64_t KeepSheets(const Grid& grid, float* phi, Sheets which, Monitor* monitor)
{
  if (which == Sheets::Both || which == Sheets::Scan)
  {
    return -1;
  }
  const std::int64_t nx = grid.Dims[0], ny = grid.Dims[1], nz = grid.Dims[2];
  const std::int64_t nodes = grid.NumberOfNodes();
  // Breadth-first search of the negative nodes reachable from the grid's boundary (6-connected).
  std::vector<unsigned char> exterior(static_cast<std::size_t>(nodes), 0);
  std::vector<std::int64_t> queue;
  auto visit = [&](std::int64_t n) {
    if (!exterior[n] && phi[n] < 0.0f)
    {
      exterior[n] = 1;
      queue.push_back(n);
    }
  };
  for (std::int64_t k = 0; k < nz; ++k)
    for (std::int64_t j = 0; j < ny; ++j)
      for (std::int64_t i = 0; i < nx; ++i)
      {
        if (i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1)
        {
          visit(grid.Index(i, j, k));
        }
      }
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    if (head % (std::size_t(1) << 22) == 0 && StopAsked(monitor)) // tens of millions of nodes take seconds
    {
      return -1;
    }
    const std::int64_t n = queue[head];
    const std::int64_t i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
    if (i > 0)
      visit(n - 1);
    if (i < nx - 1)
      visit(n + 1);
    if (j > 0)
      visit(n - nx);
    if (j < ny - 1)
      visit(n + nx);
    if (k > 0)
      visit(n - nx * ny);
    if (k < nz - 1)
      visit(n + nx * ny);
  }
  std::int64_t cavityNodes = 0;
  for (std::int64_t n = 0; n < nodes; ++n)
  {
    const bool cavity = phi[n] < 0.0f && !exterior[n];
    cavityNodes += cavity ? 1 : 0;
    const bool fill = which == Sheets::Outer ? cavity : exterior[n] != 0;
    if (fill)
    {
      phi[n] = 1.0f;
    }
  }
  return cavityNodes;
}

} // namespace nv
