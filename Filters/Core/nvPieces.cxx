// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPieces.h"

#include <cmath>
#include <deque>
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

RemovedPieces RemoveSmallPieces(const Grid& grid, float* phi, double offset)
{
  const std::int64_t nx = grid.Dims[0], ny = grid.Dims[1], nz = grid.Dims[2];
  const std::int64_t nodes = grid.NumberOfNodes();
  const double cell = grid.Spacing * grid.Spacing * grid.Spacing;
  const std::int64_t pieceNodes = static_cast<std::int64_t>(SmallPieceVolume(offset) / cell);
  const std::int64_t voidNodes = static_cast<std::int64_t>(SmallVoidVolume(offset) / cell);

  // Breadth-first search of each region of one sign. The queue holds only
  // the front of the search; the region's nodes are kept while it is still
  // small enough to be removed.
  std::vector<unsigned char> visited(static_cast<std::size_t>(nodes), 0);
  std::deque<std::int64_t> front;
  std::vector<std::int64_t> region;
  // The small regions found: their nodes, one after the other.
  struct Small
  {
    bool Inside;
    std::size_t First, Size;
  };
  std::vector<Small> smalls;
  std::vector<std::int64_t> smallNodes;
  bool largePiece = false;
  for (std::int64_t seed = 0; seed < nodes; ++seed)
  {
    if (visited[seed])
    {
      continue;
    }
    const bool inside = phi[seed] > 0.0f;
    const std::int64_t limit = inside ? pieceNodes : voidNodes;
    bool boundary = false;
    std::int64_t size = 0;
    region.clear();
    visited[seed] = 1;
    front.push_back(seed);
    while (!front.empty())
    {
      const std::int64_t n = front.front();
      front.pop_front();
      ++size;
      if (size <= limit)
      {
        region.push_back(n);
      }
      const std::int64_t i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
      boundary = boundary || i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1;
      const std::int64_t neighbours[6] = { i > 0 ? n - 1 : -1, i < nx - 1 ? n + 1 : -1, j > 0 ? n - nx : -1,
        j < ny - 1 ? n + nx : -1, k > 0 ? n - nx * ny : -1, k < nz - 1 ? n + nx * ny : -1 };
      for (std::int64_t m : neighbours)
      {
        if (m >= 0 && !visited[m] && (phi[m] > 0.0f) == inside)
        {
          visited[m] = 1;
          front.push_back(m);
        }
      }
    }
    // The exterior (a negative region that reaches the boundary) always stays.
    if (size < limit && (inside || !boundary))
    {
      smalls.push_back({ inside, smallNodes.size(), region.size() });
      smallNodes.insert(smallNodes.end(), region.begin(), region.end());
    }
    largePiece = largePiece || (inside && size >= limit);
  }

  // Flip the small regions, except the largest piece when every piece is
  // small (a tiny cloud's shell is all there is).
  std::size_t spared = smalls.size();
  for (std::size_t r = 0; r < smalls.size() && !largePiece; ++r)
  {
    if (smalls[r].Inside && (spared == smalls.size() || smalls[r].Size > smalls[spared].Size))
    {
      spared = r;
    }
  }
  RemovedPieces removed;
  for (std::size_t r = 0; r < smalls.size(); ++r)
  {
    if (r == spared)
    {
      continue;
    }
    for (std::size_t q = smalls[r].First; q < smalls[r].First + smalls[r].Size; ++q)
    {
      // Outside values are negative, inside values positive (0 counts as outside).
      const std::int64_t n = smallNodes[q];
      phi[n] = smalls[r].Inside ? -phi[n] : (phi[n] == 0.0f ? 1e-6f : -phi[n]);
    }
    ++(smalls[r].Inside ? removed.Pieces : removed.Voids);
  }
  return removed;
}

} // namespace nv
