// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvHoleProbe.h"

#include "nvSurfaceField.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace nv
{
namespace
{
/// The field's values at single nodes, brick by brick as it reads them.
class NodeValues
{
public:
  NodeValues(const BrickField& field, const Grid& grid)
    : Field(field)
  {
    for (int a = 0; a < 3; ++a)
    {
      this->BrickDims[a] = (grid.Dims[a] + BrickSize - 1) >> BrickShift;
    }
  }

  float operator()(const std::int64_t ijk[3])
  {
    const std::int64_t brick = (ijk[0] >> BrickShift) +
      this->BrickDims[0] * ((ijk[1] >> BrickShift) + this->BrickDims[1] * (ijk[2] >> BrickShift));
    auto found = this->Bricks.find(brick);
    if (found == this->Bricks.end())
    {
      found = this->Bricks.emplace(brick, std::vector<float>(BrickNodes)).first;
      this->Field.Values(brick, found->second.data());
    }
    const std::int64_t mask = BrickSize - 1;
    return found->second[(ijk[0] & mask) + BrickSize * ((ijk[1] & mask) + BrickSize * (ijk[2] & mask))];
  }

private:
  const BrickField& Field;
  std::int64_t BrickDims[3];
  std::unordered_map<std::int64_t, std::vector<float>> Bricks;
};
} // namespace

bool TunnelThrough(const BrickField& field, const Grid& grid, const Hole& disc, double wall, double reach)
{
  const std::array<double, 3>& center = disc.Center;
  NodeValues value(field, grid);
  // The box of nodes within `reach` of the centre, clamped to the grid.
  std::int64_t lo[3], hi[3], corner[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double u = (center[a] - grid.Origin[a]) / grid.Spacing;
    corner[a] = std::min(std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(u))), grid.Dims[a] - 2);
    t[a] = std::min(1.0, std::max(0.0, u - static_cast<double>(corner[a])));
    const std::int64_t cells = static_cast<std::int64_t>(std::ceil(reach / grid.Spacing));
    lo[a] = std::max<std::int64_t>(0, corner[a] - cells);
    hi[a] = std::min(grid.Dims[a] - 1, corner[a] + 1 + cells);
  }
  // The field at the centre (trilinear), and its cell's outside corners, where the region starts.
  std::vector<std::array<std::int64_t, 3>> front;
  double atCenter = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    std::array<std::int64_t, 3> node;
    double weight = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const int up = (c >> a) & 1;
      node[a] = corner[a] + up;
      weight *= up ? t[a] : 1.0 - t[a];
    }
    const float v = value(node.data());
    atCenter += weight * v;
    if (v < 0.0f)
    {
      front.push_back(node);
    }
  }
  if (!(atCenter < 0.0))
  {
    return false; // the wall covers the hole's centre
  }
  // Flood the outside region (6-connected) within the box, until it has
  // reached past the wall on both sides of the tangent plane.
  const std::int64_t size[3] = { hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1 };
  std::vector<char> seen(static_cast<std::size_t>(size[0] * size[1] * size[2]), 0);
  auto slot = [&](const std::array<std::int64_t, 3>& n) {
    return (n[0] - lo[0]) + size[0] * ((n[1] - lo[1]) + size[1] * (n[2] - lo[2]));
  };
  for (const auto& node : front)
  {
    seen[slot(node)] = 1;
  }
  bool above = false, below = false;
  while (!front.empty())
  {
    const std::array<std::int64_t, 3> node = front.back();
    front.pop_back();
    double height = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      height += (grid.Origin[a] + static_cast<double>(node[a]) * grid.Spacing - center[a]) * disc.Normal[a];
    }
    above = above || height > wall;
    below = below || height < -wall;
    if (above && below)
    {
      return true;
    }
    for (int step = 0; step < 6; ++step)
    {
      std::array<std::int64_t, 3> next = node;
      next[step / 2] += (step % 2) ? 1 : -1;
      if (next[step / 2] < lo[step / 2] || next[step / 2] > hi[step / 2])
      {
        continue;
      }
      char& mark = seen[slot(next)];
      if (!mark && value(next.data()) < 0.0f)
      {
        mark = 1;
        front.push_back(next);
      }
    }
  }
  return false; // a pocket sealed in the wall, or open to one side only
}

} // namespace nv
