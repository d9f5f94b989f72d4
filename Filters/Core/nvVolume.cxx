#include "nvVolume.h"

#include "nvAllenCahnSolver.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>

namespace nv
{

void FillVolume(const TruncatedDistance& distance, const NarrowBand& band,
  const std::vector<double>& phi, const Parameters& parameters, const VolumeArrays& arrays)
{
  const Grid& grid = distance.GetGrid();
  const std::int64_t nodes = grid.NumberOfNodes();
  const float far = static_cast<float>(grid.FarDistance());

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
  const std::vector<std::int64_t> bricks = distance.ReachedBricks();
  const double offset = parameters.OffsetDistance;
  const double xi = parameters.Xi();
  ParallelFor(0, static_cast<std::int64_t>(bricks.size()), 16, [&](std::int64_t begin, std::int64_t end) {
    double d[BrickNodes];
    for (std::int64_t b = begin; b < end; ++b)
    {
      distance.ComputeBrick(bricks[b], d);
      std::int64_t first[3];
      distance.BrickFirstNode(bricks[b], first);
      for (int k = 0; k < BrickSize && first[2] + k < grid.Dims[2]; ++k)
      {
        for (int j = 0; j < BrickSize && first[1] + j < grid.Dims[1]; ++j)
        {
          for (int i = 0; i < BrickSize && first[0] + i < grid.Dims[0]; ++i)
          {
            const double dist = d[i + BrickSize * (j + BrickSize * k)];
            if (!std::isfinite(dist))
            {
              continue;
            }
            const std::int64_t node = grid.Index(first[0] + i, first[1] + j, first[2] + k);
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
  });

  // Band nodes: the evolved phi.
  ParallelFor(0, band.Size(), 1 << 14, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t s = begin; s < end; ++s)
    {
      const std::int64_t node = band.Node[s];
      if (arrays.Phi)
        arrays.Phi[node] = static_cast<float>(phi[s]);
      if (arrays.Band)
        arrays.Band[node] = 1;
    }
  });
}

} // namespace nv
