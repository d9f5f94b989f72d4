// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvGrid.h"

#include <algorithm>
#include <cmath>

namespace nv
{

double Grid::FarDistance() const
{
  const double nx = static_cast<double>(this->Dims[0]);
  const double ny = static_cast<double>(this->Dims[1]);
  const double nz = static_cast<double>(this->Dims[2]);
  return this->Spacing * std::sqrt(nx * nx + ny * ny + nz * nz);
}

double GridPadding(double reach, double spacing)
{
  return reach + 2.0 * spacing;
}

Grid MakeGrid(const double bounds[6], double spacing, double padding)
{
  Grid grid;
  grid.Spacing = spacing;
  for (int a = 0; a < 3; ++a)
  {
    const double lo = bounds[2 * a] - padding;
    const double length = (bounds[2 * a + 1] - bounds[2 * a]) + 2.0 * padding;
    grid.Origin[a] = lo;
    // Cells along the axis, rounded up so the padded box is covered; nodes = cells + 1.
    grid.Dims[a] = static_cast<std::int64_t>(std::ceil(length / spacing - 1e-9)) + 1;
  }
  return grid;
}

double SpacingForMaximumDimension(
  const double bounds[6], double offset, double xiCells, int maximumDimension)
{
  double longest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    longest = std::max(longest, bounds[2 * a + 1] - bounds[2 * a]);
  }
  // longest + 2 (l + m h + 2 h) = D h, with eta/2 = m h (section 3).
  const double cellsLeft = maximumDimension - 2.0 * (xiCells + 2.0);
  if (cellsLeft < 1.0)
  {
    return 0.0;
  }
  return (longest + 2.0 * offset) / cellsLeft;
}

} // namespace nv
