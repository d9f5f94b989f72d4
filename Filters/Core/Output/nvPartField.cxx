// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The part's field f (PartField) and the material put back around the
// scan points the part lost (Restoration): nvPartSteps.h.
#include "nvPartSteps.h"

#include "nvParallel.h"

namespace nv
{
namespace part
{
Restoration::Restoration(const Grid& grid, const double* scan, std::int64_t scanPoints,
  const std::vector<std::int64_t>& lost, double radius, double reach)
  : Radius(radius)
  , BrickDims(BrickDimensions(grid))
{
  // The points to join: the lost ones, and the held ones within reach of
  // one (a lost limb's ends, where the part's pieces may stop short of
  // one another although each holds the points near it).
  const NearestPoints all(scan, scanPoints);
  std::vector<double> lostXyz;
  for (std::int64_t p : lost)
  {
    lostXyz.insert(lostXyz.end(), scan + 3 * p, scan + 3 * p + 3);
  }
  this->LostPoints.reset(new NearestPoints(lostXyz.data(), static_cast<std::int64_t>(lost.size())));
  const NearestPoints& lostPoints = *this->LostPoints;
  std::vector<char> joined(static_cast<std::size_t>(scanPoints), 0);
  ParallelFor(0, scanPoints, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      joined[p] = lostPoints.Distance(scan + 3 * p, reach) < reach;
    }
  });
  std::vector<std::array<double, 3>> near;
  const double side = BrickSize * grid.Spacing, margin = radius + 3.0 * grid.Spacing;
  for (std::int64_t p = 0; p < scanPoints; ++p)
  {
    if (!joined[p])
    {
      continue;
    }
    const double* x = scan + 3 * p;
    all.Nearest(x, NeighboursJoined, reach, near);
    for (const std::array<double, 3>& y : near)
    {
      Drill rod;
      std::copy(x, x + 3, rod.A);
      std::copy(y.begin(), y.end(), rod.B);
      rod.Radius = radius;
      const std::int32_t index = static_cast<std::int32_t>(this->Rods.size());
      this->Rods.push_back(rod);
      std::int64_t low[3], high[3];
      for (int a = 0; a < 3; ++a)
      {
        const double lo = std::min(rod.A[a], rod.B[a]) - margin, hi = std::max(rod.A[a], rod.B[a]) + margin;
        low[a] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((lo - grid.Origin[a]) / side)));
        high[a] = std::min(this->BrickDims[a] - 1,
          static_cast<std::int64_t>(std::floor((hi - grid.Origin[a]) / side)));
      }
      for (std::int64_t k = low[2]; k <= high[2]; ++k)
      {
        for (std::int64_t j = low[1]; j <= high[1]; ++j)
        {
          for (std::int64_t i = low[0]; i <= high[0]; ++i)
          {
            this->ByBrick.emplace_back(i + this->BrickDims[0] * (j + this->BrickDims[1] * k), index);
          }
        }
      }
    }
  }
  std::sort(this->ByBrick.begin(), this->ByBrick.end());
  this->ByBrick.erase(std::unique(this->ByBrick.begin(), this->ByBrick.end()), this->ByBrick.end());
}

PartField::PartField(const Grid& grid, const float* outer, const std::vector<float>& distance, double offset,
  const InnerField& innerField, const std::vector<Drill>& drills, const Restoration* restored)
  : BrickDims(BrickDimensions(grid))
{
  const float clamp = static_cast<float>(3.0 * grid.Spacing);
  const std::int64_t bricks = this->BrickDims[0] * this->BrickDims[1] * this->BrickDims[2];
  this->Uniform.assign(static_cast<std::size_t>(bricks), -clamp);
  std::vector<std::vector<float>> values(static_cast<std::size_t>(bricks));
  ParallelFor(0, bricks, 16, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> mine(BrickNodes);
    for (std::int64_t b = begin; b < end; ++b)
    {
      const std::int64_t first[3] = { (b % this->BrickDims[0]) * BrickSize,
        ((b / this->BrickDims[0]) % this->BrickDims[1]) * BrickSize,
        (b / (this->BrickDims[0] * this->BrickDims[1])) * BrickSize };
      bool above = true, below = true;
      const bool restoring = restored && restored->Reaches(b);
      for (int k = 0; k < BrickSize; ++k)
      {
        for (int j = 0; j < BrickSize; ++j)
        {
          for (int i = 0; i < BrickSize; ++i)
          {
            const std::int64_t x = first[0] + i, y = first[1] + j, z = first[2] + k;
            float f = -clamp;
            if (x < grid.Dims[0] && y < grid.Dims[1] && z < grid.Dims[2])
            {
              const std::int64_t n = grid.Index(x, y, z);
              const double d = distance[n];
              const double inside = std::min(d - offset, innerField(n));
              double value = outer[n] > 0.0f ? inside : -(offset + d);
              const double at[3] = { grid.Origin[0] + static_cast<double>(x) * grid.Spacing,
                grid.Origin[1] + static_cast<double>(y) * grid.Spacing,
                grid.Origin[2] + static_cast<double>(z) * grid.Spacing };
              if (restoring && value < clamp)
              {
                value = std::max(value, restored->Value(b, at));
              }
              if (!drills.empty() && value > -clamp)
              {
                for (const Drill& drill : drills)
                {
                  value = std::min(value, drill.Signed(at)); // the hole less the material
                }
              }
              f = static_cast<float>(std::max<double>(-clamp, std::min<double>(clamp, value)));
            }
            mine[i + BrickSize * (j + BrickSize * k)] = f;
            above = above && f >= clamp;
            below = below && f <= -clamp;
          }
        }
      }
      if (above || below)
      {
        this->Uniform[b] = above ? clamp : -clamp;
      }
      else
      {
        values[b] = mine;
      }
    }
  });
  for (std::int64_t b = 0; b < bricks; ++b)
  {
    if (!values[b].empty())
    {
      this->Varying.push_back(b);
      this->Stored.insert(this->Stored.end(), values[b].begin(), values[b].end());
    }
  }
}
} // namespace part
} // namespace nv
