// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvVolume.h"

#include "nvAllenCahnSolver.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvSchemeTerms.h"

#include <algorithm>
#include <cmath>

namespace nv
{

VolumeWriter::VolumeWriter(
  const Grid& grid, const Parameters& parameters, const VolumeArrays& arrays, std::int64_t kBegin, std::int64_t kEnd)
  : TheGrid(grid)
  , Scheme(parameters)
  , Arrays(arrays)
  , Begin(kBegin)
  , End(kEnd)
{
}

void VolumeWriter::Clear() const
{
  const VolumeArrays& arrays = this->Arrays;
  const float far = static_cast<float>(this->TheGrid.FarDistance());
  const std::int64_t nodes = (this->End - this->Begin) * this->TheGrid.Dims[0] * this->TheGrid.Dims[1];
  ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    // ClearNode (nvVolumeTerms.h) on a range, as fills.
    if (arrays.Phi)
      std::fill(arrays.Phi + begin, arrays.Phi + end, PhiBeyondReach);
    if (arrays.InitialPhi)
      std::fill(arrays.InitialPhi + begin, arrays.InitialPhi + end, PhiBeyondReach);
    if (arrays.Distance)
      std::fill(arrays.Distance + begin, arrays.Distance + end, far);
    if (arrays.Band)
      std::fill(arrays.Band + begin, arrays.Band + end, static_cast<unsigned char>(0));
  });
}

void VolumeWriter::WriteBrick(std::int64_t brick, const double distance[BrickNodes]) const
{
  const Grid& grid = this->TheGrid;
  const VolumeArrays& arrays = this->Arrays;
  const std::int64_t bricksX = (grid.Dims[0] + BrickSize - 1) >> BrickShift;
  const std::int64_t bricksY = (grid.Dims[1] + BrickSize - 1) >> BrickShift;
  const std::int64_t corner[3] = { (brick % bricksX) << BrickShift, ((brick / bricksX) % bricksY) << BrickShift,
    (brick / (bricksX * bricksY)) << BrickShift };
  const std::int64_t base = this->Begin * grid.Dims[0] * grid.Dims[1]; // grid index of the slab's first node
  const double offset = this->Scheme.OffsetDistance;
  const double xi = this->Scheme.Xi();
  for (std::int64_t k = std::max<std::int64_t>(0, this->Begin - corner[2]); k < BrickSize && corner[2] + k < this->End; ++k)
  {
    for (int j = 0; j < BrickSize && corner[1] + j < grid.Dims[1]; ++j)
    {
      for (int i = 0; i < BrickSize && corner[0] + i < grid.Dims[0]; ++i)
      {
        const double d = distance[i + BrickSize * (j + BrickSize * k)];
        if (!WithinReach(d))
        {
          continue; // beyond reach: as cleared
        }
        const std::int64_t node = grid.Index(corner[0] + i, corner[1] + j, corner[2] + k) - base;
        WriteReachedNode(arrays, node, d, InitialPhi(d, offset, xi));
      }
    }
  }
}

void VolumeWriter::WriteBand(const NarrowBand& band, const BandValues& phi) const
{
  const VolumeArrays& arrays = this->Arrays;
  const std::int64_t layer = this->TheGrid.Dims[0] * this->TheGrid.Dims[1];
  const std::int64_t first = this->Begin * layer, last = this->End * layer;
  auto write = [&](const std::int64_t corner[3], std::int64_t s) {
    std::int64_t ijk[3];
    band.NodeIjk(corner, s, ijk);
    const std::int64_t node = this->TheGrid.Index(ijk[0], ijk[1], ijk[2]);
    if (node < first || node >= last)
      return;
    WriteBandNode(arrays, node - first, phi[s]);
  };
  ParallelFor(0, static_cast<std::int64_t>(band.Bricks.size()), 32, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      std::int64_t corner[3]; // the brick's first node
      band.BrickFirstNode(a, corner);
      for (std::int64_t s = band.RedStart[a]; s < band.RedStart[a + 1]; ++s)
        write(corner, s);
      for (std::int64_t s = band.BlackStart[a]; s < band.BlackStart[a + 1]; ++s)
        write(corner, s);
    }
  });
}

} // namespace nv
