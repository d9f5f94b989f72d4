// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvVolume.h"

#include "nvAllenCahnSolver.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>

namespace nv
{
namespace
{
/// The bricks of `bricks` whose layer of nodes overlaps the node layers
/// [kBegin, kEnd): an index range into `bricks`.
void BricksInNodeLayers(const std::vector<std::int64_t>& bricks, std::int64_t bricksPerLayer,
  std::int64_t kBegin, std::int64_t kEnd, std::int64_t& first, std::int64_t& last)
{
  BricksInLayers(bricks, bricksPerLayer, kBegin >> BrickShift, ((kEnd - 1) >> BrickShift) + 1, first, last);
}
} // namespace

void FillVolume(const TruncatedDistance& distance, const NarrowBand& band, const std::vector<double>& phi,
  const Parameters& parameters, const std::vector<std::int64_t>& reachedBricks, const VolumeArrays& arrays,
  std::int64_t kBegin, std::int64_t kEnd, Monitor* monitor)
{
  const Grid& grid = distance.GetGrid();
  if (kEnd < 0)
  {
    kEnd = grid.Dims[2];
  }
  const std::int64_t layer = grid.Dims[0] * grid.Dims[1];
  const std::int64_t base = kBegin * layer; // grid index of the slab's first node
  const std::int64_t nodes = (kEnd - kBegin) * layer;
  const float far = static_cast<float>(grid.FarDistance());
  const std::int64_t bricksPerLayer = distance.GetBrickDims()[0] * distance.GetBrickDims()[1];

  // Nodes beyond reach: d truncated (eq. 6), phi0 = tanh(-inf) = -1.
  ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    if (arrays.Phi)
      std::fill(arrays.Phi + begin, arrays.Phi + end, -1.0f);
    if (arrays.InitialPhi)
      std::fill(arrays.InitialPhi + begin, arrays.InitialPhi + end, -1.0f);
    if (arrays.Distance)
      std::fill(arrays.Distance + begin, arrays.Distance + end, far);
    if (arrays.Band)
      std::fill(arrays.Band + begin, arrays.Band + end, static_cast<unsigned char>(0));
  });

  // Nodes within reach: recompute their distance brick by brick.
  std::int64_t first, last;
  BricksInNodeLayers(reachedBricks, bricksPerLayer, kBegin, kEnd, first, last);
  const double offset = parameters.OffsetDistance;
  const double xi = parameters.Xi();
  if (!MonitoredFor(first, last, 16, monitor, [&](std::int64_t begin, std::int64_t end) {
    double d[BrickNodes];
    for (std::int64_t b = begin; b < end; ++b)
    {
      distance.ComputeBrick(reachedBricks[b], d);
      std::int64_t corner[3];
      distance.BrickFirstNode(reachedBricks[b], corner);
      for (int k = 0; k < BrickSize && corner[2] + k < kEnd; ++k)
      {
        if (corner[2] + k < kBegin)
          continue;
        for (int j = 0; j < BrickSize && corner[1] + j < grid.Dims[1]; ++j)
        {
          for (int i = 0; i < BrickSize && corner[0] + i < grid.Dims[0]; ++i)
          {
            const double dist = d[i + BrickSize * (j + BrickSize * k)];
            if (!std::isfinite(dist))
            {
              continue;
            }
            const std::int64_t node = grid.Index(corner[0] + i, corner[1] + j, corner[2] + k) - base;
            const float phi0 = static_cast<float>(AllenCahnSolver::InitialPhi(dist, offset, xi));
            if (arrays.Phi)
              arrays.Phi[node] = phi0;
            if (arrays.InitialPhi)
              arrays.InitialPhi[node] = phi0;
            if (arrays.Distance)
              arrays.Distance[node] = static_cast<float>(dist);
          }
        }
      }
    }
  }))
  {
    return; // stopped: the arrays are incomplete
  }

  // Band nodes: the evolved phi.
  BricksInNodeLayers(band.Bricks, bricksPerLayer, kBegin, kEnd, first, last);
  ParallelFor(first, last, 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t b = begin; b < end; ++b)
    {
      for (const auto* start : { &band.RedStart, &band.BlackStart })
      {
        for (std::int64_t s = (*start)[b]; s < (*start)[b + 1]; ++s)
        {
          const std::int64_t node = band.Node[s] - base;
          if (node < 0 || node >= nodes)
            continue;
          if (arrays.Phi)
            arrays.Phi[node] = static_cast<float>(phi[s]);
          if (arrays.Band)
            arrays.Band[node] = 1;
        }
      }
    }
  });
}

} // namespace nv
